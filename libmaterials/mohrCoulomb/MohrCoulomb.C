#include "mohrCoulomb/MohrCoulomb.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "plasticity/PrincipalStresses.H"
#include "plasticity/YieldState.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <new>
#include <sstream>

namespace gpic {

GPIC_REGISTER_DIMS(Material, MohrCoulomb, "mohrCoulomb")

namespace {

constexpr double degree = M_PI / 180.0;

std::string number(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

//- A property given either as a constant `key` or as a table `tableKey`; `deflt` when neither.
HardeningTable property(const Dictionary& dict, const std::string& key, const std::string& tableKey,
                        const std::function<bool(double)>& valid, const std::string& requirement,
                        std::optional<double> deflt = std::nullopt)
{
    const bool constant = dict.found(key), table = dict.found(tableKey);
    if (constant && table)
        dict.fail(tableKey, "keyword '" + tableKey + "' in dictionary " + dict.name() +
                                ": give either " + key + " or " + tableKey + ", not both");
    if (table) return HardeningTable(dict, tableKey, valid, requirement);
    if (constant)
        return HardeningTable(dict.getChecked<double>(
            key, [&valid](const double& v) { return valid(v); }, requirement));
    if (!deflt)
        dict.fail(key, "keyword '" + key + "' is undefined in dictionary " + dict.name() +
                           " (give " + key + " or " + tableKey + ")");
    return HardeningTable(*deflt);
}

//- The keyword a property was given by, for messages.
std::string givenAs(const Dictionary& dict, const std::string& key, const std::string& tableKey)
{
    return dict.found(tableKey) ? tableKey : key;
}

//- Largest tensile strength, the apex of the shear cone c/tan(phi) (eq. H.5.7).
double apexStress(double c, double phiDeg)
{
    return phiDeg > 0 ? c / std::tan(phiDeg * degree) : std::numeric_limits<double>::infinity();
}

//- d epsPs from principal plastic shear strains, eq. H.5.36, H.5.37 (all three components).
double shearHardeningIncrement(const Eigen::Vector3d& d)
{
    const double m = d.sum() / 3.0;
    return std::sqrt(0.5 * (d.array() - m).square().sum());
}

} // namespace

template <int D>
MohrCoulomb<D>::MohrCoulomb(const Dictionary& dict)
    : Material<D>(dict),
      elastic_(dict),
      phi_(property(dict, "phi", "phiTable", [](double v) { return v >= 0 && v < 90; },
                    "0 <= phi < 90 (degrees)")),
      psi_(property(dict, "psi", "psiTable", [](double v) { return v >= 0 && v < 90; },
                    "0 <= psi <= phi (degrees)", 0.0)),
      c_(property(dict, "c", "cTable", [](double v) { return v >= 0; }, "c >= 0")),
      return_(elastic_.alpha1(), elastic_.alpha2()),
      grains_(dict, this->rho()),
      constant_(true)
{
    // psi <= phi everywhere: both are piecewise linear, so at every breakpoint of either.
    std::vector<double> xs = phi_.x();
    xs.insert(xs.end(), psi_.x().begin(), psi_.x().end());
    for (double x : xs)
        if (psi_(x) > phi_(x)) {
            const std::string key = givenAs(dict, "psi", "psiTable");
            dict.fail(key, "keyword '" + key + "' in dictionary " + dict.name() + ": psi " +
                               number(psi_(x)) + " exceeds phi " + number(phi_(x)) +
                               (psi_.isConstant() && phi_.isConstant() ? "" : " at epsPs " + number(x)) +
                               "; requires 0 <= psi <= phi (degrees)");
        }

    const double apex0 = apexStress(c_(0), phi_(0));
    if (dict.found("sigmaT") || dict.found("sigmaTTable")) {
        sigmaT_ = property(dict, "sigmaT", "sigmaTTable", [](double v) { return v >= 0; }, "sigmaT >= 0");
        if ((*sigmaT_)(0) > apex0 * (1 + 1e-12)) {
            const std::string key = givenAs(dict, "sigmaT", "sigmaTTable");
            dict.fail(key, "keyword '" + key + "' in dictionary " + dict.name() + ": sigmaT " +
                               number((*sigmaT_)(0)) + " is not valid; requires 0 <= sigmaT <= c/tan(phi) (" +
                               number(apex0) + ")");
        }
    }
    constant_ = phi_.isConstant() && psi_.isConstant() && c_.isConstant() &&
                (!sigmaT_ || sigmaT_->isConstant());
}

template <int D> YieldPlanes MohrCoulomb<D>::planes(double epsPs, double epsPt) const
{
    const double phiDeg = phi_(epsPs), c = c_(epsPs);
    const double sinPhi = std::sin(phiDeg * degree), sinPsi = std::sin(psi_(epsPs) * degree);
    const double Nphi = (1 + sinPhi) / (1 - sinPhi);  // eq. H.5.4
    const double Npsi = (1 + sinPsi) / (1 - sinPsi);  // eq. H.5.9
    const double apex = apexStress(c, phiDeg);
    const double sigmaT = sigmaT_ ? std::min((*sigmaT_)(epsPt), apex) : apex;

    // f_s(i,j) = N_phi sigma_j - sigma_i - 2c sqrt(N_phi), g_s(i,j) = N_psi sigma_j - sigma_i
    const auto shear = [&](int i, int j) {
        YieldPlane plane;
        plane.a[i] = -1; plane.a[j] = Nphi;
        plane.k = 2 * c * std::sqrt(Nphi);
        plane.b[i] = -1; plane.b[j] = Npsi;
        return plane;
    };
    // f_t(j) = sigma_j - sigmaT, g_t(j) = sigma_j
    const auto tension = [&](int j) {
        YieldPlane plane;
        plane.a[j] = 1; plane.k = sigmaT; plane.b[j] = 1;
        plane.tension = true;
        return plane;
    };
    // In the order they are tried (see PrincipalReturn.H): the main plane and the tension
    // plane first, and the tension vertex, the usual apex of a cohesionless material, early
    // among the sets of three.
    const bool cutoff = std::isfinite(sigmaT);
    YieldPlanes set;
    set.add(shear(0, 2));
    if (cutoff) {
        set.add(tension(2));
        set.add(tension(1));
        set.add(tension(0));
    }
    set.add(shear(0, 1));
    set.add(shear(1, 2));
    if constexpr (D == 3) {
        // Where a 3D point mostly returns (measured on the collapsing column of bench/): the
        // compression edge sigma2 = sigma3 before the main plane, then the extension edge,
        // and, with the cutoff, the corners the tension planes make with them. The plane case
        // keeps its order of trial, and with it its results to the bit.
        const unsigned main = 1u << 0, compressionEdge = 1u << (cutoff ? 4 : 1),
                       extensionEdge = 1u << (cutoff ? 5 : 2), t3 = 1u << 1, t2 = 1u << 2, t1 = 1u << 3;
        set.addLikely(main | compressionEdge);
        set.addLikely(main);
        if (cutoff) set.addLikely(main | t3 | extensionEdge);
        set.addLikely(main | extensionEdge);
        if (cutoff) {
            set.addLikely(main | t3 | t2);
            set.addLikely(main | t3);
            set.addLikely(main | t3 | compressionEdge);
            set.addLikely(main | t2 | t1);
        }
    }
    return set;
}

template <int D> void MohrCoulomb<D>::updateStress(Particles<D>& p, const ParticleBlock& block, double) const
{
    using SymTensor = typename Space<D>::SymTensor;
    auto& state = p.history("yieldState");
    auto& epsPs = p.history("epsPs");
    auto& epsPt = p.history("epsPt");
    const PreparedPlanes fixed = return_.prepare(planes(0, 0));
    PreparedPlanes varying;
    unsigned activeSet = 0;  // the previous particle's return region, tried first
    // A batch in three loops: trial stresses and principal values, returns, write-back. The
    // points of each loop are independent, so their long chains (sine and cosine, two square
    // roots and a division in the principal values, the square root of the hardening) overlap
    // instead of waiting one after the other: the pass is latency-bound, not arithmetic-bound.
    constexpr std::size_t batch = 32;
    std::array<PrincipalStresses<D>, batch> principal;
    std::array<bool, batch> lost;
    std::array<PrincipalReturnResult, batch> returned;
    for (std::size_t b = block.begin; b < block.end; b += batch) {
        const std::size_t e = std::min(block.end, b + batch);
        for (std::size_t i = b; i < e; ++i) {
            SymTensor& s = p.sigma[i];
            lost[i - b] = grains_.lost(p.m[i], p.V[i]);
            if (lost[i - b]) continue;
            rotateJaumann(s, p.dOmega[i]);
            elastic_.addElasticIncrement(s, p.dEps[i]);  // sigma_I, eq. H.2.1
            // Built in place: a copy would read back the values as they are being stored.
            if constexpr (D == 2) new (&principal[i - b]) PrincipalStresses<D>(s);  // eq. H.5.26 - H.5.33
        }
        // 3D: all points of the batch at once (of a point lost, unused).
        if constexpr (D == 3) PrincipalStresses<D>::compute(&p.sigma[b], e - b, principal.data());
        for (std::size_t i = b; i < e; ++i) {
            if (lost[i - b]) continue;
            // Properties at the start of the step: hardening lags one step (seed H.5.3).
            if (!constant_) varying = return_.prepare(planes(epsPs[i], epsPt[i]));
            new (&returned[i - b]) PrincipalReturnResult(  // in place, as above
                return_(principal[i - b].values(), constant_ ? fixed : varying, &activeSet));
        }
        for (std::size_t i = b; i < e; ++i) {
            SymTensor& s = p.sigma[i];
            if (lost[i - b]) {
                s = SymTensor::Zero();
                state[i] = code(YieldState::disconnected);
                continue;
            }
            const PrincipalReturnResult& r = returned[i - b];
            if (!r.plastic()) {
                state[i] = code(YieldState::elastic);
                continue;
            }
            const PrincipalStresses<D>& trial = principal[i - b];
            s = trial.tensor(r.sigma);  // back to x1, x2 with the axes kept, eq. H.5.34
            p.epsP[i] += trial.tensor(r.dEpsPShear + r.dEpsPTension);
            epsPs[i] += shearHardeningIncrement(r.dEpsPShear);
            epsPt[i] += r.dEpsPTension.sum();
            const int used = r.nShear + r.nTension;
            state[i] = code(used >= 3   ? YieldState::apex
                            : used == 2 ? YieldState::edge
                            : r.nTension ? YieldState::tension
                                         : YieldState::shear);
        }
    }
}

template class MohrCoulomb<2>;
#if GPIC_WITH_3D
template class MohrCoulomb<3>;
#endif

} // namespace gpic
