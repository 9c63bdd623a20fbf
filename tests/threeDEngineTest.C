// The engine in 3D, set up in memory (the case files: threeDCaseTest.C):
// - a cube (an octant between symmetry planes) compressed equally along its axes takes
//   sigma = 3 K ln(1 - a t) inside until the unloading wave arrives (within 1e-3);
// - a bar's first axial mode: fixed at x = 0, free at x = L, its sides slip (uniaxial
//   strain), so c = sqrt((K + 4G/3)/rho) and the velocity v0 sin(pi x / 2L) cos(w t) turns
//   at t = T/4 = L/c (within 1 %);
// - plane strain recovered: the same bar as a plane grid and as a 3D slab one cell thick
//   between slip faces move alike to round-off;
// - a column under gravity in a box with slip walls comes to rest at the geostatic stress
//   sigma_yy = -rho g (H - y), sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy (within 2 % of
//   rho g H, per layer of cells);
// - the 3D passes give bitwise the same particles at 1 and 2 threads.
#include "core/Threads.H"
#include "dictionary/Dictionary.H"
#include "engine/MpmSolver.H"
#include "schemes/UpdateScheme.H"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace gpic;

namespace {

constexpr double rho = 1000, E = 1e6, nu = 0.3;
const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // K + 4G/3

template <int D> using Vec = typename Space<D>::Vector;

//- A box of material filling `cells` cells from the grid's origin, 2 particles per cell
//  along each axis; velocity v(x).
template <int D, class Velocity>
Particles<D> box(const Grid<D>& grid, const std::array<int, D>& cells, Velocity velocity)
{
    Particles<D> p;
    const Vec<D> h = grid.cellSize(), half = 0.25 * h;
    const double volume = h.prod() / std::pow(2.0, D);
    std::array<int, D> k{};
    const auto count = [&](int a) { return 2 * cells[a]; };
    long total = 1;
    for (int a = 0; a < D; ++a) total *= count(a);
    for (long n = 0; n < total; ++n) {
        long rest = n;
        for (int a = 0; a < D; ++a) {
            k[a] = static_cast<int>(rest % count(a));
            rest /= count(a);
        }
        Vec<D> x;
        for (int a = 0; a < D; ++a) x[a] = grid.origin()[a] + (k[a] + 0.5) * 0.5 * h[a];
        const std::size_t q = p.add(x, rho * volume, volume, half, 0, 0);
        p.v[q] = velocity(x);
    }
    return p;
}

template <int D>
std::unique_ptr<MpmSolver<D>> engine(Grid<D> grid, Particles<D> particles, const std::array<std::string, 6>& sides,
                                     const Vec<D>& gravity, double damping)
{
    SolverInputs<D> in(std::move(grid));
    in.particles = std::move(particles);
    const Dictionary material = Dictionary::parse("type linearElastic; rho 1000; E 1e6; nu 0.3;", "constant/materials/solid");
    in.materials.push_back(Material<D>::New(material));
    const Dictionary none;
    in.shape = Registry<ShapeFunction<D>>::select("bilinear", none, none, "shapeFunction");
    for (int s = 0; s < Space<D>::nFaces; ++s) {
        const Dictionary side = Dictionary::parse("type " + sides[s] + ";", "constant/grid");
        in.boundaries[s] = Registry<BoundaryCondition<D>>::select(side, side, static_cast<GridSide>(s));
    }
    in.gravity = gravity;
    in.damping = damping;
    in.transfer = Registry<ParticleTransfer>::select("FLIP", Dictionary::parse("transfer FLIP;", "system/mpmSchemes"),
                                                   Dictionary::parse("transfer FLIP;", "system/mpmSchemes"), "transfer");
    return std::make_unique<MpmSolver<D>>(std::move(in));
}

//- The bar of length 1 along x1 (10 cells of 0.1, one cell across), in its first mode.
template <int D> std::unique_ptr<MpmSolver<D>> bar(double v0)
{
    typename Grid<D>::Index cells{}, filled{};
    cells.fill(1);
    filled.fill(1);
    cells[0] = 12;
    filled[0] = 10;
    Grid<D> grid(Vec<D>::Zero(), Vec<D>::Constant(0.1), cells);
    Particles<D> p = box<D>(grid, filled, [v0](const Vec<D>& x) {
        Vec<D> v = Vec<D>::Zero();
        v[0] = v0 * std::sin(M_PI * x[0] / 2.0);
        return v;
    });
    return engine<D>(std::move(grid), std::move(p), {"fixed", "free", "slip", "slip", "slip", "slip"}, Vec<D>::Zero(), 0.0);
}

template <int D> double meanVelocity(const Particles<D>& p)
{
    double sum = 0;
    for (std::size_t q = 0; q < p.size(); ++q) sum += p.v[q][0];
    return sum / double(p.size());
}

//- Steps of dt until t, the mean axial velocity after each.
template <int D> std::vector<double> history(MpmSolver<D>& s, double dt, int steps)
{
    const Dictionary none;
    const auto scheme = Registry<UpdateScheme>::select("USL", none, none, "updateScheme");
    std::vector<double> v;
    for (int k = 0; k < steps; ++k) {
        scheme->advance(s, dt);
        s.setTime(s.time() + dt);
        v.push_back(meanVelocity(s.particles()));
    }
    return v;
}

} // namespace

