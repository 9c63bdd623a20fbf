#include "functionObjects/ToolRegionFill.H"

#if GPIC_WITH_3D
#include "bodies/RigidPose.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "engine/MpmSolver.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(FunctionObject<3>, ToolRegionFill, "toolFill")

ToolRegionFill::ToolRegionFill(const Dictionary& dict, const RunContext& context)
    : FunctionObject<3>(dict, context),
      bodyName_(dict.getWord("body", context.bodyNames)),
      region_(Shape<3>::New(dict.subDict("region"))),
      givenFactor_(readFactor(dict)),
      file_(dict.fileName()),
      line_(dict.lineOf("body"))
{
    body_ = static_cast<int>(std::find(context.bodyNames.begin(), context.bodyNames.end(), bodyName_) -
                             context.bodyNames.begin());
    counted_ = bodyIds(dict, "bodies");
    reference0_ = region_->bounds().first;
}

void ToolRegionFill::start(const MpmSolver<3>& solver, double time)
{
    if (!solver.rigidBody(body_))
        throw InputError(file_, line_, "toolFill " + name() + ": '" + bodyName_ +
                                           "' is not a rigid body (constant/rigidBodies)");
    factor_ = givenFactor_ ? *givenFactor_ : 1.0;
    if (solver.writesFiles()) {  // a parallel run: rank 0
        std::ofstream& os = file("fill.dat");
        os << "# mass inside the region fixed to '" << bodyName_ << "' [kg times factor " << factor_
           << "], its displacement [m], the path length it has travelled [m] and its rotation [deg]\n"
              "# time mass dx dy dz travel rotation\n";
    }
    if (!restarted()) write(solver, time);
}

void ToolRegionFill::write(const MpmSolver<3>& solver, double time)
{
    const Particles<3>& p = solver.particles();
    const RigidPose pose = RigidPose::of(p, body_, solver.ranks());
    double mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const bool counted = counted_.empty() ? solver.rigidBody(p.body[q]) == nullptr
                                              : std::find(counted_.begin(), counted_.end(), p.body[q]) != counted_.end();
        if (counted && region_->inside(pose.unplace(p.x[q]))) mass += p.m[q];
    }
    std::vector<double> sum{mass};  // a parallel run: every rank's particles
    solver.sumOverRanks(sum);
    mass = sum[0];
    const Vector reference = pose.place(reference0_);
    if (last_) travel_ += (reference - *last_).norm();
    last_ = reference;
    const Vector d = reference - reference0_;
    // The angle of the turn R: cos = (trace R - 1) / 2, clamped against round-off.
    const double cosine = std::clamp(0.5 * (pose.R.trace() - 1.0), -1.0, 1.0);
    if (!solver.writesFiles()) return;
    std::ofstream& os = file("fill.dat");
    os << time << ' ' << factor_ * mass << ' ' << d.x() << ' ' << d.y() << ' ' << d.z() << ' ' << travel_ << ' '
       << std::acos(cosine) * 180.0 / M_PI << std::endl;
}

void ToolRegionFill::writeState(std::ostream& os) const
{
    os << "    travel " << exactNumber(travel_) << ";\n";
    if (last_)
        os << "    last (" << exactNumber(last_->x()) << ' ' << exactNumber(last_->y()) << ' ' << exactNumber(last_->z())
           << ");\n";
}

void ToolRegionFill::readState(const Dictionary& state)
{
    travel_ = state.get<double>("travel");
    if (state.found("last")) last_ = state.get<Vector>("last");
}

} // namespace gpic
#endif
