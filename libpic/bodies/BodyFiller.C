#include "bodies/BodyFiller.H"

#include "bodies/Shape.H"
#include "bodies/VectorField.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace gpic {

namespace {

template <int D> int materialIndex(const Dictionary& body, const std::vector<std::unique_ptr<Material<D>>>& materials)
{
    const std::string name = body.get<std::string>("material");
    std::string valid;
    for (std::size_t m = 0; m < materials.size(); ++m) {
        if (materials[m]->name() == name) return static_cast<int>(m);
        valid += (valid.empty() ? "" : ", ") + materials[m]->name();
    }
    body.fail("material", "material '" + name + "' is not in constant/materials; valid choices: " +
                              valid);
}

//- Initial stress at x (eqs. 3.3.1-3.3.4), tension positive; the vertical is the last axis
//  (x2 in the plane, x3 in 3D).
template <int D> class InitialStress {
    using Vector = typename Space<D>::Vector;
    using SymTensor = typename Space<D>::SymTensor;

public:
    InitialStress(const Dictionary* dict, double rho, double g, double topOfBody)
    {
        if (!dict) return;
        type_ = dict->getWord("type", {"uniform", "geostatic"});
        if (type_ == "uniform") {
            const auto s = dict->getChecked<std::vector<double>>(
                "sigma", [](const std::vector<double>& v) { return v.size() == Space<D>::nSym; },
                D == 2 ? "four components (s11 s22 s33 s12)" : "six components (s11 s22 s33 s12 s23 s13)");
            for (int k = 0; k < Space<D>::nSym; ++k) uniform_[k] = s[static_cast<std::size_t>(k)];
            return;
        }
        // K0 given (eq. 3.3.1; nu/(1-nu) for an elastic mass, eq. 3.3.2) or from the
        // friction angle by Jaky's formula K0 = 1 - sin(phi) (eq. 3.3.3).
        if (dict->found("K0") == dict->found("phi"))
            dict->fail("K0", "geostatic initial stress needs exactly one of K0 and phi (Jaky: "
                             "K0 = 1 - sin(phi)) in dictionary " + dict->name());
        if (dict->found("K0"))
            K0_ = dict->getChecked<double>("K0", [](const double& k) { return k > 0; }, "K0 > 0");
        else
            K0_ = 1.0 - std::sin(M_PI / 180.0 *
                                 dict->getChecked<double>(
                                     "phi", [](const double& p) { return p >= 0 && p < 90; },
                                     "0 <= phi < 90 (degrees)"));
        surface_ = dict->getOrDefault<double>("surface", topOfBody);
        rhoG_ = rho * g;
    }
    SymTensor at(const Vector& x) const
    {
        if (type_ != "geostatic") return uniform_;
        const double sV = -rhoG_ * std::max(0.0, surface_ - x[D - 1]);  // eq. 3.3.1
        SymTensor s = SymTensor::Zero();                                 // eq. 3.3.2
        for (int a = 0; a < 3; ++a) s[a] = K0_ * sV;
        s[D - 1] = sV;
        return s;
    }

private:
    std::string type_ = "uniform";
    SymTensor uniform_ = SymTensor::Zero();
    double K0_ = 0, surface_ = 0, rhoG_ = 0;
};


//- The cells of the grid, per axis, that a box [lo, hi] can hold particles in: one cell of
//  margin each side (bounds() rounding), clamped to the grid. Empty where it misses the grid.
template <int D>
std::array<std::pair<int, int>, D> cellRange(const Grid<D>& grid, const typename Space<D>::Vector& lo,
                                             const typename Space<D>::Vector& hi)
{
    std::array<std::pair<int, int>, D> range;
    for (int a = 0; a < D; ++a) {
        const double h = grid.cellSize()[a];
        const double first = std::floor((lo[a] - grid.origin()[a]) / h) - 1;
        const double last = std::floor((hi[a] - grid.origin()[a]) / h) + 1;
        const double top = grid.cells(a) - 1;
        range[a] = {static_cast<int>(std::clamp(first, 0.0, top + 1)), static_cast<int>(std::clamp(last, -1.0, top))};
    }
    return range;
}

//- The bodies filled so far, by where their shapes' boxes lie: about as many buckets as there
//  are bodies, over the grid, so that a body is checked for overlaps against its neighbours
//  only, not against every earlier body (which made picInit quadratic in the bodies).
template <int D> class ShapeBuckets {
public:
    using Vector = typename Space<D>::Vector;
    ShapeBuckets(const Grid<D>& grid, std::size_t bodies) : origin_(grid.origin())
    {
        const double perAxis = std::ceil(std::pow(4.0 * static_cast<double>(std::max<std::size_t>(bodies, 1)), 1.0 / D));
        std::size_t total = 1;
        for (int a = 0; a < D; ++a) {
            n_[a] = static_cast<int>(std::min<double>(perAxis, grid.cells(a)));
            size_[a] = (grid.upper()[a] - grid.origin()[a]) / n_[a];
            total *= static_cast<std::size_t>(n_[a]);
        }
        buckets_.resize(total);
    }
    //- Body `id`, of shape box [lo, hi].
    void add(int id, const Vector& lo, const Vector& hi)
    {
        std::array<int, D> from, to;
        for (int a = 0; a < D; ++a) {
            from[a] = bucket(lo[a], a);
            to[a] = bucket(hi[a], a);
        }
        std::array<int, D> k = from;
        while (true) {
            buckets_[flat(k)].push_back(id);
            int a = 0;
            while (a < D && ++k[a] > to[a]) k[a] = from[a], ++a;
            if (a == D) return;
        }
    }
    //- The bodies whose boxes share a bucket with one of `points`, in id order.
    template <class Points> std::vector<int> near(const Points& points, std::size_t first) const
    {
        std::vector<int> ids;
        std::vector<std::size_t> seen;
        for (std::size_t q = first; q < points.size(); ++q) {
            std::array<int, D> k;
            for (int a = 0; a < D; ++a) k[a] = bucket(points[q][a], a);
            const std::size_t b = flat(k);
            if (!seen.empty() && seen.back() == b) continue;  // neighbours share buckets
            seen.push_back(b);
        }
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        for (const std::size_t b : seen) ids.insert(ids.end(), buckets_[b].begin(), buckets_[b].end());
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        return ids;
    }

private:
    Vector origin_, size_;
    std::array<int, D> n_{};
    std::vector<std::vector<int>> buckets_;

    int bucket(double x, int a) const
    {
        const double k = std::floor((x - origin_[a]) / size_[a]);
        return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(n_[a] - 1)));
    }
    std::size_t flat(const std::array<int, D>& k) const
    {
        std::size_t i = 0;
        for (int a = D - 1; a >= 0; --a) i = i * static_cast<std::size_t>(n_[a]) + static_cast<std::size_t>(k[a]);
        return i;
    }
};

} // namespace

