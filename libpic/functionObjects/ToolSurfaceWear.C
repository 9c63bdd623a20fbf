#include "functionObjects/ToolSurfaceWear.H"

#if GPIC_WITH_3D
#include "bodies/RigidPose.H"
#include "functionObjects/ArchardWear.H"
#include "contact/ContactPass.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "engine/MpmSolver.H"
#include "grid/Grid.H"
#include "io/SurfaceVtk.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(FunctionObject<3>, ToolSurfaceWear, "toolWear")

ToolSurfaceWear::ToolSurfaceWear(const Dictionary& dict, const RunContext& context)
    : FunctionObject<3>(dict, context),
      bodyName_(dict.getWord("body", context.bodyNames)),
      wearPerWork_(archardWearPerWork(dict)),
      file_(dict.fileName()),
      line_(dict.lineOf("body"))
{
    body_ = static_cast<int>(std::find(context.bodyNames.begin(), context.bodyNames.end(), bodyName_) -
                             context.bodyNames.begin());
    for (const char* plane : {"faces", "resolution"})
        if (dict.found(plane))
            dict.fail(plane, "toolWear " + name() + ": '" + plane + "' belongs to a plane scene; in 3D the tool's " +
                                 "triangles are where the wear is kept (draw the tool finer to see it finer)");
}

void ToolSurfaceWear::start(const MpmSolver<3>& solver, double time)
{
    const std::string what = "toolWear " + name() + ": ";
    checkWornTool(solver, body_, bodyName_, what, file_, line_);
    std::vector<bool> tool(context().bodyNames.size());
    tool[static_cast<std::size_t>(body_)] = true;
    tools_ = std::make_shared<const ToolSurfaces<3>>(context().caseDir, context().bodyNames, tool);
    if (tools_->tools().empty())
        throw InputError(file_, line_, what + "in a 3D case the worn tool is drawn as a surface: give '" + bodyName_ +
                                           "' shape { type triSurface; file \"triSurface/....stl\"; } in constant/bodies");
    surface_ = &tools_->tools().front().surface;
    if (!restarted() || volume_.size() != surface_->facets().size()) volume_.assign(surface_->facets().size(), 0.0);

    if (solver.writesFiles()) {  // a parallel run: rank 0
        std::ofstream& os = file("wear.dat");
        os << "# Archard wear of '" << bodyName_ << "', k/H " << wearPerWork_
           << " 1/Pa: the largest depth [m] and the worn volume [m^3], whole and per part\n# time maxDepth volume";
        if (surface_->partNames().size() > 1)
            for (const auto& part : surface_->partNames()) os << ' ' << part << ":maxDepth " << part << ":volume";
        os << std::endl;
    }
    if (!restarted()) write(solver, time);
}

void ToolSurfaceWear::at(StepPoint, const MpmSolver<3>& solver)
{
    using Vector = Space<3>::Vector;
    const Grid<3>& grid = solver.grid();
    const ContactPass<3>* contact = solver.contact();
    if (grid.fContact.empty() || !contact) return;
    const RigidBodyDriver<3>* tool = solver.rigidBody(body_);
    const double dt = solver.deltaT(), tNew = solver.time() + dt;
    const double h = grid.cellSize().minCoeff(), reach = 2.0 * grid.cellSize().maxCoeff();
    const BodyField<3>& toolField = contact->field(body_);
    const RigidPose pose = RigidPose::of(solver.particles(), body_, solver.ranks());
    // A parallel run: the step's wear from the nodes each rank owns, added over the ranks, so
    // that every rank holds the whole (and writes it in its state for a restart).
    const bool parallel = solver.ranks().parallel();
    std::vector<double> added(parallel ? volume_.size() : 0, 0.0);
    std::vector<double>& wear = parallel ? added : volume_;
    for (int n : grid.active) {
        const Vector& F = grid.fContact[static_cast<std::size_t>(n)];
        if (F.isZero(0.0) || !(toolField.mass[n] > 0.0) || !solver.countsNode(n)) continue;
        const Vector x = grid.nodePosition(n), X = pose.unplace(x), push = pose.unturn(F);
        double distance = 0;  // to the nearest facet
        const int facet = surface_->facetPushedBy(X, push, 0.5 * h, reach, &distance);
        if (facet < 0) continue;
        const Vector normal = surface_->facetNormal(facet);  // in the tool's frame
        const double Fn = -push.dot(normal);  // the material presses the tool inwards
        if (!(Fn > 0.0)) continue;
        Vector material;
        if (!materialVelocity(solver, *contact, n, material)) continue;
        const Vector relative = pose.unturn(material - tool->velocity(tNew, x));
        const double slip = (relative - relative.dot(normal) * normal).norm();
        const double worn = wearPerWork_ * Fn * slip * dt;
        if (!(worn > 0.0)) continue;
        // Shared by area over the facets of the node's face within half a cell of it.
        std::vector<std::pair<int, double>> patch;
        double area = 0;
        for (const auto& near : surface_->facetsNear(X, distance + 0.5 * h))
            if (surface_->facetNormal(near.facet).dot(normal) > 0.9) {
                patch.emplace_back(near.facet, surface_->facetArea(near.facet));
                area += patch.back().second;
            }
        if (!(area > 0.0)) {
            wear[static_cast<std::size_t>(facet)] += worn;
            continue;
        }
        for (const auto& [f, a] : patch) wear[static_cast<std::size_t>(f)] += worn * a / area;
    }
    if (!parallel) return;
    solver.sumOverRanks(added);
    for (std::size_t f = 0; f < volume_.size(); ++f) volume_[f] += added[f];
}

void ToolSurfaceWear::write(const MpmSolver<3>& solver, double time)
{
    const std::size_t parts = surface_->partNames().size();
    std::vector<double> volume(parts, 0.0), deepest(parts, 0.0);
    std::vector<double> depth(volume_.size());
    double total = 0, maxDepth = 0;
    for (std::size_t f = 0; f < volume_.size(); ++f) {
        const int facet = static_cast<int>(f);
        depth[f] = volume_[f] / surface_->facetArea(facet);
        const auto part = static_cast<std::size_t>(surface_->partOf(facet));
        volume[part] += volume_[f];
        deepest[part] = std::max(deepest[part], depth[f]);
        total += volume_[f];
        maxDepth = std::max(maxDepth, depth[f]);
    }
    const RigidPose pose = RigidPose::of(solver.particles(), body_, solver.ranks());
    if (!solver.writesFiles()) return;  // a parallel run: rank 0 (every rank holds the whole)
    std::ofstream& os = file("wear.dat");
    os << time << ' ' << maxDepth << ' ' << total;
    if (parts > 1)
        for (std::size_t k = 0; k < parts; ++k) os << ' ' << deepest[k] << ' ' << volume[k];
    os << std::endl;
    std::vector<Space<3>::Vector> corners;
    corners.reserve(surface_->corners().size());
    for (const auto& c : surface_->corners()) corners.push_back(pose.place(c));
    writeSurface((directory() / (bodyName_ + "Wear.vtp")).string(), corners, surface_->facets(), time,
                 {{"wearDepth", depth}});
}

void ToolSurfaceWear::writeState(std::ostream& os) const
{
    os << "    volume (";
    for (double v : volume_) os << ' ' << exactNumber(v);
    os << " );\n";
}

void ToolSurfaceWear::readState(const Dictionary& state) { volume_ = state.get<std::vector<double>>("volume"); }

} // namespace gpic
#endif
