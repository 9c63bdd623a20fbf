#include "time/StabilitySettings.H"

#include "dictionary/Dictionary.H"
#include "time/TimeControl.H"

namespace gpic {

StabilitySettings StabilitySettings::read(const Dictionary& controlDict, const TimeControl& time)
{
    StabilitySettings s;
    if (const Dictionary* d = controlDict.subDictPtr("stabilityGuard")) {
        if (d->found("snapshotInterval"))
            s.snapshotInterval =
                d->getChecked<long>("snapshotInterval", [](const long& n) { return n >= 1; }, "snapshotInterval >= 1");
        if (d->found("maxEnergyGain"))
            s.maxEnergyGain =
                d->getChecked<double>("maxEnergyGain", [](const double& g) { return g > 0; }, "maxEnergyGain > 0");
    }
    s.adjustTimeStep = time.adjustTimeStep();
    s.courant = time.courant();
    s.fixedDeltaT = time.firstDeltaT();
    return s;
}

} // namespace gpic