template <int D>
FilledBodies<D> fillBodies(const Dictionary& bodiesDict, const Grid<D>& grid,
                           const std::vector<std::unique_ptr<Material<D>>>& materials,
                           const typename Space<D>::Vector& gravity,
                           const std::array<bool, Space<D>::nFaces>& mirrorSides)
{
    using Vector = typename Space<D>::Vector;
    FilledBodies<D> out;
    std::vector<std::unique_ptr<Shape<D>>> shapes;  //- of the bodies filled so far
    bodiesDict.refuseRepeats("body");  // merged, one body would be silently lost
    const std::vector<std::string> keys = bodiesDict.keys();
    ShapeBuckets<D> placed(grid, keys.size());
    for (const auto& key : keys) {
        if (!bodiesDict.isDict(key)) bodiesDict.fail(key, "'" + key + "' is not a body sub-dictionary");
        const Dictionary& body = bodiesDict.subDict(key);
        const int bodyId = static_cast<int>(out.bodyNames.size());
        out.bodyNames.push_back(key);
        const int mat = materialIndex(body, materials);
        auto shape = Shape<D>::New(body.subDict("shape"));
        const auto [lo, hi] = shape->bounds();
        // A millionth of a cell of slack: a cell size written with a few decimals (1.8/135 as
        // 0.0133333333) leaves the grid a rounding short of the shape it was sized for.
        const double slack = 1e-6 * grid.minCellSize();
        Vector gridLo = grid.origin().array() - slack, gridHi = grid.upper().array() + slack;
        // A shape may reach across a mirror side (symmetry): the part beyond it is the mirrored
        // half of the body, not filled (a quarter of a column between two symmetry planes).
        for (int a = 0; a < D; ++a) {
            if (mirrorSides[2 * a]) gridLo[a] = -std::numeric_limits<double>::infinity();
            if (mirrorSides[2 * a + 1]) gridHi[a] = std::numeric_limits<double>::infinity();
        }
        if ((lo.array() < gridLo.array()).any() || (hi.array() > gridHi.array()).any()) {
            std::ostringstream msg;
            msg << "body '" << key << "' reaches outside the grid: its shape spans ("
                << lo.transpose() << ") - (" << hi.transpose() << "), the grid ("
                << grid.origin().transpose() << ") - (" << grid.upper().transpose() << ")";
            body.fail("shape", msg.str());
        }
        const int n = body.getChecked<int>("particlesPerCell", [](const int& k) { return k >= 1 && k <= 10; },
                                           "1 <= particlesPerCell <= 10");
        const auto v0 = VectorField<D>(body, "velocity", Vector::Zero());
        Vector amplitude = Vector::Zero(), wavenumber = Vector::Zero();
        if (const Dictionary* mode = body.subDictPtr("modeShape")) {
            amplitude = mode->get<Vector>("amplitude");
            wavenumber = mode->get<Vector>("wavenumber");
        }
        const InitialStress<D> stress(body.subDictPtr("initialStress"), materials[mat]->rho(),
                                      gravity.norm(), hi[D - 1]);
        const Vector h = grid.cellSize();
        double volume = h.x() * h.y() / (n * n);
        if constexpr (D == 3) volume = h.x() * h.y() * h.z() / (n * n * n);
        const Vector half = 0.5 * h / n;
        std::size_t added = 0;
        const auto place = [&](const Vector& x) {
            if (!shape->inside(x)) return;
            // Axisymmetric: the ring the particle stands for, per radian (A r).
            const double V = grid.axisymmetric() ? volume * x.x() : volume;
            const std::size_t q = out.particles.add(x, materials[mat]->rho() * V, V, half, bodyId, mat);
            const double phase = wavenumber.dot(x - grid.origin());
            out.particles.v[q] = v0.at(x) + amplitude * std::sin(phase);
            out.particles.sigma[q] = stress.at(x);
            ++added;
        };
        // n^D particles per cell at the sub-cell centres, cell by cell in node order.
        const auto subCentre = [&](const typename Grid<D>::Index& cell, const typename Grid<D>::Index& sub) {
            Vector x = grid.nodePosition(cell);
            for (int d = 0; d < D; ++d) x[d] += (sub[d] + 0.5) * h[d] / n;
            return x;
        };
        // Only the cells of the shape's box: the others hold none of its particles, and a scan
        // of the whole grid per body made picInit quadratic in the bodies.
        const auto cells = cellRange(grid, lo, hi);
        try {
            if constexpr (D == 2) {
                for (int j = cells[1].first; j <= cells[1].second; ++j)
                    for (int i = cells[0].first; i <= cells[0].second; ++i)
                        for (int b = 0; b < n; ++b)
                            for (int a = 0; a < n; ++a) place(subCentre({i, j}, {a, b}));
            } else {
                for (int k = cells[2].first; k <= cells[2].second; ++k)
                    for (int j = cells[1].first; j <= cells[1].second; ++j)
                        for (int i = cells[0].first; i <= cells[0].second; ++i)
                            for (int c = 0; c < n; ++c)
                                for (int b = 0; b < n; ++b)
                                    for (int a = 0; a < n; ++a) place(subCentre({i, j, k}, {a, b, c}));
            }
        } catch (const RunError& e) {  // the particle arrays beyond the memory: name the body
            body.fail("particlesPerCell", "body '" + key + "', particlesPerCell " + std::to_string(n) + ": " + e.what());
        }
        if (added == 0) body.fail("shape", "body '" + key + "' holds no particle: enlarge it or "
                                           "raise particlesPerCell");
        // Two bodies in the same place would put twice the mass there and start interpenetrated.
        const std::size_t first = out.particles.size() - added;
        for (const int near : placed.near(out.particles.x, first)) {
            const auto other = static_cast<std::size_t>(near);
            std::size_t inside = 0, example = 0;
            for (std::size_t q = first; q < out.particles.size(); ++q)
                if (shapes[other]->inside(out.particles.x[q]) && inside++ == 0) example = q;
            if (inside == 0) continue;
            std::ostringstream msg;
            msg << "body '" << key << "' overlaps body '" << out.bodyNames[other] << "': " << inside
                << " of its particles lie inside that body's shape (the first at ("
                << out.particles.x[example].transpose() << ")); bodies may touch but not share space";
            body.fail("shape", msg.str());
        }
        placed.add(bodyId, lo, hi);
        shapes.push_back(std::move(shape));
    }
    if (out.bodyNames.empty()) bodiesDict.fail("", "constant/bodies defines no body");
    return out;
}

template FilledBodies<2> fillBodies(const Dictionary&, const Grid<2>&, const std::vector<std::unique_ptr<Material<2>>>&,
                                    const Space<2>::Vector&, const std::array<bool, Space<2>::nFaces>&);
#if GPIC_WITH_3D
template FilledBodies<3> fillBodies(const Dictionary&, const Grid<3>&, const std::vector<std::unique_ptr<Material<3>>>&,
                                    const Space<3>::Vector&, const std::array<bool, Space<3>::nFaces>&);
#endif

} // namespace gpic
