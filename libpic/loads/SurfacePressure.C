#include "loads/SurfacePressure.H"
#include "core/Info.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "grid/Grid.H"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace gpic {

GPIC_REGISTER(ParticleLoad<2>, SurfacePressure, "surfacePressure")

namespace {

std::string str(const Vector2& x)
{
    std::ostringstream os;
    os << '(' << x.x() << ' ' << x.y() << ')';
    return os.str();
}

//- A particle whose domain reaches across the segment, in segment coordinates: s along
//  from -> to, d along the outward normal.
struct Candidate {
    std::size_t q;
    double lo, hi;   //- extent of the domain along the segment [m]
    double d;        //- centre distance from the segment's line [m]
    double halfN;    //- half-size of the domain along the normal [m]
    double outer() const { return d + halfN; }
};

} // namespace

SurfacePressure::SurfacePressure(const Dictionary& dict)
    : name_(dict.name()),
      file_(dict.fileName()),
      bodyLine_(dict.lineOf("body")),
      bodyName_(dict.get<std::string>("body")),
      p_(TimeFunction::read(dict, "pressure")),
      rampTime_(dict.found("rampTime")
                    ? dict.getChecked<double>("rampTime", [](const double& t) { return t >= 0; }, "rampTime >= 0")
                    : 0.0)
{
    const int given = int(dict.found("from") || dict.found("to")) + int(dict.found("points")) + int(dict.found("arc"));
    if (given != 1)
        dict.fail(dict.found("points") ? "points" : dict.found("arc") ? "arc" : "from",
                  name_ + " needs exactly one loaded part: from and to (a segment), points (a polyline) "
                          "or arc { centre; radius; startAngle; endAngle; }");
    if (dict.found("points")) {
        line_ = dict.lineOf("points");
        points_ = dict.get<std::vector<Vector2>>("points");
        if (points_.size() < 2) dict.fail("points", "the polyline of " + name_ + " needs at least 2 points");
    } else if (const Dictionary* arc = dict.subDictPtr("arc")) {
        line_ = dict.lineOf("arc");
        const Vector2 centre = arc->get<Vector2>("centre");
        const double R = arc->getChecked<double>("radius", [](const double& r) { return r > 0; }, "radius > 0");
        const double a0 = arc->get<double>("startAngle"), a1 = arc->get<double>("endAngle");
        if (!(std::abs(a1 - a0) > 0 && std::abs(a1 - a0) <= 360))
            arc->fail("endAngle", "the arc of " + name_ + " must turn by more than 0 and at most 360 degrees "
                                  "from startAngle to endAngle");
        const int chords = static_cast<int>(std::ceil(std::abs(a1 - a0)));  // at most 1 degree each
        for (int k = 0; k <= chords; ++k) {
            const double a = (a0 + (a1 - a0) * k / chords) * M_PI / 180;
            points_.push_back(centre + R * Vector2(std::cos(a), std::sin(a)));
        }
    } else {
        line_ = dict.lineOf("from");
        points_ = {dict.get<Vector2>("from"), dict.get<Vector2>("to")};
    }
    for (std::size_t k = 1; k < points_.size(); ++k)
        if (!((points_[k] - points_[k - 1]).norm() > 0))
            dict.fail(dict.found("points") ? "points" : "to",
                      "the loaded segment of " + name_ + " has zero length: from and to are both " + str(points_[k]));
}

void SurfacePressure::fail(const std::string& message, int line) const
{
    throw InputError(file_, line, name_ + ": " + message);
}

double SurfacePressure::pressure(double t) const
{
    const double ramp = rampTime_ > 0 ? std::min(1.0, std::max(0.0, t) / rampTime_) : 1.0;
    return ramp * p_.value(t);
}

void SurfacePressure::initialise(const Particles<2>& p, const Grid<2>& grid,
                                 const std::vector<std::string>& bodyNames)
{
    const auto it = std::find(bodyNames.begin(), bodyNames.end(), bodyName_);
    if (it == bodyNames.end()) {
        std::string valid;
        for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
        fail("body '" + bodyName_ + "' is not a body of constant/bodies; valid choices: " + valid, bodyLine_);
    }
    const int body = static_cast<int>(it - bodyNames.begin());

    std::vector<LoadedPiece> entries;
    double L = 0;
    for (std::size_t k = 1; k < points_.size(); ++k) {
        loadSegment(points_[k - 1], points_[k], k - 1, p, grid, body, entries);
        L += (points_[k] - points_[k - 1]).norm();
    }
    std::stable_sort(entries.begin(), entries.end(), [](const LoadedPiece& a, const LoadedPiece& z) { return a.q < z.q; });
    loaded_.clear();
    lengths_.clear();
    normals_.clear();
    for (const LoadedPiece& e : entries) {
        loaded_.push_back(e.q);
        lengths_.push_back(e.length);
        normals_.push_back(e.normal);
    }
    std::vector<std::size_t> distinct(loaded_);
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    info() << "Load " << name_ << ": pressure on " << distinct.size() << " particles of body " << bodyName_
           << " along " << L << " m";
    if (points_.size() == 2)
        info() << ", outward normal " << str(normals_.front()) << '\n';
    else
        info() << " in " << points_.size() - 1 << " pieces\n";
}

