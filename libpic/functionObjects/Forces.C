#include "functionObjects/Forces.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "engine/MpmSolver.H"
#include "grid/FaceBand.H"
#include "grid/Grid.H"
#include "bodies/RigidPose.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER_DIMS(FunctionObject, Forces, "forces")

template <int D>
Forces<D>::Forces(const Dictionary& dict, const RunContext& context)
    : FunctionObject<D>(dict, context),
      names_(dict.getOrDefault<std::vector<std::string>>("bodies", {})),
      CofR_(dict.getOrDefault<Vector>("CofR", Vector::Zero())),
      file_(dict.fileName()),
      line_(dict.lineOf(dict.found("bodies") ? "bodies" : "type"))
{
    for (const auto& n : names_)
        if (std::find(context.bodyNames.begin(), context.bodyNames.end(), n) == context.bodyNames.end())
            dict.fail("bodies", "forces " + name() + ": '" + n + "' is not a body; valid choices: " +
                                    choiceList(context.bodyNames));
    if (D == 3 && dict.found("faces"))
        dict.fail("faces", "forces " + name() + ": faces are straight segments of a plane scene; a 3D case "
                           "reports the force and moment of each whole body");
    if (const Dictionary* faces = dict.subDictPtr("faces")) {
        for (const auto& key : faces->keys()) {
            const Dictionary& f = faces->subDict(key);
            Face face{key, f.getWord("body", context.bodyNames), -1, f.get<Vector>("from"), f.get<Vector>("to")};
            if (!((face.to - face.from).norm() > 0.0))
                f.fail("to", "forces " + name() + ": face '" + key + "' has no length (from = to)");
            faces_.push_back(face);
        }
    }
}

template <int D>
void Forces<D>::start(const MpmSolver<D>& solver, double)
{
    const auto& all = context().bodyNames;
    std::vector<std::string> rigid;
    for (std::size_t b = 0; b < all.size(); ++b)
        if (solver.rigidBody(static_cast<int>(b))) rigid.push_back(all[b]);
    if (rigid.empty())
        throw InputError(file_, line_, "forces " + name() + ": the case has no rigid body (constant/rigidBodies)");
    bodies_.clear();
    for (const auto& n : names_.empty() ? rigid : names_) {
        if (std::find(rigid.begin(), rigid.end(), n) == rigid.end())
            throw InputError(file_, line_, "forces " + name() + ": '" + n +
                                               "' is not a rigid body (constant/rigidBodies); valid choices: " +
                                               choiceList(rigid));
        bodies_.push_back(static_cast<int>(std::find(all.begin(), all.end(), n) - all.begin()));
    }
    parts_.clear();
    if constexpr (D == 3) {
        std::vector<bool> isRigid(all.size());
        for (int b : bodies_) isRigid[static_cast<std::size_t>(b)] = true;
        tools_ = std::make_shared<const ToolSurfaces<D>>(context().caseDir, all, isRigid);
        for (const auto& tool : tools_->tools())
            if (tool.surface.partNames().size() > 1)
                for (std::size_t k = 0; k < tool.surface.partNames().size(); ++k)
                    parts_.push_back({tool.body, tool.name + "." + tool.surface.partNames()[k], &tool.surface,
                                      static_cast<int>(k)});
    }
    if (!restarted() || work_.size() != bodies_.size()) work_.assign(bodies_.size(), 0.0);
    for (auto& face : faces_) {
        if (std::find(rigid.begin(), rigid.end(), face.bodyName) == rigid.end())
            throw InputError(file_, line_, "forces " + name() + ": face '" + face.name + "': '" + face.bodyName +
                                               "' is not a rigid body; valid choices: " + choiceList(rigid));
        face.body = static_cast<int>(std::find(all.begin(), all.end(), face.bodyName) - all.begin());
    }
    axisymmetric_ = solver.grid().axisymmetric();
    if (!solver.writesFiles()) return;  // a parallel run: rank 0 writes
    std::ofstream& os = file("forces.dat");
    if constexpr (D == 2) {
        os << "# force of the material on each body [N/m], its moment about CofR (" << CofR_.x() << ' '
           << CofR_.y() << ") [N m/m] and the body's mean displacement [m]; forces on faces [N/m]; the work "
              "each body has done on the material [J/m]"
           << (solver.grid().axisymmetric() ? "; all per radian, then the axial force of the revolution [N]" : "")
           << "\n# time";
        for (int b : bodies_)
            for (const char* c : {"Fx", "Fy", "Mz", "dx", "dy"}) os << ' ' << all[b] << ':' << c;
    } else {
        os << "# force of the material on each body [N], its moment about CofR (" << CofR_.transpose()
           << ") [N m] and the body's mean displacement [m]; the work each body has done on the material [J]"
           << "\n# time";
        for (int b : bodies_)
            for (const char* c : {"Fx", "Fy", "Fz", "Mx", "My", "Mz", "dx", "dy", "dz"}) os << ' ' << all[b] << ':' << c;
    }
    for (const auto& face : faces_) os << ' ' << face.name << ":Fx " << face.name << ":Fy";
    for (const auto& part : parts_)
        for (const char* c : {"Fx", "Fy", "Fz"}) os << ' ' << part.name << ':' << c;
    for (int b : bodies_) os << ' ' << all[b] << ":W";
    if (axisymmetric_)
        for (int b : bodies_) os << ' ' << all[b] << ":Faxial";
    os << std::endl;
}