TEST(ThreeDEngine, aBarsFirstAxialModeTurnsAtAQuarterPeriod)
{
    auto s = bar<3>(1e-3);
    const double c = std::sqrt(M / rho), dt = 0.05 * 0.1 / c, quarter = 1.0 / c;
    const std::vector<double> v = history(*s, dt, static_cast<int>(1.5 * quarter / dt));
    ASSERT_GT(v.front(), 0.0);
    std::size_t k = 0;
    while (k + 1 < v.size() && v[k + 1] > 0) ++k;
    ASSERT_LT(k + 1, v.size()) << "the bar never turned";
    const double turn = dt * (k + 1 + v[k] / (v[k] - v[k + 1]));  // v[k] after step k + 1
    EXPECT_NEAR(turn / quarter, 1.0, 0.01) << "turned at " << turn << " s, closed form " << quarter << " s";
    std::cout << "3D bar: turned at " << turn << " s, closed form L/c = " << quarter << " s\n";
}

TEST(ThreeDEngine, aCubeCompressedEquallyAlongItsThreeAxesTakesTheBulkModulusStress)
{
    // An elastic cube (an octant, 0.6 m, between three symmetry planes through its centre)
    // set moving at v = -a x, free outside: until the unloading from its faces arrives
    // (0.3 m / c; the particles within 0.15 m of the centre, ahead of the wave's numerical
    // spread, at t = 0.25 m / c) its inside is compressed
    // equally along the three axes, sigma11 = sigma22 = sigma33 = 3 K ln(1 - a t)
    // (K = E / (3 (1 - 2 nu)); the strain rate a / (1 - a t) of the shrinking cube), no
    // shear; to 1e-3 of the stress (the lumped mass maps the linear velocity field of
    // particles moved off their lattice onto the nodes to the mass-weighted mean of the
    // nearby positions, not the nodes': an error in the strain rate of the order of the
    // particles' shift in cells, 2e-3 here).
    const double a = 0.1, K = E / (3 * (1 - 2 * nu)), c = std::sqrt(M / rho), h = 0.05;
    Grid<3> grid(Vec<3>::Zero(), Vec<3>::Constant(h), Grid<3>::Index{14, 14, 14});
    Particles<3> p = box<3>(grid, {12, 12, 12}, [a](const Vec<3>& x) { return Vec<3>(-a * x); });
    auto s = engine<3>(std::move(grid), std::move(p), {"symmetry", "free", "symmetry", "free", "symmetry", "free"},
                       Vec<3>::Zero(), 0.0);
    const double dt = 0.05 * h / c;
    const int steps = static_cast<int>(0.25 / c / dt);
    history(*s, dt, steps);
    const double t = steps * dt, expected = 3 * K * std::log(1 - a * t);
    const Particles<3>& q = s->particles();
    std::size_t inside = 0;
    for (std::size_t k = 0; k < q.size(); ++k) {
        if (q.x0[k].maxCoeff() > 0.15) continue;  // ahead of the discrete unloading wave's spread
        ++inside;
        for (int d : {XX, YY, ZZ}) EXPECT_NEAR(q.sigma[k][d], expected, 1e-3 * std::abs(expected)) << "particle " << k;
        for (int d : {XY, YZ, XZ}) EXPECT_NEAR(q.sigma[k][d], 0.0, 1e-6 * std::abs(expected));
    }
    EXPECT_GT(inside, 200u);
}

