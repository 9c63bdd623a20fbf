#include "functionObjects/ToolWear.H"

#include "functionObjects/ArchardWear.H"

#include "contact/ContactPass.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "grid/FaceBand.H"
#include "grid/Grid.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(FunctionObject<2>, ToolWear, "toolWear")

namespace {
const auto positive = [](const double& v) { return v > 0; };
}

ToolWear::ToolWear(const Dictionary& dict, const RunContext& context)
    : FunctionObject<2>(dict, context),
      bodyName_(dict.getWord("body", context.bodyNames)),
      wearPerWork_(archardWearPerWork(dict)),
      resolution_(dict.found("resolution") ? dict.getChecked<double>("resolution", positive, "resolution > 0 (m)")
                                           : 0.0),
      file_(dict.fileName()),
      line_(dict.lineOf("body"))
{
    body_ = static_cast<int>(std::find(context.bodyNames.begin(), context.bodyNames.end(), bodyName_) -
                             context.bodyNames.begin());
    const Dictionary* faces = dict.subDictPtr("faces");
    if (!faces || faces->keys().empty())
        dict.fail("faces", "toolWear " + name() + ": give the worn faces, e.g. faces { front { from (x0 y0); to "
                                                  "(x1 y1); } } (material on the right of from -> to)");
    for (const auto& key : faces->keys()) {
        const Dictionary& f = faces->subDict(key);
        Face face{key, f.get<Vector2>("from"), f.get<Vector2>("to"), {}};
        if (!((face.to - face.from).norm() > 0.0))
            f.fail("to", "toolWear " + name() + ": face '" + key + "' has no length (from = to)");
        faces_.push_back(face);
    }
}

void ToolWear::spread(std::vector<double>& bins, double length, double s, double width, double amount)
{
    // Over the node's stretch of the face, [s - width/2, s + width/2] within [0, L], so that a
    // bin gets its share of each node whatever the bins' alignment with the node lines.
    const double from = std::max(0.0, s - 0.5 * width), to = std::min(length, s + 0.5 * width);
    const double binLength = length / static_cast<double>(bins.size());
    const auto binOf = [&](double x) {
        return std::min(bins.size() - 1, static_cast<std::size_t>(std::max(0.0, x / binLength)));
    };
    if (!(to > from)) {
        bins[binOf(s)] += amount;
        return;
    }
    for (std::size_t b = binOf(from); b <= binOf(to); ++b) {
        const double overlap = std::min(to, (b + 1) * binLength) - std::max(from, b * binLength);
        if (overlap > 0) bins[b] += amount * overlap / (to - from);
    }
}

void ToolWear::start(const MpmSolver<2>& solver, double time)
{
    checkWornTool(solver, body_, bodyName_, "toolWear " + name() + ": ", file_, line_);
    if (resolution_ == 0.0) resolution_ = solver.grid().cellSize().maxCoeff();
    axisymmetric_ = solver.grid().axisymmetric();
    for (auto& face : faces_) {
        const auto bins = static_cast<std::size_t>(std::max(1.0, std::ceil((face.to - face.from).norm() / resolution_ - 1e-9)));
        if (!restarted() || face.volume.size() != bins) face.volume.assign(bins, 0.0);
    }

    if (solver.writesFiles()) {  // a parallel run: rank 0
        std::ofstream& os = file("wear.dat");
        os << "# Archard wear of '" << bodyName_ << "', k/H " << wearPerWork_
           << " 1/Pa: per face the largest depth [m] and the worn volume [m^3/m]\n# time";
        for (const auto& face : faces_) os << ' ' << face.name << ":maxDepth " << face.name << ":volume";
        os << std::endl;
        std::ofstream& profile = file("wearProfile.dat");
        profile << "# wear depth along each face, at each row of wear.dat; face";
        for (std::size_t k = 0; k < faces_.size(); ++k) profile << ' ' << k << ' ' << faces_[k].name;
        profile << "; s from the face's start, bin centre (x y) [m]\n# time face s x y depth\n";
    }
    if (!restarted()) write(solver, time);
}

