#include "rigidBodyDrivers/WeightedDriver.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(RigidBodyDriver, WeightedDriver, "weighted")

template <int D> WeightedDriver<D>::WeightedDriver(const Dictionary& dict) : name_(dict.name())
{
    free_[D - 1] = true;
    if (dict.found("free")) {
        const auto flags = dict.getChecked<std::vector<int>>(
            "free",
            [](const std::vector<int>& f) {
                return f.size() == std::size_t(D) && std::all_of(f.begin(), f.end(), [](int k) { return k == 0 || k == 1; });
            },
            D == 2 ? "(fx fy) with 1 (free) or 0 (prescribed) per direction, e.g. (0 1)"
                   : "(fx fy fz) with 1 (free) or 0 (prescribed) per direction, e.g. (0 0 1)");
        for (int d = 0; d < D; ++d) free_[d] = flags[d] == 1;
        if (std::none_of(free_.begin(), free_.end(), [](bool f) { return f; }))
            dict.fail("free", "weighted body " + name_ +
                                  " has no free direction; use type prescribedVelocity for a body moved at a given velocity");
    }
    if (dict.found("velocity")) velocity_ = TimeFunction::readVector<D>(dict, "velocity");
    if (dict.found("addedForce")) addedForce_ = TimeFunction::readVector<D>(dict, "addedForce");
    damping_ = dict.getOrDefault<double>("damping", 0.0);
    if (damping_ < 0.0 || damping_ >= 1.0) dict.fail("damping", "weighted body " + name_ + ": damping must lie in [0, 1)");
}

template <int D> void WeightedDriver<D>::attach(const RigidBodyInfo<D>& info)
{
    if (!(info.mass > 0.0)) throw RunError("weighted rigid body " + name_ + " has no particles (no mass)");
    mass_ = info.mass;
    gravity_ = info.gravity;
    velocity0_ = info.velocity;  // restart-safe: the body's particles carry its velocity
    for (int d = 0; d < D; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
}

template <int D>
typename WeightedDriver<D>::Vector WeightedDriver<D>::freeAcceleration(double t, const Vector& materialForce,
                                                                       const Vector& v) const
{
    Vector a = Vector::Zero();
    const Vector added = valueOf(addedForce_, t);
    for (int d = 0; d < D; ++d) {
        if (!free_[d]) continue;
        double F = mass_ * gravity_[d] + added[d] + materialForce[d];
        if (damping_ > 0.0 && v[d] != 0.0) F -= damping_ * std::abs(F) * (v[d] > 0.0 ? 1.0 : -1.0);  // eq. 3.3.5
        a[d] = F / mass_;
    }
    return a;
}

template <int D> void WeightedDriver<D>::start(double t) const
{
    started_ = true;
    time_ = t;
    // No reaction is known before the first step (nor after a restart): weight and added force.
    acceleration_ = freeAcceleration(t, Vector::Zero(), velocity0_);
}

template <int D> typename WeightedDriver<D>::Vector WeightedDriver<D>::velocity(double t, const Vector&) const
{
    if (!started_) start(t);
    const Vector prescribed = valueOf(velocity_, t);
    Vector v;
    for (int d = 0; d < D; ++d) v[d] = free_[d] ? velocity0_[d] + (t - time_) * acceleration_[d] : prescribed[d];
    return v;
}

template <int D> void WeightedDriver<D>::advance(double t, double dt, const RigidBodyLoad<D>& load)
{
    if (!started_) start(t);
    // The step [t, t + dt] moved the body with v(t + dt); that is the new state.
    velocity0_ += (t + dt - time_) * acceleration_;
    time_ = t + dt;
    for (int d = 0; d < D; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
    // The material's reaction of that step drives the next one (one step late, see the header).
    acceleration_ = freeAcceleration(time_, load.force, velocity0_);
}

template class WeightedDriver<2>;
#if GPIC_WITH_3D
template class WeightedDriver<3>;
#endif

} // namespace gpic