void SurfacePressure::loadSegment(const Vector2& from, const Vector2& to, std::size_t piece, const Particles<2>& p,
                                  const Grid<2>& grid, int body, std::vector<LoadedPiece>& entries) const
{
    const std::string segment = points_.size() == 2
        ? "the segment from " + str(from) + " to " + str(to)
        : "piece " + std::to_string(piece + 1) + " of the polyline (from " + str(from) + " to " + str(to) + ")";

    const double L = (to - from).norm();
    const Vector2 t = (to - from) / L;
    Vector2 n(-t.y(), t.x());
    // Sizes along a direction of the axis-aligned particle domains and cells.
    const auto along = [](const Vector2& dir, const Vector2& half) {
        return std::abs(dir.x()) * half.x() + std::abs(dir.y()) * half.y();
    };
    const double cellN = along(n, grid.cellSize());

    std::vector<Candidate> c;
    double narrowest = L;
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (p.body[q] != body) continue;
        const Vector2 r = p.x[q] - from;
        const double s = r.dot(t), halfT = along(t, p.halfSize[q]);
        if (s + halfT <= 0 || s - halfT >= L) continue;
        c.push_back({q, s - halfT, s + halfT, r.dot(n), along(n, p.halfSize[q])});
        narrowest = std::min(narrowest, 2 * halfT);
    }
    // The body lies on the side of the particles next to the line.
    double side = 0;
    std::size_t near = 0;
    for (const auto& k : c)
        if (std::abs(k.d) - k.halfN <= cellN) {
            side += k.d;
            ++near;
        }
    if (near == 0)
        fail("no particle of body '" + bodyName_ + "' lies within one cell of " + segment +
             ": the segment must lie on the body's surface", line_);
    if (side > 0) {
        n = -n;
        for (auto& k : c) k.d = -k.d;
    }
    const Vector2 normalOut(n.x() + 0.0, n.y() + 0.0);  // + 0.0: no '-0' in messages

    // Cut the segment where particle domains begin and end (ends closer than a round-off
    // tolerance merged), then give each piece to the outermost particle covering it.
    const double eps = 1e-9 * narrowest;
    std::vector<double> cuts{0.0, L};
    for (const auto& k : c) {
        if (k.lo > 0) cuts.push_back(k.lo);
        if (k.hi < L) cuts.push_back(k.hi);
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> b{0.0};
    for (double x : cuts)
        if (x > b.back() + eps && x < L - eps) b.push_back(x);
    b.push_back(L);
    const std::size_t pieces = b.size() - 1;

    std::sort(c.begin(), c.end(), [](const Candidate& a, const Candidate& z) {
        return a.outer() > z.outer() || (a.outer() == z.outer() && a.q < z.q);
    });
    std::vector<int> owner(pieces, -1);
    for (std::size_t i = 0; i < c.size(); ++i) {
        auto k = static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), c[i].lo) - b.begin());
        for (k = k > 0 ? k - 1 : 0; k < pieces && b[k] < c[i].hi; ++k) {
            const double mid = 0.5 * (b[k] + b[k + 1]);
            if (owner[k] < 0 && mid > c[i].lo && mid < c[i].hi) owner[k] = static_cast<int>(i);
        }
    }

    std::vector<double> length(c.size(), 0.0);
    for (std::size_t k = 0; k < pieces; ++k) {
        const Vector2 a = from + b[k] * t, z = from + b[k + 1] * t;
        if (owner[k] < 0)
            fail(segment + " leaves body '" + bodyName_ + "' between " + str(a) + " and " + str(z) +
                 ": every point of a loaded segment must lie on the body's surface", line_);
        const Candidate& k0 = c[owner[k]];
        if (std::abs(k0.outer()) > cellN) {
            std::ostringstream msg;
            msg << segment << " is not on the surface of body '" << bodyName_ << "': near "
                << str(0.5 * (a + z)) << " the surface lies " << std::abs(k0.outer()) << " m "
                << (k0.outer() > 0 ? "beyond" : "short of") << " it (allowed: one cell, " << cellN << " m)";
            fail(msg.str(), line_);
        }
        // Axisymmetric: the ring's area per radian, the length times the radius of its middle.
        length[owner[k]] += (b[k + 1] - b[k]) * (grid.axisymmetric() ? 0.5 * (a.x() + z.x()) : 1.0);
    }

    for (std::size_t i = 0; i < c.size(); ++i)
        if (length[i] > 0) entries.push_back({c[i].q, length[i], normalOut});
}

void SurfacePressure::addForces(double t, const Particles<2>&, std::vector<Vector2>& force) const
{
    // Compression positive: the pressure pushes against the outward normal.
    const double pt = pressure(t);
    for (std::size_t k = 0; k < loaded_.size(); ++k) force[loaded_[k]] += lengths_[k] * (-pt * normals_[k]);
}

void SurfacePressure::renumber(const std::vector<std::size_t>& newIndex)
{
    // A removed particle takes its share of the loaded length with it.
    std::size_t kept = 0;
    for (std::size_t k = 0; k < loaded_.size(); ++k) {
        const std::size_t q = newIndex[loaded_[k]];
        if (q == removedParticle) continue;
        loaded_[kept] = q;
        lengths_[kept] = lengths_[k];
        normals_[kept] = normals_[k];
        ++kept;
    }
    loaded_.resize(kept);
    lengths_.resize(kept);
    normals_.resize(kept);
}

} // namespace gpic
