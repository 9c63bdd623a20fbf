#include "rigidBodyDrivers/FixedDriver.H"

namespace gpic {

GPIC_REGISTER_DIMS(RigidBodyDriver, FixedDriver, "fixed")

} // namespace gpic