template <int D>
void Forces<D>::write(const MpmSolver<D>& solver, double time)
{
    const Particles<D>& p = solver.particles();
    const std::size_t nBodies = context().bodyNames.size();
    std::vector<double> mass(nBodies, 0.0);
    std::vector<Vector> moved(nBodies, Vector::Zero());
    for (std::size_t q = 0; q < p.size(); ++q) {
        const auto b = static_cast<std::size_t>(p.body[q]);
        if (b >= nBodies) continue;
        mass[b] += p.m[q];
        moved[b] += p.m[q] * (p.x[q] - p.x0[q]);
    }
    // A parallel run: the sums over every rank's particles and over the nodes each owns, on
    // every rank; rank 0 writes.
    sumOverRanks(solver, moved, &mass);
    std::vector<Vector> faceForces = faceSums(solver, mass, moved);
    sumOverRanks(solver, faceForces);
    std::vector<Vector> partForces = partSums(solver);
    sumOverRanks(solver, partForces);
    if (!solver.writesFiles()) return;
    const auto& loads = solver.rigidBodyLoads();
    std::ofstream& os = file("forces.dat");
    os << time;
    for (int b : bodies_) {
        const auto k = static_cast<std::size_t>(b);
        const RigidBodyLoad<D> load = k < loads.size() ? loads[k] : RigidBodyLoad<D>{};
        const Vector d = mass[k] > 0.0 ? Vector(moved[k] / mass[k]) : Vector::Zero();
        if constexpr (D == 2)
            os << ' ' << load.force.x() << ' ' << load.force.y() << ' ' << load.momentAbout(CofR_) << ' '
               << d.x() << ' ' << d.y();
        else {
            const typename Space<D>::Moment M = load.momentAbout(CofR_);
            for (const Vector* v : std::initializer_list<const Vector*>{&load.force, &M, &d})
                for (int a = 0; a < D; ++a) os << ' ' << (*v)[a];
        }
    }
    for (const Vector& F : faceForces)
        for (int a = 0; a < D; ++a) os << ' ' << F[a];
    for (const Vector& F : partForces)
        for (int a = 0; a < D; ++a) os << ' ' << F[a];
    for (double w : work_) os << ' ' << w;
    if (axisymmetric_)
        for (int b : bodies_) {
            const auto k = static_cast<std::size_t>(b);
            os << ' ' << 2.0 * M_PI * (k < loads.size() ? loads[k].force.y() : 0.0);
        }
    os << std::endl;  // readable while the run goes on
}

