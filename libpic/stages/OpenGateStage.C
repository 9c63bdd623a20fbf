#include "stages/OpenGateStage.H"

#include "dictionary/Dictionary.H"

namespace gpic {

GPIC_REGISTER_DIMS(Stage, OpenGateStage, "openGate")

template <int D>
OpenGateStage<D>::OpenGateStage(const Dictionary& dict, const StageSetup<D>& setup) : Stage<D>(dict, setup)
{
    setOpening(dict, "side", dict.get<std::string>("side"), 1);
}

template class OpenGateStage<2>;
#if GPIC_WITH_3D
template class OpenGateStage<3>;
#endif

} // namespace gpic
