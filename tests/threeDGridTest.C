// The bottom of the 3D engine: a 3D grid's node numbering, cells and sides, a 3D particle
// set, and the three shape functions as tensor products in 3D. Each shape function must
// keep the properties the 2D test asks of it (partition of unity and of its gradient,
// exact linear fields, grad x = I), and a 3D weight summed through the thickness of a grid
// must give the plane weight of the same particle: the tensor product of the 2D kernel with
// the z kernel, whose weights sum to one.
#include "boundaryConditions/GridSides.H"
#include "dictionary/Dictionary.H"
#include "particles/ParticleFields.H"
#include "shapeFunctions/ShapeFunction.H"
#include "support/ShapeChecks.H"

#include <gtest/gtest.h>

#include <map>
#include <random>

using namespace gpic;
using Vector3 = Space<3>::Vector;

namespace {

template <int D>
ShapeWeights<D> weightsAt(const std::string& type, const Grid<D>& grid, const std::vector<typename Space<D>::Vector>& xs)
{
    Dictionary dict;
    auto shape = Registry<ShapeFunction<D>>::select(type, dict, dict, "shapeFunction");
    Particles<D> p;
    const typename Space<D>::Vector half = 0.25 * grid.cellSize();  // 2 particles per cell along each axis
    for (const auto& x : xs) p.add(x, 1.0, 1.0, half, 0, 0);
    ShapeWeights<D> w;
    shape->evaluate(grid, p, w);
    return w;
}

class ThreeDShapes : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST(ThreeDGrid, nodesCellsAndSidesFollowTheNumbering)
{
    const Grid<3> grid(Vector3(-1, 0, 2), Vector3(0.5, 0.25, 1.0), {4, 3, 2});
    EXPECT_EQ(grid.nNodes(), 5 * 4 * 3);
    EXPECT_EQ(grid.nCells(), 4 * 3 * 2);
    EXPECT_EQ(grid.node({1, 2, 1}), 1 + 5 * (2 + 4 * 1));
    for (int n = 0; n < grid.nNodes(); ++n) EXPECT_EQ(grid.node(grid.nodeIndex(n)), n);
    EXPECT_TRUE(grid.nodePosition(grid.node({4, 3, 2})).isApprox(grid.upper()));
    EXPECT_TRUE(grid.upper().isApprox(Vector3(1, 0.75, 4)));
    const auto cell = grid.cellOf(Vector3(0.2, 0.6, 3.999));
    EXPECT_EQ(cell, (Grid<3>::Index{2, 2, 1}));
    EXPECT_EQ(grid.cellOf(grid.upper()), (Grid<3>::Index{3, 2, 1}));  // the upper sides belong to the last cells
    EXPECT_TRUE(grid.contains(Vector3(0, 0.5, 3)));
    EXPECT_FALSE(grid.contains(Vector3(0, 0.5, 4.01)));
    // Each side holds the nodes of its plane, in node order; the six cover every boundary node.
    const std::size_t expected[6] = {4 * 3, 4 * 3, 5 * 3, 5 * 3, 5 * 4, 5 * 4};
    for (int s = 0; s < 6; ++s) {
        const auto side = static_cast<GridSide>(s);
        const std::vector<int> nodes = grid.sideNodes(side);
        EXPECT_EQ(nodes.size(), expected[s]) << gridSideNames()[s];
        EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
        for (int n : nodes) {
            const double x = grid.nodePosition(n)[sideAxis(side)];
            EXPECT_DOUBLE_EQ(x, lowSide(side) ? grid.origin()[sideAxis(side)] : grid.upper()[sideAxis(side)]);
        }
    }
    EXPECT_EQ(gridSideNames()[static_cast<int>(GridSide::back)], "back");
}

TEST(ThreeDGrid, readsThreeCellCountsAndRefusesTwo)
{
    const Dictionary ok = Dictionary::parse("origin (0 0 0); cellSize 0.1; nCells (3 4 5);", "constant/grid");
    const Grid<3> grid(ok);
    EXPECT_EQ(grid.nNodes(), 4 * 5 * 6);
    EXPECT_TRUE(grid.cellSize().isApprox(Vector3::Constant(0.1)));
    const Dictionary plane = Dictionary::parse("origin (0 0 0); cellSize (0.1 0.2 0.3); nCells (3 4);", "constant/grid");
    EXPECT_THROW(Grid<3>{plane}, std::exception);
}

TEST(ThreeDParticles, carryThreeComponentsAndSixStresses)
{
    Particles<3> p;
    p.add(Vector3(1, 2, 3), 2.0, 0.5, Vector3::Constant(0.1), 0, 1);
    p.add(Vector3(4, 5, 6), 1.0, 0.5, Vector3::Constant(0.1), 0, 0);
    p.sigma[0][XZ] = -7.0;
    p.carry(FieldGroup::affine);
    p.affine[1] = Space<3>::Gradient::Identity();
    p.sortByMaterial();
    EXPECT_EQ(p.x[0], Vector3(4, 5, 6));
    EXPECT_EQ(p.sigma[1][XZ], -7.0);
    EXPECT_EQ(p.affine[0], Space<3>::Gradient::Identity());
    // Six stress components, a 3-vector spin, and no polar group in 3D.
    static_assert(Space<3>::SymTensor::RowsAtCompileTime == 6);
    for (const ParticleField<3>& f : particleFields<3>()) EXPECT_NE(f.group, FieldGroup::polar) << f.name;
    double out[3];
    for (const ParticleField<3>& f : particleFields<3>())
        if (std::string(f.name) == "displacement") {
            p.x[0] += Vector3(0, 0, 0.25);
            f.derive(p, 0, out);
            EXPECT_EQ(out[2], 0.25);
        }
}

TEST_P(ThreeDShapes, partitionOfUnityAndLinearReproduction)
{
    const Vector3 h(0.5, 0.25, 0.4);
    const Grid<3> grid(Vector3(-1, 2, 0), h, {8, 8, 6});
    std::mt19937 random(7);
    // 2.5 cells from the sides, where every support is complete and B-splines are centred.
    std::uniform_real_distribution<double> ux(-1 + 2.5 * h.x(), 3 - 2.5 * h.x()), uy(2 + 2.5 * h.y(), 4 - 2.5 * h.y()),
        uz(2.5 * h.z(), 2.4 - 2.5 * h.z());
    std::vector<Vector3> xs;
    for (int k = 0; k < 200; ++k) xs.emplace_back(ux(random), uy(random), uz(random));
    const ShapeWeights<3> w = weightsAt<3>(GetParam(), grid, xs);
    EXPECT_EQ(w.stride, GetParam() == "bilinear" ? 8 : 27);
    for (int k = 0; k < int(w.node.size()); ++k) ASSERT_GE(w.node[k], 0);  // every support inside
    expectPartitionOfUnityAndLinearFields<3>(grid, w, xs);
}

TEST_P(ThreeDShapes, summedThroughTheThicknessGiveThePlaneWeights)
{
    // Near the sides too: the kernels' edge rules are per axis.
    const Eigen::Vector2d h(0.5, 0.25);
    const Grid<2> plane(Eigen::Vector2d(-1, 2), h, 8, 10);
    const Grid<3> slab(Vector3(-1, 2, 0), Vector3(h.x(), h.y(), 0.3), {8, 10, 3});
    std::mt19937 random(3);
    std::uniform_real_distribution<double> ux(-1, 3), uy(2, 4.5), uz(0.1, 0.8);
    std::vector<Eigen::Vector2d> xs2;
    std::vector<Vector3> xs3;
    for (int k = 0; k < 100; ++k) {
        xs2.emplace_back(ux(random), uy(random));
        xs3.emplace_back(xs2.back().x(), xs2.back().y(), uz(random));
    }
    // uGIMP needs the particle's domain inside the grid's sides, as the solver keeps it.
    if (GetParam() == "uGIMP")
        for (std::size_t q = 0; q < xs2.size(); ++q) {
            xs2[q] = xs2[q].cwiseMax(Eigen::Vector2d(-1 + 0.125, 2 + 0.0625)).cwiseMin(Eigen::Vector2d(3 - 0.125, 4.5 - 0.0625));
            xs3[q].head<2>() = xs2[q];
        }
    const ShapeWeights<2> w2 = weightsAt<2>(GetParam(), plane, xs2);
    const ShapeWeights<3> w3 = weightsAt<3>(GetParam(), slab, xs3);
    for (std::size_t q = 0; q < xs2.size(); ++q) {
        std::map<int, double> N2, N3;
        std::map<int, Eigen::Vector2d> G2, G3;
        for (int a = 0; a < w2.stride; ++a) {
            const std::size_t k = q * w2.stride + a;
            if (w2.node[k] < 0) continue;
            N2[w2.node[k]] += w2.N[k];
            G2.try_emplace(w2.node[k], Eigen::Vector2d::Zero()).first->second += w2.dN[k];  // Eigen leaves a default one unset
        }
        for (int a = 0; a < w3.stride; ++a) {
            const std::size_t k = q * w3.stride + a;
            if (w3.node[k] < 0) continue;
            const auto i = slab.nodeIndex(w3.node[k]);
            const int n = plane.node(i[0], i[1]);
            N3[n] += w3.N[k];
            G3.try_emplace(n, Eigen::Vector2d::Zero()).first->second += w3.dN[k].head<2>();
        }
        for (const auto& [n, N] : N2) {
            EXPECT_NEAR(N3[n], N, 1e-12) << GetParam() << " particle " << q;
            EXPECT_NEAR((G3[n] - G2[n]).norm(), 0.0, 1e-10) << GetParam() << " particle " << q;
        }
        for (const auto& [n, N] : N3) EXPECT_TRUE(N2.count(n) || N == 0.0) << GetParam() << " particle " << q;
    }
}

INSTANTIATE_TEST_SUITE_P(AllShapes, ThreeDShapes, ::testing::Values("bilinear", "uGIMP", "quadraticBSpline"));

TEST(ThreeDShapesBSpline, inertiaTensorIsAQuarterCellSquaredInside)
{
    // APIC's D_p = sum N (x_i - x_p)(x_i - x_p)^T = h^2/4 I for quadratic B-splines (Jiang et al. 2015).
    const Vector3 h(0.5, 0.25, 0.4);
    const Grid<3> grid(Vector3::Zero(), h, {8, 8, 8});
    const ShapeWeights<3> w = weightsAt<3>("quadraticBSpline", grid, {Vector3(2.01, 0.97, 1.63)});
    Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
    for (int a = 0; a < w.stride; ++a) {
        const Vector3 r = grid.nodePosition(w.node[a]) - Vector3(2.01, 0.97, 1.63);
        D += w.N[a] * r * r.transpose();
    }
    const Eigen::Matrix3d expected = (0.25 * h.cwiseProduct(h)).asDiagonal();
    EXPECT_NEAR((D - expected).norm(), 0.0, 1e-12);
}

TEST(ThreeDSides, aDiscOpeningFreesItsNodesAndASlipSideItsNormalComponent)
{
    const Grid<3> grid(Vector3::Zero(), Vector3::Constant(0.1), {10, 4, 10});
    const Dictionary none = Dictionary::parse("type slip;", "constant/grid");
    const Dictionary outlet =
        Dictionary::parse("type fixed; opening { centre (0.5 0.5); radius 0.15; }", "constant/grid");
    GridSides<3>::Conditions conditions;
    for (int s = 0; s < 6; ++s) {
        const Dictionary& d = s == static_cast<int>(GridSide::bottom) ? outlet : none;
        conditions[s] = Registry<BoundaryCondition<3>>::select(d, d, static_cast<GridSide>(s));
    }
    const GridSides<3> sides(std::move(conditions), grid);
    EXPECT_TRUE(sides.hasOutlet());
    // The bottom's nodes within 0.15 of (x, z) = (0.5, 0.5): the centre and its 4 neighbours
    // at 0.1 (those at 0.1 sqrt 2 = 0.141 too): 9 of 121.
    EXPECT_EQ(sides.constrainedNodes(GridSide::bottom).size(), 121u - 9u);
    EXPECT_EQ(sides.condition(GridSide::back).normal(), Vector3(0, 0, -1));
    std::vector<Vector3> v(grid.nNodes(), Vector3(1, 2, 3));
    sides.constrain(v);
    const int backCorner = grid.node({5, 2, 0}), frontCorner = grid.node({5, 2, 10}), open = grid.node({5, 0, 5});
    EXPECT_EQ(v[backCorner], Vector3(1, 2, 0));
    EXPECT_EQ(v[frontCorner], Vector3(1, 2, 0));
    EXPECT_EQ(v[open], Vector3(1, 2, 3));
    EXPECT_EQ(v[grid.node({5, 0, 2})], Vector3::Zero());  // a fixed bottom node off the disc
    // A particle a little below the bottom under the disc leaves; one past the back wall is put back.
    Vector3 x(0.52, -0.01, 0.47), u(0, -1, 0);
    EXPECT_TRUE(sides.leftThroughOpening(grid, x));
    x = Vector3(0.3, 0.2, -0.02);
    u = Vector3(0, 0, -1);
    EXPECT_TRUE(sides.keepInsideWalls(grid, x, u));
    EXPECT_EQ(x, Vector3(0.3, 0.2, 0.0));
    EXPECT_EQ(u, Vector3::Zero());
}
