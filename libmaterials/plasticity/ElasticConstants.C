#include "plasticity/ElasticConstants.H"

#include "dictionary/Dictionary.H"

#include <cmath>

namespace gpic {

namespace {

const char* const bothPairs = "give either E and nu, or K and G";

} // namespace

ElasticConstants::ElasticConstants(const Dictionary& dict) : K_(0), G_(0)
{
    const bool young = dict.found("E") || dict.found("nu");
    const bool bulk = dict.found("K") || dict.found("G");
    if (young && bulk) {
        const std::string second = dict.found("K") ? "K" : "G";
        dict.fail(second, "keyword '" + second + "' in dictionary " + dict.name() +
                              ": elastic constants from both pairs (E, nu and K, G); " +
                              bothPairs + ", not both");
    }
    if (!young && !bulk)
        dict.fail("E", "keyword 'E' is undefined in dictionary " + dict.name() +
                           ": elastic constants missing; " + bothPairs);

    if (young) {
        const double E = dict.getChecked<double>("E", [](const double& v) { return v > 0; }, "E > 0");
        const double nu = dict.getChecked<double>(
            "nu", [](const double& v) { return v > -1.0 && v < 0.5; }, "-1 < nu < 0.5");
        *this = ElasticConstants(E, nu);
    } else {
        K_ = dict.getChecked<double>("K", [](const double& v) { return v > 0; }, "K > 0");
        G_ = dict.getChecked<double>("G", [](const double& v) { return v > 0; }, "G > 0");
    }
}

double ElasticConstants::waveSpeed(double rho) const
{
    return std::sqrt((K_ + 4.0 * G_ / 3.0) / rho);
}

} // namespace gpic
