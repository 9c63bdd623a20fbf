#include "cosseratElastic/CosseratElasticity.H"

#include "dictionary/Dictionary.H"

#include <cmath>
#include <sstream>

namespace gpic {

CosseratElasticity::CosseratElasticity(const Dictionary& dict, double defaultGc)
    : G_(dict.getChecked<double>("G", [](const double& v) { return v > 0; }, "G > 0")),
      nu_(dict.getChecked<double>("nu", [](const double& v) { return v > -1.0 && v < 0.5; }, "-1 < nu < 0.5")),
      Gc_(0), l_(0), J33_(0)
{
    const auto nonNegative = [](const double& v) { return v >= 0; };
    if (defaultGc < 0 || dict.found("Gc")) Gc_ = dict.getChecked<double>("Gc", nonNegative, "Gc >= 0");
    else Gc_ = defaultGc;
    l_ = dict.getChecked<double>("l", nonNegative, "l >= 0 (characteristic length, m)");
    if (dict.found("J33")) {
        const bool needed = Gc_ > 0 || l_ > 0;
        J33_ = dict.getChecked<double>(
            "J33", [needed](const double& v) { return needed ? v > 0 : v >= 0; },
            needed ? "J33 > 0 (rotational inertia per unit mass, m^2) when Gc > 0 or l > 0" : "J33 >= 0");
    } else {
        J33_ = 0.125 * l_ * l_;  // a cylinder of diameter l (seed Table 6.2)
        if (J33_ == 0 && Gc_ > 0)
            dict.fail("J33", "keyword 'J33' is undefined in dictionary " + dict.name() +
                                 ": with l = 0 and Gc > 0 give the rotational inertia J33 > 0 (m^2)");
    }
}

CosseratMatrix CosseratElasticity::D() const
{
    CosseratMatrix D = CosseratMatrix::Zero();
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) D(a, b) = a == b ? c1G2() : c2G2();
    D(3, 3) = D(4, 4) = G_ + Gc_;
    D(3, 4) = D(4, 3) = G_ - Gc_;
    D(5, 5) = D(6, 6) = 2.0 * G_;
    return D;
}

double CosseratElasticity::waveSpeed(double rho) const
{
    return std::sqrt(std::max(c1G2(), G_ + Gc_) / rho);
}

double CosseratElasticity::rotationalTimeStep(double rho, double h) const
{
    if (!(J33_ > 0)) return 1e300;  // no rotational stiffness either (l = Gc = 0)
    const double cr2 = 2.0 * G_ * l_ * l_ / (rho * J33_);
    const double inverse2 = cr2 / (h * h) + Gc_ / (rho * J33_);
    return inverse2 > 0 ? 1.0 / std::sqrt(inverse2) : 1e300;
}

void setCosseratStress(Particles<2>& p, std::size_t i, const CosseratVector& s, double l)
{
    p.sigma[i] = SymTensor(s[0], s[1], s[2], s[3]);
    p.polar.sigma21[i] = s[4];
    p.polar.mu[i] = Vector2(l * s[5], l * s[6]);
}

} // namespace gpic
