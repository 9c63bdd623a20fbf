#include "stages/RunStage.H"

namespace gpic {

GPIC_REGISTER_DIMS(Stage, RunStage, "run")

} // namespace gpic
