#include "stages/RunStage.H"

namespace gpic {

GPIC_REGISTER(Stage, RunStage, "run")

} // namespace gpic
