#include "rigidBodyDrivers/PrescribedVelocityDriver.H"

#include "core/Info.H"
#include "dictionary/Dictionary.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER(RigidBodyDriver<2>, PrescribedVelocityDriver, "prescribedVelocity")

PrescribedVelocityDriver::PrescribedVelocityDriver(const Dictionary& dict) : name_(dict.name())
{
    if (!dict.found("velocity") && !dict.found("omega"))
        dict.fail("type", "prescribedVelocity body " + name_ +
                              " needs velocity (vx vy) [m/s] and/or omega [rad/s]");
    if (dict.found("velocity")) velocity_ = TimeFunction::readVector(dict, "velocity");
    if (dict.found("omega")) {
        omega_ = TimeFunction::read(dict, "omega");
        if (!dict.found("centre"))
            dict.fail("omega", "prescribedVelocity body " + name_ +
                                   ": omega needs centre (x y), the point the body turns about");
    }
    centre0_ = dict.getOrDefault<Vector2>("centre", Vector2::Zero());
    cacheCentre_ = centre0_;
    previousCentre_ = centre0_;
    if (dict.found("targetForce")) {
        targetForce_ = dict.getChecked<Vector2>("targetForce", [](const Vector2& f) { return f.norm() > 0; },
                                                "a non-zero force (Fx Fy) [N/m]");
        hasTarget_ = true;
    }
}

Vector2 PrescribedVelocityDriver::centre(double t) const
{
    if (t == cacheTime_) return cacheCentre_;
    if (t == previousTime_) return previousCentre_;
    const Vector2 c = cacheCentre_ + integralOf(velocity_, cacheTime_, t);
    if (t > cacheTime_) {
        previousTime_ = cacheTime_;
        previousCentre_ = cacheCentre_;
        cacheTime_ = t;
        cacheCentre_ = c;
    }
    return c;
}

Vector2 PrescribedVelocityDriver::prescribedVelocity(double t, const Vector2& x) const
{
    Vector2 v = valueOf(velocity_, t);
    if (!omega_.isZero()) {
        const Vector2 r = x - centre(t);
        v += omega_.value(t) * Vector2(-r.y(), r.x());  // omega e_z x r
    }
    return v;
}

void PrescribedVelocityDriver::recogniseStop(double t) const
{
    started_ = true;
    if (!hasTarget_ || t <= 0.0 || info_.mass <= 0.0) return;
    const Vector2 expected = prescribedVelocity(t, info_.centroid);
    if (expected.norm() > 0.0 && info_.velocity.norm() <= 1e-9 * expected.norm()) {
        stopped_ = true;
        info() << "Rigid body " << name_ << " starts at rest: its targetForce was reached before t = "
                  << t << " s\n";
    }
}

Vector2 PrescribedVelocityDriver::velocity(double t, const Vector2& x) const
{
    if (!started_) recogniseStop(t);
    return stopped_ ? Vector2::Zero() : prescribedVelocity(t, x);
}

Vector2 PrescribedVelocityDriver::move(double t, double dt, const Vector2& x) const
{
    if (!started_) recogniseStop(t);
    if (stopped_) return x;
    if (omega_.isZero()) return x + integralOf(velocity_, t, t + dt);
    const Vector2 c0 = centre(t);
    const Vector2 c1 = centre(t + dt);
    const double turn = omega_.integral(t, t + dt);
    const double c = std::cos(turn), s = std::sin(turn);
    const Vector2 r = x - c0;
    return c1 + Vector2(c * r.x() - s * r.y(), s * r.x() + c * r.y());
}

void PrescribedVelocityDriver::advance(double t, double dt, const RigidBodyLoad<2>& load)
{
    if (!started_) recogniseStop(t);
    if (!hasTarget_ || stopped_) return;
    const double along = load.force.dot(targetForce_.normalized());
    if (along >= targetForce_.norm()) {
        stopped_ = true;
        info() << "Rigid body " << name_ << " reached its targetForce at t = " << t + dt
                  << " s (force along it " << along << " N/m): held still from now on\n";
    }
}

} // namespace gpic
