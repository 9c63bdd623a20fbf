#include "plasticity/MohrCoulombFit.H"

#include <cmath>
#include <stdexcept>

namespace gpic {

namespace {

//- qPhi-type coefficient and the kPhi-type factor (times c) of one fit for one angle.
struct ConeCoefficients {
    double slope;     //- qPhi (or qPsi)
    double cohesion;  //- kPhi / c
};

ConeCoefficients cone(MohrCoulombFitKind kind, double angle)
{
    const double sn = std::sin(angle), cs = std::cos(angle), r3 = std::sqrt(3.0);
    switch (kind) {
    case MohrCoulombFitKind::outer:  // eq. H.6.1
        return {6.0 * sn / (r3 * (3.0 - sn)), 6.0 * cs / (r3 * (3.0 - sn))};
    case MohrCoulombFitKind::inner:  // eq. H.6.2
        return {6.0 * sn / (r3 * (3.0 + sn)), 6.0 * cs / (r3 * (3.0 + sn))};
    case MohrCoulombFitKind::planeStrain: {  // FLAC
        const double t = std::tan(angle), root = std::sqrt(9.0 + 12.0 * t * t);
        return {3.0 * t / root, 3.0 / root};
    }
    }
    throw std::logic_error("unknown Mohr-Coulomb fit");
}

} // namespace

const std::vector<std::string>& mohrCoulombFitNames()
{
    static const std::vector<std::string> names{"outer", "inner", "planeStrain"};
    return names;
}

MohrCoulombFitKind mohrCoulombFitKind(const std::string& name)
{
    if (name == "outer") return MohrCoulombFitKind::outer;
    if (name == "inner") return MohrCoulombFitKind::inner;
    if (name == "planeStrain") return MohrCoulombFitKind::planeStrain;
    throw std::logic_error("unknown Mohr-Coulomb fit '" + name + "'");
}

DruckerPragerParameters fitMohrCoulomb(MohrCoulombFitKind kind, double phi, double psi, double c)
{
    const ConeCoefficients friction = cone(kind, phi);
    return {friction.slope, friction.cohesion * c, cone(kind, psi).slope};
}

} // namespace gpic