TEST(ThreeDEngine, aSlabOneCellThickBetweenSlipFacesMovesAsThePlaneBar)
{
    auto plane = bar<2>(1e-3);
    auto slab = bar<3>(1e-3);
    const double dt = 0.05 * 0.1 / std::sqrt(M / rho);
    const std::vector<double> v2 = history(*plane, dt, 400), v3 = history(*slab, dt, 400);
    double worst = 0;
    for (std::size_t k = 0; k < v2.size(); ++k) worst = std::max(worst, std::abs(v3[k] - v2[k]));
    EXPECT_LT(worst, 1e-12) << "of a mean velocity of about 6e-4 m/s";
    std::cout << "slab against plane: largest difference of the mean velocity " << worst << " m/s\n";
    for (std::size_t q = 0; q < slab->particles().size(); ++q) EXPECT_EQ(slab->particles().v[q][2], 0.0);
}

TEST(ThreeDEngine, aColumnInABoxComesToTheGeostaticStress)
{
    const double H = 1.0, g = 10.0;
    Grid<3> grid(Space<3>::Vector::Zero(), Space<3>::Vector::Constant(0.1), {4, 11, 4});
    Particles<3> p = box<3>(grid, {4, 10, 4}, [](const Space<3>::Vector&) { return Space<3>::Vector::Zero(); });
    auto s = engine<3>(std::move(grid), std::move(p), {"slip", "slip", "fixed", "free", "slip", "slip"},
                       Space<3>::Vector(0, -g, 0), 0.3);
    const double dt = 0.5 * 0.1 / std::sqrt(M / rho);
    history(*s, dt, static_cast<int>(1.5 / dt));
    // The mean per layer of cells against the closed form at the layer's centre.
    std::map<int, std::pair<double, int>> yy, lateral;
    const Particles<3>& q = s->particles();
    for (std::size_t k = 0; k < q.size(); ++k) {
        const int layer = static_cast<int>(q.x0[k][1] / 0.1);
        yy[layer].first += q.sigma[k][YY];
        yy[layer].second += 1;
        lateral[layer].first += 0.5 * (q.sigma[k][XX] + q.sigma[k][ZZ]);
        lateral[layer].second += 1;
        EXPECT_NEAR(q.sigma[k][XY], 0.0, 1e-3 * rho * g * H);
        EXPECT_NEAR(q.sigma[k][YZ], 0.0, 1e-3 * rho * g * H);
    }
    double worst = 0;
    for (const auto& [layer, sum] : yy) {
        const double y = (layer + 0.5) * 0.1, exact = -rho * g * (H - y);
        worst = std::max({worst, std::abs(sum.first / sum.second - exact),
                          std::abs(lateral[layer].first / lateral[layer].second - nu / (1 - nu) * exact)});
        EXPECT_NEAR(sum.first / sum.second, exact, 0.02 * rho * g * H) << "layer " << layer;
        EXPECT_NEAR(lateral[layer].first / lateral[layer].second, nu / (1 - nu) * exact, 0.02 * rho * g * H)
            << "layer " << layer;
    }
    std::cout << "geostatic column: largest error of a layer's mean stress " << worst / (rho * g * H) << " rho g H\n";
}

TEST(ThreeDEngine, theSameParticlesAtOneAndTwoThreads)
{
    const long savedWork = minParallelWork();
    minParallelWork() = 1;  // thread every pass of this small scene
    const int saved = omp_get_max_threads();
    std::vector<Particles<3>> results;
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        auto s = bar<3>(1e-2);
        s->sortParticles();
        history(*s, 2e-4, 200);
        results.push_back(s->particles());
    }
    omp_set_num_threads(saved);
    minParallelWork() = savedWork;
    ASSERT_EQ(results[0].size(), results[1].size());
    for (std::size_t q = 0; q < results[0].size(); ++q) {
        EXPECT_EQ(results[0].x[q], results[1].x[q]);
        EXPECT_EQ(results[0].v[q], results[1].v[q]);
        EXPECT_EQ(results[0].sigma[q], results[1].sigma[q]);
    }
}
