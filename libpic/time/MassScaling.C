#include "time/MassScaling.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <sstream>

namespace gpic {

MassScaling MassScaling::read(const Dictionary& parent, double courant, const MassScaling& fallback)
{
    if (!parent.found("massScaling")) return fallback;
    if (!parent.isDict("massScaling"))
        parent.fail("massScaling", "massScaling needs a sub-dictionary: { factor 100; } or { timeStep 2e-4; }");
    const Dictionary& d = parent.subDict("massScaling");
    MassScaling s;
    s.courant_ = courant;
    const bool byFactor = d.found("factor"), byStep = d.found("timeStep");
    if (byFactor == byStep)
        d.fail(byFactor ? "timeStep" : "massScaling",
               "massScaling takes one of factor (the density's multiplier) or timeStep (the stable step to reach)");
    if (byFactor)
        s.factor_ = d.getChecked<double>("factor", [](const double& f) { return f >= 1; },
                                          "factor >= 1 (1: no scaling; a lighter material would only shorten the step)");
    else
        s.timeStep_ = d.getChecked<double>("timeStep", [](const double& t) { return t > 0; }, "timeStep > 0 [s]");
    s.kineticRatio_ = d.found("kineticRatio")
                          ? d.getChecked<double>("kineticRatio", [](const double& r) { return r > 0; }, "kineticRatio > 0")
                          : s.kineticRatio_;
    return s;
}

double MassScaling::scaleFor(double stableStep) const
{
    if (timeStep_ <= 0) return factor_;
    // C stableStep sqrt(s) = timeStep
    const double ratio = timeStep_ / (courant_ * stableStep);
    return std::max(1.0, ratio * ratio);
}

void MassScaling::refuseLoads(const Dictionary& where, bool hasLoads) const
{
    if (hasLoads && active())
        where.fail("massScaling", "mass scaling does not take the applied loads of constant/loads; run this "
                                  "scene unscaled");
}

std::string MassScaling::describe() const
{
    std::ostringstream os;
    if (timeStep_ > 0) os << "timeStep " << timeStep_ << " s";
    else os << "factor " << factor_;
    return os.str();
}

} // namespace gpic
