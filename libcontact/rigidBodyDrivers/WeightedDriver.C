#include "rigidBodyDrivers/WeightedDriver.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER(RigidBodyDriver<2>, WeightedDriver, "weighted")

WeightedDriver::WeightedDriver(const Dictionary& dict) : name_(dict.name())
{
    if (dict.found("free")) {
        const auto flags = dict.getChecked<std::vector<int>>(
            "free",
            [](const std::vector<int>& f) { return f.size() == 2 && (f[0] == 0 || f[0] == 1) && (f[1] == 0 || f[1] == 1); },
            "(fx fy) with 1 (free) or 0 (prescribed) per direction, e.g. (0 1)");
        free_ = {flags[0] == 1, flags[1] == 1};
        if (!free_[0] && !free_[1])
            dict.fail("free", "weighted body " + name_ +
                                  " has no free direction; use type prescribedVelocity for a body moved at a given velocity");
    }
    if (dict.found("velocity")) velocity_ = TimeFunction::readVector(dict, "velocity");
    if (dict.found("addedForce")) addedForce_ = TimeFunction::readVector(dict, "addedForce");
    damping_ = dict.getOrDefault<double>("damping", 0.0);
    if (damping_ < 0.0 || damping_ >= 1.0) dict.fail("damping", "weighted body " + name_ + ": damping must lie in [0, 1)");
}

void WeightedDriver::attach(const RigidBodyInfo<2>& info)
{
    if (!(info.mass > 0.0)) throw RunError("weighted rigid body " + name_ + " has no particles (no mass)");
    mass_ = info.mass;
    gravity_ = info.gravity;
    velocity0_ = info.velocity;  // restart-safe: the body's particles carry its velocity
    for (int d = 0; d < PlaneSpace::dim; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
}

Vector2 WeightedDriver::freeAcceleration(double t, const Vector2& materialForce, const Vector2& v) const
{
    Vector2 a = Vector2::Zero();
    const Vector2 added = valueOf(addedForce_, t);
    for (int d = 0; d < PlaneSpace::dim; ++d) {
        if (!free_[d]) continue;
        double F = mass_ * gravity_[d] + added[d] + materialForce[d];
        if (damping_ > 0.0 && v[d] != 0.0) F -= damping_ * std::abs(F) * (v[d] > 0.0 ? 1.0 : -1.0);  // eq. 3.3.5
        a[d] = F / mass_;
    }
    return a;
}

void WeightedDriver::start(double t) const
{
    started_ = true;
    time_ = t;
    // No reaction is known before the first step (nor after a restart): weight and added force.
    acceleration_ = freeAcceleration(t, Vector2::Zero(), velocity0_);
}

Vector2 WeightedDriver::velocity(double t, const Vector2&) const
{
    if (!started_) start(t);
    const Vector2 prescribed = valueOf(velocity_, t);
    Vector2 v;
    for (int d = 0; d < PlaneSpace::dim; ++d) v[d] = free_[d] ? velocity0_[d] + (t - time_) * acceleration_[d] : prescribed[d];
    return v;
}

void WeightedDriver::advance(double t, double dt, const RigidBodyLoad<2>& load)
{
    if (!started_) start(t);
    // The step [t, t + dt] moved the body with v(t + dt); that is the new state.
    velocity0_ += (t + dt - time_) * acceleration_;
    time_ = t + dt;
    for (int d = 0; d < PlaneSpace::dim; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
    // The material's reaction of that step drives the next one (one step late, see the header).
    acceleration_ = freeAcceleration(time_, load.force, velocity0_);
}

} // namespace gpic
