// A rigid body shaken along x1, as a user's library would add a driver: x1(t) = x1(0) +
// A sin(omega t), moved exactly (not by the velocity times the step).
//     constant/rigidBodies:   plate { type shaker; amplitude 0.005; omega 31.4159; }
#include "bodies/RigidBodyDriver.H"
#include "dictionary/Dictionary.H"

#include <cmath>

namespace scenePlugin {

class ShakerDriver : public gpic::RigidBodyDriver<2> {
public:
    explicit ShakerDriver(const gpic::Dictionary& dict)
        : A_(dict.get<double>("amplitude")),
          omega_(dict.getChecked<double>("omega", [](const double& w) { return w > 0; }, "omega > 0"))
    {}
    gpic::Vector2 velocity(double t, const gpic::Vector2&) const override
    {
        return {A_ * omega_ * std::cos(omega_ * t), 0.0};
    }
    gpic::Vector2 move(double t, double dt, const gpic::Vector2& x) const override
    {
        return x + gpic::Vector2(A_ * (std::sin(omega_ * (t + dt)) - std::sin(omega_ * t)), 0.0);
    }

private:
    double A_, omega_;
};

GPIC_REGISTER(gpic::RigidBodyDriver<2>, ShakerDriver, "shaker")

} // namespace scenePlugin
