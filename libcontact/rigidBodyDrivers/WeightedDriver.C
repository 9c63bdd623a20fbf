#include "rigidBodyDrivers/WeightedDriver.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

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
    if (dict.found("freeRotation")) {
        if constexpr (D == 2) {
            const int flag = dict.getChecked<int>("freeRotation", [](int k) { return k == 0 || k == 1; },
                                                  "1 (turns freely about e3) or 0");
            freeAxes_[0] = flag == 1;
        } else {
            const auto flags = dict.getChecked<std::vector<int>>(
                "freeRotation",
                [](const std::vector<int>& f) {
                    return f.size() == 3u && std::all_of(f.begin(), f.end(), [](int k) { return k == 0 || k == 1; });
                },
                "(r1 r2 r3) with 1 (turns freely about that axis) or 0 per axis, e.g. (0 1 0)");
            for (int a = 0; a < 3; ++a) freeAxes_[a] = flags[a] == 1;
        }
        turns_ = std::any_of(freeAxes_.begin(), freeAxes_.end(), [](bool f) { return f; });
    }
    if (dict.found("addedMoment")) {
        if (!turns_) dict.fail("addedMoment", "weighted body " + name_ + ": an added moment needs freeRotation");
        if constexpr (D == 2) addedMoment_[0] = TimeFunction::read(dict, "addedMoment");
        else addedMoment_ = TimeFunction::readVector<3>(dict, "addedMoment");
    }
}

namespace {
//- omega x r: (-omega r_y, omega r_x) in the plane.
inline Space<2>::Vector turnVelocity(double omega, const Space<2>::Vector& r) { return omega * Space<2>::Vector(-r.y(), r.x()); }
inline Space<3>::Vector turnVelocity(const Space<3>::Vector& omega, const Space<3>::Vector& r) { return omega.cross(r); }

//- r turned by omega dt (about e3 in the plane; Rodrigues about omega's direction in 3D).
inline Space<2>::Vector turned(double omega, double dt, const Space<2>::Vector& r)
{
    const double c = std::cos(omega * dt), s = std::sin(omega * dt);
    return {c * r.x() - s * r.y(), s * r.x() + c * r.y()};
}
inline Space<3>::Vector turned(const Space<3>::Vector& omega, double dt, const Space<3>::Vector& r)
{
    const double rate = omega.norm();
    if (rate == 0.0) return r;
    const Space<3>::Vector e = omega / rate;
    const double c = std::cos(rate * dt), s = std::sin(rate * dt);
    return c * r + s * e.cross(r) + (1.0 - c) * e.dot(r) * e;
}
//- The component of a moment about axis a (the plane has one, about e3).
inline double& axisOf(double& m, int) { return m; }
inline double axisOf(const double& m, int) { return m; }
inline double& axisOf(Space<3>::Vector& m, int a) { return m[a]; }
inline double axisOf(const Space<3>::Vector& m, int a) { return m[a]; }
//- The matrix of that turn (3D).
inline Eigen::Matrix3d turnMatrix(const Space<3>::Vector& omega, double dt)
{
    Eigen::Matrix3d R;
    for (int a = 0; a < 3; ++a) R.col(a) = turned(omega, dt, Space<3>::Vector::Unit(a));
    return R;
}
} // namespace