template <int D>
void Forces<D>::sumOverRanks(const MpmSolver<D>& solver, std::vector<Vector>& vectors, std::vector<double>* scalars)
{
    std::vector<double> values = scalars ? *scalars : std::vector<double>{};
    for (const Vector& v : vectors) values.insert(values.end(), v.data(), v.data() + D);
    solver.sumOverRanks(values);
    std::size_t k = 0;
    if (scalars)
        for (double& x : *scalars) x = values[k++];
    for (Vector& v : vectors)
        for (int a = 0; a < D; ++a) v[a] = values[k++];
}

template <int D>
std::vector<typename Forces<D>::Vector> Forces<D>::faceSums(const MpmSolver<D>& solver, const std::vector<double>& mass,
                                                           const std::vector<Vector>& moved) const
{
    std::vector<Vector> F(faces_.size(), Vector::Zero());
    if constexpr (D == 2) {
        const Grid<D>& grid = solver.grid();
        for (std::size_t k = 0; k < faces_.size(); ++k) {
            const Face& face = faces_[k];
            const auto b = static_cast<std::size_t>(face.body);
            const Vector d = mass[b] > 0.0 ? Vector(moved[b] / mass[b]) : Vector::Zero();
            const FaceBand band(face.from + d, face.to + d, grid.cellSize().maxCoeff());
            if (!grid.fContact.empty())
                for (int n : grid.active)
                    if (solver.countsNode(n) && band.station(grid.nodePosition(n))) F[k] += grid.fContact[static_cast<std::size_t>(n)];
        }
    }
    return F;
}

template <int D>
std::vector<typename Forces<D>::Vector> Forces<D>::partSums(const MpmSolver<D>& solver) const
{
    std::vector<Vector> F(parts_.size(), Vector::Zero());
    if constexpr (D == 3) {
        const Grid<D>& grid = solver.grid();
        const double reach = 2.0 * grid.cellSize().maxCoeff();
        // Part after part of one body are neighbours in parts_: one pose and one pass over
        // the nodes per body.
        for (std::size_t first = 0; first < parts_.size();) {
            const Part& tool = parts_[first];
            std::size_t last = first;
            while (last < parts_.size() && parts_[last].body == tool.body) ++last;
            const RigidPose pose = RigidPose::of(solver.particles(), tool.body, solver.ranks());
            if (!grid.fContact.empty())
                for (int n : grid.active) {
                    const Vector& f = grid.fContact[static_cast<std::size_t>(n)];
                    if (f.isZero() || !solver.countsNode(n)) continue;
                    const int facet = tool.surface->facetPushedBy(pose.unplace(grid.nodePosition(n)), pose.unturn(f),
                                                                  0.5 * grid.cellSize().minCoeff(), reach);
                    if (facet < 0) continue;
                    F[first + static_cast<std::size_t>(tool.surface->partOf(facet))] += f;
                }
            first = last;
        }
    }
    return F;
}

template <int D>
void Forces<D>::at(StepPoint, const MpmSolver<D>& solver)
{
    const auto& loads = solver.rigidBodyLoads();
    const double dt = solver.deltaT(), tMid = solver.time() + 0.5 * dt;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const auto b = static_cast<std::size_t>(bodies_[k]);
        if (b < loads.size()) work_[k] += dt * powerOnMaterial(*solver.rigidBody(bodies_[k]), loads[b], tMid);
    }
}

template <int D>
void Forces<D>::writeState(std::ostream& os) const
{
    os << "    work (";
    for (double w : work_) os << ' ' << exactNumber(w);
    os << " );\n";
}

template <int D>
void Forces<D>::readState(const Dictionary& state) { work_ = state.getOrDefault<std::vector<double>>("work", {}); }

template class Forces<2>;
#if GPIC_WITH_3D
template class Forces<3>;
#endif

} // namespace gpic