void ToolWear::at(StepPoint point, const MpmSolver<2>& solver)
{
    const RigidBodyDriver<2>* tool = solver.rigidBody(body_);
    const double dt = solver.deltaT();
    if (point == StepPoint::afterGridToParticles) {
        // The faces move as the tool's particles just did (MpmSolver::gridToParticles).
        for (auto& face : faces_) {
            face.from = tool->move(solver.time(), dt, face.from);
            face.to = tool->move(solver.time(), dt, face.to);
        }
        return;
    }
    const Grid<2>& grid = solver.grid();
    const ContactPass<2>* contact = solver.contact();
    if (grid.fContact.empty() || !contact) return;
    const double tNew = solver.time() + dt;
    const BodyField<2>& toolField = contact->field(body_);
    // A parallel run: the step's wear from the nodes each rank owns, added over the ranks, so
    // that every rank holds the whole (and writes it in its state for a restart).
    const bool parallel = solver.ranks().parallel();
    std::vector<std::vector<double>> added;
    if (parallel)
        for (const auto& face : faces_) added.emplace_back(face.volume.size(), 0.0);
    for (std::size_t k = 0; k < faces_.size(); ++k) {
        Face& face = faces_[k];
        std::vector<double>& wear = parallel ? added[k] : face.volume;
        const FaceBand band(face.from, face.to, grid.cellSize().maxCoeff());
        // A node's stretch of the face: the node spacing along it.
        const double width = std::abs(band.tangent().x()) * grid.cellSize().x() +
                             std::abs(band.tangent().y()) * grid.cellSize().y();
        for (int n : grid.active) {
            const Vector2& F = grid.fContact[static_cast<std::size_t>(n)];
            if (F.isZero(0.0) || !(toolField.mass[n] > 0.0) || !solver.countsNode(n)) continue;
            const Vector2 x = grid.nodePosition(n);
            const auto s = band.station(x);
            if (!s) continue;
            const double Fn = -F.dot(band.normal());  // the material presses the tool away from it
            if (!(Fn > 0.0)) continue;
            Vector2 material;
            if (!materialVelocity(solver, *contact, n, material)) continue;
            const double slip = std::abs((material - tool->velocity(tNew, x)).dot(band.tangent()));
            spread(wear, band.length(), *s, width, wearPerWork_ * Fn * slip * dt);
        }
    }
    if (!parallel) return;
    std::vector<double> all;
    for (const auto& a : added) all.insert(all.end(), a.begin(), a.end());
    solver.sumOverRanks(all);
    std::size_t i = 0;
    for (auto& face : faces_)
        for (double& v : face.volume) v += all[i++];
}

void ToolWear::write(const MpmSolver<2>& solver, double time)
{
    if (!solver.writesFiles()) return;  // a parallel run: rank 0 (every rank holds the whole)
    std::ofstream& os = file("wear.dat");
    std::ofstream& profile = file("wearProfile.dat");
    os << time;
    for (std::size_t k = 0; k < faces_.size(); ++k) {
        const Face& face = faces_[k];
        const double length = (face.to - face.from).norm();
        const double binLength = length / static_cast<double>(face.volume.size());
        double volume = 0, deepest = 0;
        for (std::size_t b = 0; b < face.volume.size(); ++b) {
            volume += face.volume[b];
            const double s = (static_cast<double>(b) + 0.5) * binLength;
            const Vector2 x = face.from + s / length * (face.to - face.from);
            // Axisymmetric: the bin's volume per radian covers its length times its radius.
            const double depth = face.volume[b] / (binLength * (axisymmetric_ ? x.x() : 1.0));
            deepest = std::max(deepest, depth);
            profile << time << ' ' << k << ' ' << s << ' ' << x.x() << ' ' << x.y() << ' ' << depth << '\n';
        }
        os << ' ' << deepest << ' ' << volume;
    }
    os << std::endl;
    profile.flush();
}

void ToolWear::writeState(std::ostream& os) const
{
    for (const auto& face : faces_) {
        os << "    " << face.name << " { from (" << exactNumber(face.from.x()) << ' ' << exactNumber(face.from.y())
           << "); to (" << exactNumber(face.to.x()) << ' ' << exactNumber(face.to.y()) << "); volume (";
        for (double v : face.volume) os << ' ' << exactNumber(v);
        os << " ); }\n";
    }
}

void ToolWear::readState(const Dictionary& state)
{
    for (auto& face : faces_) {
        const Dictionary& f = state.subDict(face.name);
        face.from = f.get<Vector2>("from");
        face.to = f.get<Vector2>("to");
        face.volume = f.get<std::vector<double>>("volume");
    }
}

} // namespace gpic