template <int D> void WeightedDriver<D>::attach(const RigidBodyInfo<D>& info)
{
    if (!(info.mass > 0.0)) throw RunError("weighted rigid body " + name_ + " has no particles (no mass)");
    mass_ = info.mass;
    gravity_ = info.gravity;
    velocity0_ = info.velocity;  // restart-safe: the body's particles carry its velocity
    for (int d = 0; d < D; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
    if (!turns_) return;
    centre_ = info.centroid;
    inertia0_ = info.inertia;
    // Restart-safe, as the velocity: L = I omega with the particles' spin about the free axes.
    Moment omega = info.angularVelocity;
    if constexpr (D == 2) {
        if (!(inertia0_ > 0.0)) throw RunError("weighted rigid body " + name_ + " has no moment of inertia to turn with");
    } else {
        turn_ = Inertia::Identity();
        for (int a = 0; a < 3; ++a) {
            if (!freeAxes_[a]) omega[a] = 0.0;
            else if (!(inertia0_(a, a) > 0.0))
                throw RunError("weighted rigid body " + name_ + " has no moment of inertia about axis " + std::to_string(a + 1));
        }
    }
    angularMomentum_ = inertia0_ * omega;
}

template <int D> const typename WeightedDriver<D>::Moment& WeightedDriver<D>::omegaAt(double t) const
{
    if (t == omegaTime_ && time_ == omegaState_) return omega_;
    const Moment L = angularMomentum_ + (t - time_) * momentRate_;
    if constexpr (D == 2) {
        omega_ = L / inertia0_;
    } else {
        // The rows of the free axes of I omega = L, with omega zero about the others.
        Inertia A = turn_ * inertia0_ * turn_.transpose();
        Moment b = L;
        for (int a = 0; a < 3; ++a) {
            if (freeAxes_[a]) continue;
            A.row(a).setZero();
            A.col(a).setZero();
            A(a, a) = 1.0;
            b[a] = 0.0;
        }
        omega_ = A.ldlt().solve(b);
    }
    omegaTime_ = t;
    omegaState_ = time_;
    return omega_;
}

template <int D>
typename WeightedDriver<D>::Moment WeightedDriver<D>::freeMomentRate(double t, const Moment& materialMoment,
                                                                     const Moment& omega) const
{
    Moment rate = materialMoment;
    for (int a = 0; a < nAxes; ++a) {
        double& M = axisOf(rate, a);
        if (!freeAxes_[a]) {
            M = 0.0;
            continue;
        }
        M += addedMoment_[a].value(t);
        const double w = axisOf(omega, a);
        if (damping_ > 0.0 && w != 0.0) M -= damping_ * std::abs(M) * (w > 0.0 ? 1.0 : -1.0);  // eq. 3.3.5
    }
    return rate;
}

template <int D> typename WeightedDriver<D>::Vector WeightedDriver<D>::centreAt(double t) const
{
    return centre_ + (t - time_) * linearVelocity(t);
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
    if (turns_) momentRate_ = freeMomentRate(t, Space<D>::zeroMoment(), omegaAt(t));
}

template <int D> typename WeightedDriver<D>::Vector WeightedDriver<D>::linearVelocity(double t) const
{
    if (!started_) start(t);
    const Vector prescribed = valueOf(velocity_, t);
    Vector v;
    for (int d = 0; d < D; ++d) v[d] = free_[d] ? velocity0_[d] + (t - time_) * acceleration_[d] : prescribed[d];
    return v;
}

template <int D> typename WeightedDriver<D>::Vector WeightedDriver<D>::velocity(double t, const Vector& x) const
{
    const Vector v = linearVelocity(t);
    return turns_ ? Vector(v + turnVelocity(omegaAt(t), x - (centre_ + (t - time_) * v))) : v;  // c(t), centreAt
}

template <int D> typename WeightedDriver<D>::Vector WeightedDriver<D>::move(double t, double dt, const Vector& x) const
{
    if (!turns_) return x + dt * velocity(t + dt, x);
    if (!started_) start(t);
    return centreAt(t + dt) + turned(omegaAt(t + dt), dt, x - centreAt(t));
}

template <int D> void WeightedDriver<D>::advance(double t, double dt, const RigidBodyLoad<D>& load)
{
    if (!started_) start(t);
    Moment materialMoment{};
    if (turns_) {  // the turn of the step, with the omega the points moved by
        const Vector c = centreAt(t);
        materialMoment = load.momentAbout(c);
        const Moment omega = omegaAt(t + dt);
        if constexpr (D == 3) turn_ = turnMatrix(omega, dt) * turn_;
        centre_ = centreAt(t + dt);
        angularMomentum_ += (t + dt - time_) * momentRate_;
    }
    // The step [t, t + dt] moved the body with v(t + dt); that is the new state.
    velocity0_ += (t + dt - time_) * acceleration_;
    time_ = t + dt;
    for (int d = 0; d < D; ++d)
        if (!free_[d]) velocity0_[d] = 0.0;
    // The material's reaction of that step drives the next one (one step late, see the header).
    acceleration_ = freeAcceleration(time_, load.force, velocity0_);
    if (turns_) momentRate_ = freeMomentRate(time_, materialMoment, omegaAt(time_));
}

template class WeightedDriver<2>;
#if GPIC_WITH_3D
template class WeightedDriver<3>;
#endif

} // namespace gpic
