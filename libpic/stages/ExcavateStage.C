#include "stages/ExcavateStage.H"

#include "core/error.H"
#include "core/Info.H"
#include "dictionary/Dictionary.H"
#include "engine/MpmSolver.H"
#include "stages/ParticlePool.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>

namespace gpic {

GPIC_REGISTER_DIMS(Stage, ExcavateStage, "excavate")

template <int D>
ExcavateStage<D>::ExcavateStage(const Dictionary& dict, const StageSetup<D>& setup) : Stage<D>(dict, setup, 0.8)
{
    if (until().kind() != EndCondition<D>::Kind::equilibrium)
        dict.fail("until", "excavate brings the soil to equilibrium after each layer: until { equilibrium 1e-6; } "
                           "(optionally maxTime, minSteps), not " + until().kindName());
    const std::string name = dict.get<std::string>("body");
    body_ = bodyId(dict, "body", name);
    if (!isActive(body_)) dict.fail("body", "body '" + name + "' is dug but not among the stage's bodies (" + bodyList() + ")");
    if (dict.found("region") == dict.found("regions"))
        dict.fail("region", "excavate needs exactly one of region { type rectangle; min (..); max (..); } and "
                            "regions { a { ... } b { ... } } in dictionary " + dict.name());
    if (dict.found("region")) regions_.push_back(Shape<D>::New(dict.subDict("region")));
    else {
        const Dictionary& all = dict.subDict("regions");
        for (const auto& key : all.keys()) {
            if (!all.isDict(key)) all.fail(key, "'" + key + "' needs a shape sub-dictionary { type rectangle; ... }");
            regions_.push_back(Shape<D>::New(all.subDict(key)));
        }
        if (regions_.empty()) all.fail("", "regions holds no shape");
    }
    thickness_ = dict.found("layerThickness")
                     ? dict.getChecked<double>("layerThickness", [](const double& v) { return v > 0; }, "layerThickness > 0")
                     : setup.cellHeight;
}

template <int D>
bool ExcavateStage<D>::inRegion(const Particles<D>& p, std::size_t q) const
{
    if (p.body[q] != body_) return false;
    for (const auto& r : regions_)
        if (r->inside(p.x[q])) return true;
    return false;
}

template <int D>
bool ExcavateStage<D>::digLayer(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step)
{
    const Particles<D>& p = solver.particles();
    double highest = -std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < p.size(); ++q)
        if (inRegion(p, q)) highest = std::max(highest, p.x[q][D - 1]);
    highest = solver.ranks().largest(highest);  // a parallel run: every rank's particles
    if (highest == -std::numeric_limits<double>::infinity()) return false;
    // The band of the highest particle left: bands of layerThickness down from the top.
    band_ = std::max(band_ + 1, static_cast<long>(std::floor((top_ - highest) / thickness_ + 1e-9)));
    const double bottom = top_ - (band_ + 1) * thickness_;
    std::size_t count = 0;
    std::vector<double> dug{pool.remove(
        solver, [&](const Particles<D>& s, std::size_t q) { return inRegion(s, q) && s.x[q][D - 1] >= bottom; }, &count)};
    dug.push_back(static_cast<double>(count));
    solver.sumOverRanks(dug);
    const double mass = dug[0];
    count = static_cast<std::size_t>(dug[1]);
    removed_ += mass;
    ++layers_;
    until().start(solver, t, step);
    info() << "Stage " << name() << ": layer " << layers_ << " dug, " << count << " particles (" << mass
           << (D == 2 ? " kg/m) above x2 = " : " kg) above x3 = ") << bottom << " m, t = " << t << " s\n";
    return true;
}

template <int D>
StageEvent ExcavateStage<D>::started(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step)
{
    const Particles<D>& p = solver.particles();
    top_ = -std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < p.size(); ++q)
        if (inRegion(p, q)) top_ = std::max(top_, p.x[q][D - 1] + p.halfSize[q][D - 1]);
    top_ = solver.ranks().largest(top_);
    if (top_ == -std::numeric_limits<double>::infinity()) return end("nothing to dig in the region");
    if (!digLayer(solver, pool, t, step)) return end("nothing to dig in the region");
    return StageEvent::particlesChanged;
}

template <int D>
StageEvent ExcavateStage<D>::afterStep(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step, double dt)
{
    std::string why;
    bool timedOut = false;
    if (!until().reached(solver, t, step, dt, why, timedOut)) return StageEvent::none;
    if (timedOut) warning(fileName(), line(), "stage " + name() + ", layer " + std::to_string(layers_) + ": " + why);
    if (digLayer(solver, pool, t, step)) return StageEvent::particlesChanged;
    return end(why, timedOut);
}

template <int D>
std::string ExcavateStage<D>::summary() const
{
    char mass[32];
    std::snprintf(mass, sizeof mass, "%.4g", removed_);
    return " after " + std::to_string(layers_) + (layers_ == 1 ? " layer" : " layers") + " (" + mass + (D == 2 ? " kg/m dug)" : " kg dug)");
}

template <int D>
void ExcavateStage<D>::writeOwnProgress(std::ostream& os) const
{
    char buf[96];
    std::snprintf(buf, sizeof buf, "    top %.17g;\n    removed %.17g;\n", top_, removed_);
    os << buf << "    band " << band_ << ";\n    layers " << layers_ << ";\n";
}

template <int D>
void ExcavateStage<D>::readOwnProgress(const Dictionary& progress)
{
    top_ = progress.get<double>("top");
    removed_ = progress.get<double>("removed");
    band_ = progress.get<long>("band");
    layers_ = progress.get<long>("layers");
}

template class ExcavateStage<2>;
#if GPIC_WITH_3D
template class ExcavateStage<3>;
#endif


} // namespace gpic
