#include "schemes/ParticleTransfer.H"

#include "dictionary/Dictionary.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER(ParticleTransfer, FlipTransfer, "FLIP")
GPIC_REGISTER(ParticleTransfer, PicTransfer, "PIC")
GPIC_REGISTER(ParticleTransfer, ApicTransfer, "APIC")
GPIC_REGISTER(ParticleTransfer, XpicTransfer, "XPIC")

FlipTransfer::FlipTransfer(const Dictionary& schemes)
{
    if (schemes.found("flipFraction") && schemes.found("flipRelaxationTime"))
        schemes.fail("flipRelaxationTime", "give flipFraction (a share per step) or flipRelaxationTime "
                                           "(per unit time), not both");
    if (schemes.found("flipFraction"))
        fraction_ = schemes.getChecked<double>("flipFraction", [](const double& f) { return f >= 0.0 && f <= 1.0; },
                                               "0 <= flipFraction <= 1 (1: FLIP, the seed's eq. 2.4.8; 0: PIC)");
    if (schemes.found("flipRelaxationTime"))
        relaxationTime_ = schemes.getChecked<double>("flipRelaxationTime", [](const double& t) { return t > 0.0; },
                                                     "flipRelaxationTime > 0 [s]");
    // No transfer named at all: the default, which lets a particle's own velocity relax.
    // `transfer FLIP;` alone is the seed's pure FLIP.
    else if (!schemes.found("transfer") && !schemes.found("flipFraction"))
        relaxationTime_ = defaultRelaxationTime;
}

double FlipTransfer::flipShare(double dt) const
{
    // A particle's own velocity then decays as exp(-t/tau) whatever the step.
    return relaxationTime_ > 0.0 ? std::exp(-dt / relaxationTime_) : fraction_;
}

XpicTransfer::XpicTransfer(const Dictionary& schemes)
{
    if (schemes.found("xpicOrder"))
        order_ = schemes.getChecked<int>("xpicOrder", [](const int& m) { return m >= 1 && m <= 20; },
                                         "1 <= xpicOrder <= 20 (1: PIC; 2 ... 5 are usual)");
}

} // namespace gpic
