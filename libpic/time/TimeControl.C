#include "time/TimeControl.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gpic {

namespace {
const auto positive = [](const double& v) { return v > 0; };
std::string format(double v)
{
    std::ostringstream os;
    os.precision(4);
    os << v;
    return os.str();
}
} // namespace

TimeControl::TimeControl(const Dictionary& d)
    : dict_(d),
      startFrom_(d.getWordOrDefault("startFrom", {"startTime", "firstTime", "latestTime"},
                                    "latestTime")),
      startTime_(d.getOrDefault<double>("startTime", 0.0)),
      // A run in stages ends with its last stage: endTime is optional there.
      endTime_(d.found("stages") && !d.found("endTime") ? std::numeric_limits<double>::infinity()
                                                         : d.get<double>("endTime")),
      deltaT_(d.getChecked<double>("deltaT", positive, "deltaT > 0")),
      adjustTimeStep_(d.getOrDefault<bool>("adjustTimeStep", false)),
      maxCourant_(d.found("maxCourant")
                      ? d.getChecked<double>(
                            "maxCourant", [](const double& c) { return c > 0 && c <= 1; },
                            "0 < maxCourant <= 1")
                      : 0.5),
      maxDeltaT_(d.found("maxDeltaT") ? d.getChecked<double>("maxDeltaT", positive, "maxDeltaT > 0")
                                      : deltaT_),
      writeControl_(d.getWordOrDefault("writeControl", {"timeStep", "runTime", "adjustableRunTime"},
                                       "runTime")),
      writeInterval_(d.getChecked<double>("writeInterval", positive, "writeInterval > 0")),
      timePrecision_(d.found("timePrecision")
                         ? d.getChecked<int>(
                               "timePrecision", [](const int& p) { return p >= 1 && p <= 17; },
                               "1 <= timePrecision <= 17")
                         : 6),
      purgeWrite_(d.found("purgeWrite")
                      ? d.getChecked<int>("purgeWrite", [](const int& n) { return n >= 0; },
                                          "purgeWrite >= 0")
                      : 0)
{
    // Only endTime is meaningful before a run starts (OpenFOAM's other choices act on a
    // running case); `application` names the solver for scripts.
    d.getWordOrDefault("stopAt", {"endTime"}, "endTime");
    d.getOrDefault<std::string>("application", "picSolver");
    if (endTime_ < startTime_) d.fail("endTime", "endTime is before startTime");
    if (writeControl_ == "timeStep" && std::floor(writeInterval_) != writeInterval_)
        d.fail("writeInterval", "writeInterval must be a whole number of steps with "
                                "writeControl timeStep");
}

bool TimeControl::finished(double t) const { return t >= endTime_ - 1e-9 * deltaT_; }

long TimeControl::writeIndex(double t) const
{
    return static_cast<long>(std::floor(t / writeInterval_ + 1e-9));
}

void TimeControl::checkStable(double dtCritical, const std::string& why) const
{
    if (!adjustTimeStep_ && deltaT_ > dtCritical)
        dict_.fail("deltaT", "deltaT " + format(deltaT_) + " s is above the stability limit " +
                                 format(dtCritical) + " s (" + why +
                                 "); use deltaT <= " + format(dtCritical) +
                                 " or adjustTimeStep yes");
}

double TimeControl::deltaT(double t, double dtCritical, double landOn) const
{
    double dt;
    if (adjustTimeStep_) {
        dt = plainDeltaT(dtCritical);
    } else {
        if (deltaT_ > dtCritical)
            throw RunError("at time " + format(t) + " the fixed deltaT " + format(deltaT_) +
                           " s exceeds the stability limit " + format(dtCritical) +
                           " s (particles sped up); use a smaller deltaT or adjustTimeStep yes");
        dt = deltaT_;
    }
    if (writeControl_ == "adjustableRunTime") {
        const double nextWrite = (writeIndex(t) + 1) * writeInterval_;
        if (t + dt > nextWrite - 1e-9 * dt) dt = nextWrite - t;
    }
    if (t + dt > landOn) dt = landOn - t;
    if (t + dt > endTime_) dt = endTime_ - t;
    return dt;
}

bool TimeControl::isWriteTime(double tPrevious, double t, long step) const
{
    if (writeControl_ == "timeStep") return step % static_cast<long>(writeInterval_) == 0;
    return writeIndex(t) > writeIndex(tPrevious);
}

} // namespace gpic
