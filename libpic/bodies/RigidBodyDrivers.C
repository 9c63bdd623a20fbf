// The built-in drivers: small enough to share one file.
#include "bodies/RigidBodyDriver.H"

#include "dictionary/Dictionary.H"

namespace gpic {

//- Held in place.
class FixedDriver : public RigidBodyDriver {
public:
    explicit FixedDriver(const Dictionary&) {}
    Vector2 velocity(double, const Vector2&) const override { return Vector2::Zero(); }
};

//- Constant translation.
class PrescribedVelocityDriver : public RigidBodyDriver {
public:
    explicit PrescribedVelocityDriver(const Dictionary& d) : velocity_(d.get<Vector2>("velocity")) {}
    Vector2 velocity(double, const Vector2&) const override { return velocity_; }

private:
    Vector2 velocity_;  //- [m/s]
};

GPIC_REGISTER(RigidBodyDriver, FixedDriver, "fixed")
GPIC_REGISTER(RigidBodyDriver, PrescribedVelocityDriver, "prescribedVelocity")

} // namespace gpic
