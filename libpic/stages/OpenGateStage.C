#include "stages/OpenGateStage.H"

#include "dictionary/Dictionary.H"

namespace gpic {

GPIC_REGISTER(Stage, OpenGateStage, "openGate")

OpenGateStage::OpenGateStage(const Dictionary& dict, const StageSetup& setup) : Stage(dict, setup)
{
    setOpening(dict, "side", dict.get<std::string>("side"), 1);
}

} // namespace gpic
