#include "functionObjects/ToolFill.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(FunctionObject<2>, ToolFill, "toolFill")

ToolFill::ToolFill(const Dictionary& dict, const RunContext& context)
    : FunctionObject<2>(dict, context),
      bodyName_(dict.getWord("body", context.bodyNames)),
      region_(Shape<2>::New(dict.subDict("region"))),
      givenFactor_(readFactor(dict)),
      file_(dict.fileName()),
      line_(dict.lineOf("body"))
{
    body_ = static_cast<int>(std::find(context.bodyNames.begin(), context.bodyNames.end(), bodyName_) -
                             context.bodyNames.begin());
    counted_ = bodyIds(dict, "bodies");
    // The region's lower-left corner: a point of the body to follow it by.
    reference0_ = reference_ = region_->bounds().first;
    handle_ = reference_ + Vector2::UnitX();
}

void ToolFill::start(const MpmSolver<2>& solver, double time)
{
    if (!solver.rigidBody(body_))
        throw InputError(file_, line_, "toolFill " + name() + ": '" + bodyName_ +
                                           "' is not a rigid body (constant/rigidBodies)");
    factor_ = rowFactor(givenFactor_, solver.grid());
    if (solver.writesFiles()) {  // a parallel run: rank 0
        std::ofstream& os = file("fill.dat");
        os << "# mass inside the region fixed to '" << bodyName_ << "' [kg per "
           << (solver.grid().axisymmetric() ? "radian" : "metre") << " times factor " << factor_
           << "], its displacement [m], the path length it has travelled [m] and its rotation [deg]\n"
              "# time mass dx dy travel rotation\n";
    }
    if (!restarted()) write(solver, time);
}

Vector2 ToolFill::atStart(const Vector2& x, double c, double s) const
{
    const Vector2 r = x - reference_;
    return reference0_ + Vector2(c * r.x() + s * r.y(), -s * r.x() + c * r.y());
}

void ToolFill::at(StepPoint, const MpmSolver<2>& solver)
{
    const RigidBodyDriver<2>* tool = solver.rigidBody(body_);
    const Vector2 before = reference_;
    reference_ = tool->move(solver.time(), solver.deltaT(), reference_);
    handle_ = tool->move(solver.time(), solver.deltaT(), handle_);
    travel_ += (reference_ - before).norm();
}

void ToolFill::write(const MpmSolver<2>& solver, double time)
{
    const Particles<2>& p = solver.particles();
    const Vector2 e = handle_ - reference_;
    const double c = e.x() / e.norm(), s = e.y() / e.norm();  // the turn since the start
    double mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const bool counted = counted_.empty() ? solver.rigidBody(p.body[q]) == nullptr
                                              : std::find(counted_.begin(), counted_.end(), p.body[q]) != counted_.end();
        if (counted && region_->inside(atStart(p.x[q], c, s))) mass += p.m[q];
    }
    std::vector<double> sum{mass};  // a parallel run: every rank's particles
    solver.sumOverRanks(sum);
    mass = sum[0];
    if (!solver.writesFiles()) return;
    const Vector2 d = reference_ - reference0_;
    std::ofstream& os = file("fill.dat");
    os << time << ' ' << factor_ * mass << ' ' << d.x() << ' ' << d.y() << ' ' << travel_ << ' '
       << std::atan2(e.y(), e.x()) * 180.0 / M_PI << std::endl;
}

void ToolFill::writeState(std::ostream& os) const
{
    const auto vec = [](const Vector2& v) { return "(" + exactNumber(v.x()) + ' ' + exactNumber(v.y()) + ")"; };
    os << "    reference " << vec(reference_) << ";\n    handle " << vec(handle_) << ";\n    travel "
       << exactNumber(travel_) << ";\n";
}

void ToolFill::readState(const Dictionary& state)
{
    reference_ = state.get<Vector2>("reference");
    handle_ = state.get<Vector2>("handle");
    travel_ = state.get<double>("travel");
}

} // namespace gpic
