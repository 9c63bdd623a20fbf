#include "rigidBodyDrivers/FixedDriver.H"

namespace gpic {

GPIC_REGISTER(RigidBodyDriver<2>, FixedDriver, "fixed")

} // namespace gpic
