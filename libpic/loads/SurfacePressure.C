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

GPIC_REGISTER(ParticleLoad, SurfacePressure, "surfacePressure")

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
      line_(dict.lineOf("from")),
      bodyLine_(dict.lineOf("body")),
      bodyName_(dict.get<std::string>("body")),
      from_(dict.get<Vector2>("from")),
      to_(dict.get<Vector2>("to")),
      p_(TimeFunction::read(dict, "pressure")),
      rampTime_(dict.found("rampTime")
                    ? dict.getChecked<double>("rampTime", [](const double& t) { return t >= 0; }, "rampTime >= 0")
                    : 0.0)
{
    if (!((to_ - from_).norm() > 0))
        dict.fail("to", "the loaded segment of " + name_ + " has zero length: from and to are both " + str(from_));
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

void SurfacePressure::initialise(const Particles& p, const Grid& grid,
                                 const std::vector<std::string>& bodyNames)
{
    const auto it = std::find(bodyNames.begin(), bodyNames.end(), bodyName_);
    if (it == bodyNames.end()) {
        std::string valid;
        for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
        fail("body '" + bodyName_ + "' is not a body of constant/bodies; valid choices: " + valid, bodyLine_);
    }
    const int body = static_cast<int>(it - bodyNames.begin());
    const std::string segment = "the segment from " + str(from_) + " to " + str(to_);

    const double L = (to_ - from_).norm();
    const Vector2 t = (to_ - from_) / L;
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
        const Vector2 r = p.x[q] - from_;
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
    normalOut_ = Vector2(n.x() + 0.0, n.y() + 0.0);  // + 0.0: no '-0' in messages

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
        const Vector2 a = from_ + b[k] * t, z = from_ + b[k + 1] * t;
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

    loaded_.clear();
    lengths_.clear();
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (length[i] > 0) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t z) { return c[a].q < c[z].q; });
    for (std::size_t i : order) {
        loaded_.push_back(c[i].q);
        lengths_.push_back(length[i]);
    }
    info() << "Load " << name_ << ": pressure on " << loaded_.size() << " particles of body "
              << bodyName_ << " along " << L << " m, outward normal " << str(normalOut_) << '\n';
}

void SurfacePressure::addForces(double t, const Particles&, std::vector<Vector2>& force) const
{
    // Compression positive: the pressure pushes against the outward normal.
    const Vector2 perLength = -pressure(t) * normalOut_;
    for (std::size_t k = 0; k < loaded_.size(); ++k) force[loaded_[k]] += lengths_[k] * perLength;
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
        ++kept;
    }
    loaded_.resize(kept);
    lengths_.resize(kept);
}

} // namespace gpic
