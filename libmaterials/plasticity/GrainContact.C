#include "plasticity/GrainContact.H"

#include "dictionary/Dictionary.H"

#include <sstream>

namespace gpic {

GrainContact::GrainContact(const Dictionary& dict, double rho)
    : rhoDisconnected_(rho / defaultLooseness)
{
    if (!dict.found("rhoDisconnected")) return;
    std::ostringstream requirement;
    requirement << "0 <= rhoDisconnected < rho (" << rho << " kg/m^3); 0 keeps the grains in contact";
    rhoDisconnected_ = dict.getChecked<double>(
        "rhoDisconnected", [rho](const double& v) { return v >= 0 && v < rho; }, requirement.str());
}

} // namespace gpic
