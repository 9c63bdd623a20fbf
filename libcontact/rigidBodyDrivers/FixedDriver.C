#include "rigidBodyDrivers/FixedDriver.H"

namespace gpic {

GPIC_REGISTER(RigidBodyDriver, FixedDriver, "fixed")

} // namespace gpic
