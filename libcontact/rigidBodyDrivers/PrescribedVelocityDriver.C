#include "rigidBodyDrivers/PrescribedVelocityDriver.H"

#include "core/Info.H"
#include "dictionary/Dictionary.H"

#include <Eigen/Geometry>

#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(RigidBodyDriver, PrescribedVelocityDriver, "prescribedVelocity")

template <int D>
PrescribedVelocityDriver<D>::PrescribedVelocityDriver(const Dictionary& dict) : name_(dict.name())
{
    if (!dict.found("velocity") && !dict.found("omega"))
        dict.fail("type", "prescribedVelocity body " + name_ + (D == 2 ? " needs velocity (vx vy)" : " needs velocity (vx vy vz)") +
                              " [m/s] and/or omega [rad/s]");
    if (dict.found("velocity")) velocity_ = TimeFunction::readVector<D>(dict, "velocity");
    if (dict.found("omega")) {
        omega_ = TimeFunction::read(dict, "omega");
        if (!dict.found("centre"))
            dict.fail("omega", "prescribedVelocity body " + name_ + ": omega needs centre " +
                                   (D == 2 ? "(x y), the point the body turns about" : "(x y z), a point of the axis the body turns about"));
        if (D == 3 && !dict.found("axis"))
            dict.fail("omega", "prescribedVelocity body " + name_ +
                                   ": omega needs axis (ex ey ez) in 3D, the direction the body turns about");
    }
    if (D == 3 && dict.found("axis"))
        axis_ = dict.getChecked<Vector>("axis", [](const Vector& e) { return e.norm() > 0; }, "a non-zero direction")
                    .normalized();
    centre0_ = dict.getOrDefault<Vector>("centre", Vector::Zero());
    cacheCentre_ = centre0_;
    previousCentre_ = centre0_;
    if (dict.found("targetForce")) {
        targetForce_ = dict.getChecked<Vector>("targetForce", [](const Vector& f) { return f.norm() > 0; },
                                               D == 2 ? "a non-zero force (Fx Fy) [N/m]" : "a non-zero force (Fx Fy Fz) [N]");
        hasTarget_ = true;
    }
}

template <int D>
typename Space<D>::Vector PrescribedVelocityDriver<D>::centre(double t) const
{
    if (t == cacheTime_) return cacheCentre_;
    if (t == previousTime_) return previousCentre_;
    const Vector c = cacheCentre_ + integralOf(velocity_, cacheTime_, t);
    if (t > cacheTime_) {
        previousTime_ = cacheTime_;
        previousCentre_ = cacheCentre_;
        cacheTime_ = t;
        cacheCentre_ = c;
    }
    return c;
}

template <int D>
typename Space<D>::Vector PrescribedVelocityDriver<D>::prescribedVelocity(double t, const Vector& x) const
{
    Vector v = valueOf(velocity_, t);
    if (!omega_.isZero()) {
        const Vector r = x - centre(t);
        if constexpr (D == 2) v += omega_.value(t) * Vector(-r.y(), r.x());  // omega e_z x r
        else v += omega_.value(t) * axis_.cross(r);
    }
    return v;
}

template <int D>
void PrescribedVelocityDriver<D>::recogniseStop(double t) const
{
    started_ = true;
    if (!hasTarget_ || t <= 0.0 || info_.mass <= 0.0) return;
    const Vector expected = prescribedVelocity(t, info_.centroid);
    if (expected.norm() > 0.0 && info_.velocity.norm() <= 1e-9 * expected.norm()) {
        stopped_ = true;
        info() << "Rigid body " << name_ << " starts at rest: its targetForce was reached before t = "
                  << t << " s\n";
    }
}

template <int D>
typename Space<D>::Vector PrescribedVelocityDriver<D>::velocity(double t, const Vector& x) const
{
    if (!started_) recogniseStop(t);
    return stopped_ ? Vector(Vector::Zero()) : prescribedVelocity(t, x);
}

template <int D>
typename Space<D>::Vector PrescribedVelocityDriver<D>::move(double t, double dt, const Vector& x) const
{
    if (!started_) recogniseStop(t);
    if (stopped_) return x;
    if (omega_.isZero()) return x + integralOf(velocity_, t, t + dt);
    const Vector c0 = centre(t);
    const Vector c1 = centre(t + dt);
    const double turn = omega_.integral(t, t + dt);
    const double c = std::cos(turn), s = std::sin(turn);
    const Vector r = x - c0;
    if constexpr (D == 2) {
        return c1 + Vector(c * r.x() - s * r.y(), s * r.x() + c * r.y());
    } else {  // Rodrigues: r turned by `turn` about the unit axis e
        const Vector& e = axis_;
        return c1 + c * r + s * e.cross(r) + (1.0 - c) * e.dot(r) * e;
    }
}

template <int D> void PrescribedVelocityDriver<D>::advance(double t, double dt, const RigidBodyLoad<D>& load)
{
    if (!started_) recogniseStop(t);
    if (!hasTarget_ || stopped_) return;
    const double along = load.force.dot(targetForce_.normalized());
    if (along >= targetForce_.norm()) {
        stopped_ = true;
        info() << "Rigid body " << name_ << " reached its targetForce at t = " << t + dt << " s (force along it "
               << along << (D == 2 ? " N/m" : " N") << "): held still from now on\n";
    }
}

template class PrescribedVelocityDriver<2>;
#if GPIC_WITH_3D
template class PrescribedVelocityDriver<3>;
#endif

} // namespace gpic
