#include "functionObjects/MassFlow.H"

#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "bodies/Shape.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER_DIMS(FunctionObject, MassFlow, "massFlow")

template <int D>
MassFlow<D>::MassFlow(const Dictionary& dict, const RunContext& context)
    : FunctionObject<D>(dict, context),
      givenFactor_(readFactor(dict))
{
    if (const Dictionary* region = dict.subDictPtr("region"); region && region->found("type")) {
        shape_ = Shape<D>::New(*region);  // any shape of constant/bodies: a cylinder, a sphere, an STL
    } else if (region) {
        const Vector lo = region->get<Vector>("min"), hi = region->get<Vector>("max");
        if (!(hi.array() > lo.array()).all())
            region->fail("max", "keyword 'max' in dictionary " + region->name() + ": the region needs max > min in " +
                                    (D == 2 ? "x1 and x2" : "x1, x2 and x3"));
        region_ = std::make_pair(lo, hi);
    }
    bodies_ = bodyIds(dict, "bodies");
}

template <int D> bool MassFlow<D>::insideRegion(const Vector& x) const
{
    if (shape_) return shape_->inside(x);
    return !((x.array() < region_->first.array()).any() || (x.array() > region_->second.array()).any());
}

template <int D>
double MassFlow<D>::massInRegion(const MpmSolver<D>& solver) const
{
    const Particles<D>& p = solver.particles();
    double mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const bool counted = bodies_.empty() ? solver.rigidBody(p.body[q]) == nullptr
                                             : std::find(bodies_.begin(), bodies_.end(), p.body[q]) != bodies_.end();
        if (!counted) continue;
        if ((region_ || shape_) && !insideRegion(p.x[q])) continue;
        mass += p.m[q];
    }
    return mass;
}

template <int D> std::pair<double, double> MassFlow<D>::totals(const MpmSolver<D>& solver) const
{
    // A parallel run: every rank's particles and outflow (MpmSolver::sumOverRanks).
    std::vector<double> sums{massInRegion(solver), solver.removedMass()};
    solver.sumOverRanks(sums);
    return {factor_ * sums[0], factor_ * sums[1]};
}

template <int D>
void MassFlow<D>::start(const MpmSolver<D>& solver, double time)
{
    factor_ = rowFactor(givenFactor_, solver.grid());
    const auto [mass, removed] = totals(solver);
    if (!solver.writesFiles()) {
        if (!restarted()) lastTime_ = time, lastRemoved_ = removed, lastMass_ = mass;
        return;
    }
    std::ofstream& os = file("massFlow.dat");
    os << "# mass in the region [kg], mass gone through the outlets [kg], outflow rate [kg/s], "
          "drain rate of the region [kg/s]; masses per "
       << (D == 3 ? "the scene" : solver.grid().axisymmetric() ? "radian" : "metre of thickness") << " times factor " << factor_
       << "\n# time mass out outflowRate drainRate\n";
    if (restarted()) return;  // the rates go on from the restored last row
    lastTime_ = time;
    lastRemoved_ = removed;
    lastMass_ = mass;
    os << time << ' ' << lastMass_ << ' ' << lastRemoved_ << " 0 0" << std::endl;  // readable while the run goes on
}

template <int D>
void MassFlow<D>::writeState(std::ostream& os) const
{
    os << "    lastTime    " << exactNumber(lastTime_) << ";\n    lastRemoved " << exactNumber(lastRemoved_)
       << ";\n    lastMass    " << exactNumber(lastMass_) << ";\n";
}

template <int D>
void MassFlow<D>::readState(const Dictionary& state)
{
    lastTime_ = state.get<double>("lastTime");
    lastRemoved_ = state.get<double>("lastRemoved");
    lastMass_ = state.get<double>("lastMass");
}

template <int D>
void MassFlow<D>::write(const MpmSolver<D>& solver, double time)
{
    const auto [mass, removed] = totals(solver);
    const double dt = time - lastTime_;
    const double outflow = dt > 0 ? (removed - lastRemoved_) / dt : 0.0;
    const double drain = dt > 0 ? (lastMass_ - mass) / dt : 0.0;
    if (solver.writesFiles()) file("massFlow.dat") << time << ' ' << mass << ' ' << removed << ' ' << outflow << ' ' << drain << '\n';
    lastTime_ = time;
    lastRemoved_ = removed;
    lastMass_ = mass;
}

template class MassFlow<2>;
#if GPIC_WITH_3D
template class MassFlow<3>;
#endif

} // namespace gpic
