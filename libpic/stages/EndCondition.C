#include "stages/EndCondition.H"

#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "engine/MpmSolver.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>

namespace gpic {

namespace {
const char* const kindNames[] = {"endTime", "duration", "displacement", "equilibrium"};

std::string brief(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}
} // namespace

template <int D>
EndCondition<D>::EndCondition(const Dictionary& stage, const std::vector<std::string>& bodyNames, int defaultBody)
    : body_(defaultBody)
{
    if (!stage.isDict("until"))
        stage.fail("until", "stage '" + stage.name() + "' needs an end condition: until { endTime T; }, "
                   "{ duration T; }, { displacement D; body b; } or { equilibrium v; }");
    const Dictionary& until = stage.subDict("until");
    int given = 0;
    for (int k = 0; k < 4; ++k)
        if (until.found(kindNames[k])) {
            kind_ = static_cast<Kind>(k);
            ++given;
        }
    if (given != 1)
        until.fail("", "until needs exactly one of endTime, duration, displacement and equilibrium in dictionary " +
                           until.name());
    const auto positive = [](const double& v) { return v > 0; };
    if (kind_ == Kind::endTime) value_ = until.get<double>("endTime");
    else value_ = until.getChecked<double>(kindName(), positive, kindName() + " > 0");
    if (kind_ == Kind::displacement) {
        if (until.found("body") || body_ < 0) {
            const std::string name = until.get<std::string>("body");
            const auto it = std::find(bodyNames.begin(), bodyNames.end(), name);
            if (it == bodyNames.end()) {
                std::string valid;
                for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
                until.fail("body", "'" + name + "' is not a body of the particles; valid choices: " + valid);
            }
            body_ = static_cast<int>(it - bodyNames.begin());
        }
    }
    if (kind_ == Kind::equilibrium)
        minSteps_ = until.getOrDefault<long>("minSteps", 10);
    if (until.found("maxTime")) maxTime_ = until.getChecked<double>("maxTime", positive, "maxTime > 0");
    until.warnUnused();
}

template <int D>
const std::string& EndCondition<D>::kindName() const
{
    static const std::string names[] = {kindNames[0], kindNames[1], kindNames[2], kindNames[3]};
    return names[static_cast<int>(kind_)];
}

template <int D>
double EndCondition<D>::maxSpeed(const MpmSolver<D>& solver)
{
    const Particles<D>& p = solver.particles();
    double v2 = 0;
    for (std::size_t q = 0; q < p.size(); ++q)
        if (!solver.rigidBody(p.body[q])) v2 = std::max(v2, p.v[q].squaredNorm());
    return std::sqrt(solver.ranks().largest(v2));  // a parallel run: over every rank
}

template <int D>
typename Space<D>::Vector EndCondition<D>::centreOf(const MpmSolver<D>& solver, int b)
{
    const Particles<D>& p = solver.particles();
    double m = 0;
    Vector c = Vector::Zero();
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == b) {
            m += p.m[q];
            c += p.m[q] * p.x[q];
        }
    if (solver.ranks().parallel()) {  // every rank's particles of the body
        std::vector<double> sums{m};
        sums.insert(sums.end(), c.data(), c.data() + D);
        solver.sumOverRanks(sums);
        m = sums[0];
        for (int a = 0; a < D; ++a) c[a] = sums[1 + a];
    }
    return m > 0 ? Vector(c / m) : c;
}

template <int D>
void EndCondition<D>::start(const MpmSolver<D>& solver, double t, long step)
{
    tStart_ = t;
    stepStart_ = step;
    if (kind_ == Kind::displacement) centre0_ = centreOf(solver, body_);
}

template <int D>
double EndCondition<D>::landOn() const
{
    double t = std::numeric_limits<double>::infinity();
    if (kind_ == Kind::endTime) t = value_;
    if (kind_ == Kind::duration) t = tStart_ + value_;
    if (maxTime_ > 0) t = std::min(t, tStart_ + maxTime_);
    return t;
}

template <int D>
bool EndCondition<D>::reached(const MpmSolver<D>& solver, double t, long step, double dt, std::string& reason,
                           bool& timedOut) const
{
    timedOut = false;
    const double slack = 1e-9 * dt;  // the step landed on the time up to round-off
    switch (kind_) {
    case Kind::endTime:
        if (t >= value_ - slack) {
            reason = "endTime " + brief(value_) + " s reached";
            return true;
        }
        break;
    case Kind::duration:
        if (t >= tStart_ + value_ - slack) {
            reason = "duration " + brief(value_) + " s reached";
            return true;
        }
        break;
    case Kind::displacement: {
        const double d = (centreOf(solver, body_) - centre0_).norm();
        if (d >= value_) {
            reason = "displacement " + brief(d) + " m >= " + brief(value_) + " m";
            return true;
        }
        break;
    }
    case Kind::equilibrium: {
        const double v = maxSpeed(solver);
        if (step - stepStart_ >= minSteps_ && v <= value_) {
            reason = "equilibrium |v|max " + brief(v) + " <= " + brief(value_) + " m/s";
            return true;
        }
        break;
    }
    }
    if (maxTime_ > 0 && t >= tStart_ + maxTime_ - slack) {
        timedOut = true;
        std::string missed = kindName() + " " + brief(value_);
        if (kind_ == Kind::equilibrium) missed += " m/s (|v|max " + brief(maxSpeed(solver)) + " m/s)";
        if (kind_ == Kind::displacement)
            missed += " m (moved " + brief((centreOf(solver, body_) - centre0_).norm()) + " m)";
        reason = "maxTime " + brief(maxTime_) + " s reached before " + missed;
        return true;
    }
    return false;
}

template <int D>
void EndCondition<D>::writeProgress(std::ostream& os, const std::string& indent) const
{
    os << indent << "startTime " << exactNumber(tStart_) << ";\n"
       << indent << "startStep " << stepStart_ << ";\n"
       << indent << "centre (" << exactNumber(centre0_.x()) << " " << exactNumber(centre0_.y()) << ");\n";
}

template <int D>
void EndCondition<D>::readProgress(const Dictionary& d)
{
    tStart_ = d.get<double>("startTime");
    stepStart_ = d.get<long>("startStep");
    centre0_ = d.get<Vector>("centre");
}

template class EndCondition<2>;
#if GPIC_WITH_3D
template class EndCondition<3>;
#endif

} // namespace gpic
