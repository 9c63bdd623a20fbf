#include "stages/GeostaticFillStage.H"

#include "core/error.H"
#include "core/Info.H"
#include "dictionary/Dictionary.H"
#include "engine/MpmSolver.H"
#include "stages/ParticlePool.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace gpic {

GPIC_REGISTER_DIMS(Stage, GeostaticFillStage, "geostaticFill")

template <int D>
GeostaticFillStage<D>::GeostaticFillStage(const Dictionary& dict, const StageSetup<D>& setup)
    : Stage<D>(dict, setup, 0.8)
{
    if (until().kind() != EndCondition<D>::Kind::equilibrium)
        dict.fail("until", "geostaticFill brings each layer to equilibrium: until { equilibrium 1e-6; } "
                           "(optionally maxTime, minSteps), not " + until().kindName());
    const std::size_t nBodies = setup.bodyNames.size();
    fill_.assign(nBodies, 0);
    if (dict.found("fill")) {
        for (const auto& name : dict.get<std::vector<std::string>>("fill")) {
            const int b = bodyId(dict, "fill", name);
            if (!isActive(b)) dict.fail("fill", "body '" + name + "' is filled but not among the stage's bodies (" + bodyList() + ")");
            if (isRigid(b)) dict.fail("fill", "body '" + name + "' has a driver: only deformable bodies are filled");
            fill_[static_cast<std::size_t>(b)] = 1;
        }
    } else {
        for (std::size_t b = 0; b < nBodies; ++b) fill_[b] = isActive(static_cast<int>(b)) && !isRigid(static_cast<int>(b));
    }
    if (std::find(fill_.begin(), fill_.end(), 1) == fill_.end())
        dict.fail("fill", "geostaticFill has no deformable body to fill among its bodies (" + bodyList() + ")");
    const auto positive = [](const double& v) { return v > 0; };
    thickness_ = dict.found("layerThickness")
                     ? dict.getChecked<double>("layerThickness", positive, "layerThickness > 0")
                     : setup.cellHeight;
    upTo_ = dict.getOrDefault<double>("upTo", std::numeric_limits<double>::infinity());
    // K0 given (eq. 3.3.1; nu/(1-nu) for an elastic mass) or by Jaky (eq. 3.3.3).
    if (dict.found("K0") == dict.found("phi"))
        dict.fail("K0", "geostaticFill needs exactly one of K0 and phi (Jaky: K0 = 1 - sin(phi)) in dictionary " +
                            dict.name());
    if (dict.found("K0")) K0_ = dict.getChecked<double>("K0", positive, "K0 > 0");
    else
        K0_ = 1.0 - std::sin(M_PI / 180.0 * dict.getChecked<double>(
                                                 "phi", [](const double& p) { return p >= 0 && p < 90; },
                                                 "0 <= phi < 90 (degrees)"));
}

template <int D>
typename Space<D>::Vector GeostaticFillStage<D>::up() const
{
    const Vector g = gravity();
    return g.norm() > 0 ? Vector(-g / g.norm()) : Vector(Vector::Unit(D - 1));
}

