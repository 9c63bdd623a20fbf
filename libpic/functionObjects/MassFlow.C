#include "functionObjects/MassFlow.H"

#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER(FunctionObject, MassFlow, "massFlow")

MassFlow::MassFlow(const Dictionary& dict, const RunContext& context)
    : FunctionObject(dict, context),
      givenFactor_(readFactor(dict))
{
    if (const Dictionary* region = dict.subDictPtr("region")) {
        const Vector2 lo = region->get<Vector2>("min"), hi = region->get<Vector2>("max");
        if (!(hi.x() > lo.x() && hi.y() > lo.y()))
            region->fail("max", "keyword 'max' in dictionary " + region->name() +
                                    ": the region needs max > min in x1 and x2");
        region_ = std::make_pair(lo, hi);
    }
    bodies_ = bodyIds(dict, "bodies");
}

double MassFlow::massInRegion(const MpmSolver<2>& solver) const
{
    const Particles<2>& p = solver.particles();
    double mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const bool counted = bodies_.empty() ? solver.rigidBody(p.body[q]) == nullptr
                                             : std::find(bodies_.begin(), bodies_.end(), p.body[q]) != bodies_.end();
        if (!counted) continue;
        if (region_ && (p.x[q].x() < region_->first.x() || p.x[q].y() < region_->first.y() ||
                        p.x[q].x() > region_->second.x() || p.x[q].y() > region_->second.y()))
            continue;
        mass += p.m[q];
    }
    return factor_ * mass;
}

void MassFlow::start(const MpmSolver<2>& solver, double time)
{
    factor_ = rowFactor(givenFactor_, solver.grid());
    std::ofstream& os = file("massFlow.dat");
    os << "# mass in the region [kg], mass gone through the outlets [kg], outflow rate [kg/s], "
          "drain rate of the region [kg/s]; masses per "
       << (solver.grid().axisymmetric() ? "radian" : "metre of thickness") << " times factor " << factor_
       << "\n# time mass out outflowRate drainRate\n";
    if (restarted()) return;  // the rates go on from the restored last row
    lastTime_ = time;
    lastRemoved_ = factor_ * solver.removedMass();
    lastMass_ = massInRegion(solver);
    os << time << ' ' << lastMass_ << ' ' << lastRemoved_ << " 0 0" << std::endl;  // readable while the run goes on
}

void MassFlow::writeState(std::ostream& os) const
{
    os << "    lastTime    " << exactNumber(lastTime_) << ";\n    lastRemoved " << exactNumber(lastRemoved_)
       << ";\n    lastMass    " << exactNumber(lastMass_) << ";\n";
}

void MassFlow::readState(const Dictionary& state)
{
    lastTime_ = state.get<double>("lastTime");
    lastRemoved_ = state.get<double>("lastRemoved");
    lastMass_ = state.get<double>("lastMass");
}

void MassFlow::write(const MpmSolver<2>& solver, double time)
{
    const double mass = massInRegion(solver), removed = factor_ * solver.removedMass();
    const double dt = time - lastTime_;
    const double outflow = dt > 0 ? (removed - lastRemoved_) / dt : 0.0;
    const double drain = dt > 0 ? (lastMass_ - mass) / dt : 0.0;
    file("massFlow.dat") << time << ' ' << mass << ' ' << removed << ' ' << outflow << ' ' << drain << '\n';
    lastTime_ = time;
    lastRemoved_ = removed;
    lastMass_ = mass;
}

} // namespace gpic
