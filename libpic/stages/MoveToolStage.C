#include "stages/MoveToolStage.H"

#include "dictionary/Dictionary.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER_DIMS(Stage, MoveToolStage, "moveTool")

template <int D>
int MoveToolStage<D>::toolOf(const Dictionary& dict, const StageSetup<D>& setup)
{
    const auto& names = setup.bodyNames;
    const std::string tool = dict.get<std::string>("body");
    const auto it = std::find(names.begin(), names.end(), tool);
    if (it == names.end()) {
        std::string valid;
        for (const auto& n : names) valid += (valid.empty() ? "" : ", ") + n;
        dict.fail("body", "'" + tool + "' is not a body of the particles; valid choices: " + valid);
    }
    return static_cast<int>(it - names.begin());
}

template <int D>
MoveToolStage<D>::MoveToolStage(const Dictionary& dict, const StageSetup<D>& setup)
    : Stage<D>(dict, setup, 0.0, toolOf(dict, setup))
{
    const std::string tool = dict.get<std::string>("body");
    const int b = toolOf(dict, setup);
    if (!isActive(b)) dict.fail("body", "the tool '" + tool + "' is not among the stage's bodies (" + bodyList() + ")");
    if (!isRigid(b))
        dict.fail("body", "the tool '" + tool + "' has no driver: give it one in constant/rigidBodies or in the "
                          "stage's drivers { " + tool + " { type prescribedVelocity; velocity (0.01 0); } }");
}

template class MoveToolStage<2>;
#if GPIC_WITH_3D
template class MoveToolStage<3>;
#endif

} // namespace gpic