template <int D>
bool GeostaticFillStage<D>::addLayer(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step)
{
    // Heights and depths are measured against gravity, so a scene turned on the grid (gravity
    // not along -x2, seed fig. 6.19) fills in layers normal to gravity, as the seed's upright
    // one does; with gravity along -x2 the height is x2.
    const Vector u = up();
    const auto height = [&](const Particles<D>& p, std::size_t q) { return p.x[q].dot(u); };
    const Particles<D>& sleeping = pool.dormant();
    const auto waiting = [&](const Particles<D>& p, std::size_t q) { return fills(p.body[q]) && height(p, q) < upTo_; };
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < sleeping.size(); ++q)
        if (waiting(sleeping, q)) lowest = std::min(lowest, height(sleeping, q));
    lowest = solver.ranks().smallest(lowest);  // a parallel run: every rank's sleeping particles
    if (!std::isfinite(lowest)) return false;
    // The band of the lowest waiting particle: bands of layerThickness from the grid's lowest corner.
    const Vector &lo = setup().gridMin, &hi = setup().gridMax;
    double y0 = 0;
    if constexpr (D == 2) {
        y0 = std::min({lo.dot(u), Vector(hi.x(), lo.y()).dot(u), Vector(lo.x(), hi.y()).dot(u), hi.dot(u)});
    } else {  // the lowest corner: the lower end along each axis
        for (int a = 0; a < D; ++a) y0 += std::min(lo[a] * u[a], hi[a] * u[a]);
    }
    band_ = std::max(band_ + 1, static_cast<long>(std::floor((lowest - y0) / thickness_ + 1e-9)));
    const double top = y0 + (band_ + 1) * thickness_;
    const double g = gravity().norm();
    const auto wakes = [&](const Particles<D>& p, std::size_t q) { return waiting(p, q) && height(p, q) < top; };
    // The free surface of the new layer: the top of its particles' domains (over every rank's).
    double surface = -std::numeric_limits<double>::infinity();
    double count = 0;
    for (std::size_t q = 0; q < sleeping.size(); ++q)
        if (wakes(sleeping, q)) {
            surface = std::max(surface, height(sleeping, q) + sleeping.halfSize[q].cwiseProduct(u).cwiseAbs().sum());
            ++count;
        }
    surface = solver.ranks().largest(surface);
    count = solver.ranks().total(count);
    pool.exchange(
        solver, [](const Particles<D>&, std::size_t) { return false; }, wakes,
        [&](Particles<D>& p, std::size_t begin, std::size_t end) {
            for (std::size_t q = begin; q < end; ++q) {
                const double rho = solver.materials()[static_cast<std::size_t>(p.material[q])]->rho();
                const double sV = -rho * g * std::max(0.0, surface - height(p, q));  // eq. 3.3.4, along gravity
                // K0 sV across gravity and out of plane, sV along it: K0 sV I + (1 - K0) sV u u^T.
                const double sUU = (1.0 - K0_) * sV;
                if constexpr (D == 2) {
                    p.sigma[q] = SymTensor(K0_ * sV + sUU * u.x() * u.x(), K0_ * sV + sUU * u.y() * u.y(), K0_ * sV,
                                           sUU * u.x() * u.y());
                    if (p.carries(FieldGroup::polar)) {  // no couple stress, sigma21 = sigma12 (eq. 3.3.4)
                        p.polar.sigma21[q] = p.sigma[q][XY];
                        p.polar.mu[q].setZero();
                        p.polar.omega[q] = 0.0;
                    }
                } else {
                    SymTensor& s = p.sigma[q];
                    s << K0_ * sV + sUU * u.x() * u.x(), K0_ * sV + sUU * u.y() * u.y(), K0_ * sV + sUU * u.z() * u.z(),
                        sUU * u.x() * u.y(), sUU * u.y() * u.z(), sUU * u.x() * u.z();
                }
                p.v[q].setZero();
            }
        });
    ++layers_;
    until().start(solver, t, step);
    info() << "Stage " << name() << ": layer " << layers_ << ", " << static_cast<long>(count) << " particles up to "
           << (D == 2 && u.x() == 0.0 ? "x2" : D == 3 && u.x() == 0.0 && u.y() == 0.0 ? "x3" : "height") << " = " << surface << " m, t = " << t << " s\n";
    return true;
}

template <int D>
StageEvent GeostaticFillStage<D>::started(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step)
{
    if (!addLayer(solver, pool, t, step)) return end("nothing left to fill");
    return StageEvent::particlesChanged;
}

template <int D>
StageEvent GeostaticFillStage<D>::afterStep(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step, double dt)
{
    std::string why;
    bool timedOut = false;
    if (!until().reached(solver, t, step, dt, why, timedOut)) return StageEvent::none;
    if (timedOut) warning(fileName(), line(), "stage " + name() + ", layer " + std::to_string(layers_) + ": " + why);
    if (addLayer(solver, pool, t, step)) return StageEvent::particlesChanged;
    return end(why, timedOut);
}

template <int D>
std::string GeostaticFillStage<D>::summary() const
{
    return " after " + std::to_string(layers_) + (layers_ == 1 ? " layer" : " layers");
}

template <int D>
void GeostaticFillStage<D>::writeOwnProgress(std::ostream& os) const
{
    os << "    band " << band_ << ";\n    layers " << layers_ << ";\n";
}

template <int D>
void GeostaticFillStage<D>::readOwnProgress(const Dictionary& progress)
{
    band_ = progress.get<long>("band");
    layers_ = progress.get<long>("layers");
}

template class GeostaticFillStage<2>;
#if GPIC_WITH_3D
template class GeostaticFillStage<3>;
#endif

} // namespace gpic
