// Shape functions: partition of unity (sum N = 1) and of its gradient (sum grad N = 0)
// inside the grid, exact reproduction of a linear field (x = sum N_i x_i), and for uGIMP a
// gradient that stays continuous when a particle crosses a cell face (Bardenhagen & Kober
// 2004), where the bilinear one jumps by 1/h.
#include "dictionary/Dictionary.H"
#include "shapeFunctions/ShapeFunction.H"
#include "support/ShapeChecks.H"

#include <gtest/gtest.h>

#include <random>

using namespace gpic;

namespace {

ShapeWeights<2> weightsAt(const std::string& type, const Grid<2>& grid, const std::vector<Vector2>& xs)
{
    Dictionary dict;
    auto shape = Registry<ShapeFunction<2>>::select(type, dict, dict, "shapeFunction");
    Particles<2> p;
    const Vector2 half = 0.25 * grid.cellSize();  // 2 x 2 particles per cell
    for (const auto& x : xs) p.add(x, 1.0, 1.0, half, 0, 0);
    ShapeWeights<2> w;
    shape->evaluate(grid, p, w);
    return w;
}

class ShapeFunctionProperties : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(ShapeFunctionProperties, partitionOfUnityAndLinearReproduction)
{
    const Grid<2> grid(Vector2(-1, 2), Vector2(0.5, 0.25), 8, 8);
    std::mt19937 random(7);
    // Away from the edges by a particle half-size, where the support is complete.
    std::uniform_real_distribution<double> ux(-1 + 0.5, 3 - 0.5), uy(2 + 0.25, 4 - 0.25);
    std::vector<Vector2> xs;
    for (int k = 0; k < 200; ++k) xs.emplace_back(ux(random), uy(random));
    expectPartitionOfUnityAndLinearFields<2>(grid, weightsAt(GetParam(), grid, xs), xs);
}

INSTANTIATE_TEST_SUITE_P(AllShapes, ShapeFunctionProperties, ::testing::Values("bilinear", "uGIMP"));

TEST(ShapeFunctions, uGimpGradientIsContinuousAcrossACellFaceWhereBilinearJumps)
{
    const Grid<2> grid(Vector2(0, 0), Vector2(1, 1), 4, 4);
    const double eps = 1e-9;
    const std::vector<Vector2> xs{{2 - eps, 1.5}, {2 + eps, 1.5}};
    auto gradOfNode = [&](const ShapeWeights<2>& w, int q, int node) {
        for (int a = 0; a < w.stride; ++a)
            if (w.node[q * w.stride + a] == node) return w.dN[q * w.stride + a].x();
        return 0.0;
    };
    const int node = grid.node(2, 1);  // the node on the face x = 2
    const ShapeWeights<2> gimp = weightsAt("uGIMP", grid, xs);
    EXPECT_NEAR(gradOfNode(gimp, 0, node), gradOfNode(gimp, 1, node), 1e-6);
    const ShapeWeights<2> bilinear = weightsAt("bilinear", grid, xs);
    EXPECT_NEAR(gradOfNode(bilinear, 0, node) - gradOfNode(bilinear, 1, node), 0.5 * 2 / 1.0, 1e-6);
}

// Quadratic B-splines (QuadraticBSplineShape.H): the weights sum to one and their gradients
// to zero everywhere, the sides included; inside (2.5 cells from a side) they reproduce
// linear fields with the node positions and D_p = sum N (x_i - x_p)(x_i - x_p)^T = h^2/4 I
// (APIC's inertia-like tensor), and up to the sides about their Greville points; on a side only the side node has weight; the gradient is
// continuous across cell faces.
TEST(ShapeFunctions, quadraticBSplineSumsToOneUpToTheSidesAndIsExactInside)
{
    const Vector2 h(0.5, 0.25);
    const Grid<2> grid(Vector2(-1, 2), h, 8, 10);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> ux(-1, 3), uy(2, 4.5);
    std::vector<Vector2> xs;
    for (int k = 0; k < 400; ++k) xs.emplace_back(ux(random), uy(random));
    for (double s : {0.0, 1e-12, 0.5, 1.5, 2.5}) {  // on and near the sides, at the knots
        xs.emplace_back(-1 + s * h.x(), 3.0);
        xs.emplace_back(3 - s * h.x(), 3.0);
        xs.emplace_back(0.0, 2 + s * h.y());
        xs.emplace_back(0.0, 4.5 - s * h.y());
    }
    const ShapeWeights<2> w = weightsAt("quadraticBSpline", grid, xs);
    ASSERT_EQ(w.stride, 9);
    Dictionary none;
    const auto shape = Registry<ShapeFunction<2>>::select("quadraticBSpline", none, none, "shapeFunction");
    int inside = 0;
    for (std::size_t q = 0; q < xs.size(); ++q) {
        double sumN = 0;
        Vector2 sumGrad = Vector2::Zero(), reproduced = Vector2::Zero(), aboutCentres = Vector2::Zero();
        Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero(), D = Eigen::Matrix2d::Zero();
        for (int a = 0; a < w.stride; ++a) {
            const std::size_t k = q * w.stride + a;
            ASSERT_GE(w.node[k], 0);
            EXPECT_GE(w.N[k], 0.0);
            const Vector2 xi = grid.nodePosition(w.node[k]);
            sumN += w.N[k];
            sumGrad += w.dN[k];
            reproduced += w.N[k] * xi;
            aboutCentres += w.N[k] * shape->affineCentre(grid, w.node[k]);
            gradX += xi * w.dN[k].transpose();
            D += w.N[k] * (xi - xs[q]) * (xi - xs[q]).transpose();
        }
        EXPECT_NEAR(sumN, 1.0, 1e-12) << xs[q].transpose();
        EXPECT_NEAR(sumGrad.norm(), 0.0, 1e-10) << xs[q].transpose();
        // Linear fields everywhere about the Greville points (APIC's affine terms).
        EXPECT_NEAR((aboutCentres - xs[q]).norm(), 0.0, 1e-12) << xs[q].transpose();
        const Vector2 u = (xs[q] - grid.origin()).cwiseQuotient(h);
        if (u.x() < 2.5 || u.x() > 5.5 || u.y() < 2.5 || u.y() > 7.5) continue;
        ++inside;
        EXPECT_NEAR((reproduced - xs[q]).norm(), 0.0, 1e-12);
        EXPECT_NEAR((gradX - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-10);
        EXPECT_NEAR(D(0, 0), 0.25 * h.x() * h.x(), 1e-12);
        EXPECT_NEAR(D(1, 1), 0.25 * h.y() * h.y(), 1e-12);
        EXPECT_NEAR(D(0, 1), 0.0, 1e-12);
    }
    EXPECT_GT(inside, 20);
}

TEST(ShapeFunctions, quadraticBSplineHasTheStandardValuesInsideAndOnlyTheSideNodeOnASide)
{
    const Grid<2> grid(Vector2(0, 0), Vector2(1, 1), 8, 8);
    // On a node inside: 3/4 there, 1/8 at both neighbours (per axis).
    const ShapeWeights<2> w = weightsAt("quadraticBSpline", grid, {{4.0, 4.0}, {0.0, 4.0}, {8.0, 0.0}});
    for (int a = 0; a < 9; ++a) {
        const Vector2 xi = grid.nodePosition(w.node[a]);
        const double wx = xi.x() == 4.0 ? 0.75 : 0.125, wy = xi.y() == 4.0 ? 0.75 : 0.125;
        EXPECT_NEAR(w.N[a], wx * wy, 1e-14);
    }
    // On the left side (x = 0) and in the corner (8, 0): the side's nodes alone.
    for (int q = 1; q <= 2; ++q)
        for (int a = 0; a < 9; ++a) {
            const std::size_t k = static_cast<std::size_t>(q * 9 + a);
            const Vector2 xi = grid.nodePosition(w.node[k]);
            const bool onSide = q == 1 ? xi.x() == 0.0 : (xi.x() == 8.0 && xi.y() == 0.0);
            if (!onSide) {
                EXPECT_EQ(w.N[k], 0.0) << q << ": " << xi.transpose();
            }
        }
}

TEST(ShapeFunctions, quadraticBSplineGradientIsContinuousAcrossFacesAndKnots)
{
    const Grid<2> grid(Vector2(0, 0), Vector2(1, 1), 8, 8);
    const double eps = 1e-9;
    // A cell face (x = 3), a knot between cells (x = 3.5) and the first knots off a side (1.5, 2.5).
    for (double x : {3.0, 3.5, 1.5, 2.5, 0.5}) {
        const ShapeWeights<2> w = weightsAt("quadraticBSpline", grid, {{x - eps, 4.5}, {x + eps, 4.5}});
        for (int n = 0; n <= 8; ++n) {
            const int node = grid.node(n, 4);
            double g[2] = {0, 0};
            for (int q = 0; q < 2; ++q)
                for (int a = 0; a < 9; ++a)
                    if (w.node[q * 9 + a] == node) g[q] = w.dN[q * 9 + a].x();
            EXPECT_NEAR(g[0], g[1], 1e-6) << "x = " << x << ", node " << n;
        }
    }
}

TEST(ShapeFunctions, quadraticBSplineIsLinearAcrossAnAxisOfOneCell)
{
    const Grid<2> grid(Vector2(0, 0), Vector2(1, 0.5), 6, 1);  // a bar one cell thick
    const ShapeWeights<2> w = weightsAt("quadraticBSpline", grid, {{2.3, 0.1}, {5.9, 0.45}});
    for (int q = 0; q < 2; ++q) {
        double sumN = 0, sumY = 0;
        for (int a = 0; a < 9; ++a) {
            const std::size_t k = static_cast<std::size_t>(q * 9 + a);
            if (w.node[k] < 0) continue;
            sumN += w.N[k];
            sumY += w.N[k] * grid.nodePosition(w.node[k]).y();
        }
        EXPECT_NEAR(sumN, 1.0, 1e-12);
        EXPECT_NEAR(sumY, q == 0 ? 0.1 : 0.45, 1e-12);
    }
}

// Axisymmetric uGIMP (Nairn & Guilkey 2015): the weights are averages over the particle's
// ring, weighted by r. They still sum to one and reproduce the ring's centroid
// int r^2 dr / int r dr; the radial gradients reproduce d r / d r = 1; the hoop weights
// <N_i / r> sum to the inverse mean radius and reproduce <r / r> = 1. Near the axis the ring
// is cut at r = 0. Far from the axis the weights tend to plane strain's.
TEST(ShapeFunctions, axisymmetricUGimpAveragesOverTheRing)
{
    Grid<2> grid(Vector2(0, 0), Vector2(0.1, 0.1), 10, 10);
    grid.setAxisymmetric(true);
    const double l = 0.025;  // 2 x 2 particles per cell
    // Inside, next to the axis (the domain touches it), across a face, and across the axis.
    const std::vector<Vector2> xs{{0.437, 0.52}, {0.025, 0.31}, {0.098, 0.66}, {0.01, 0.4}};
    const ShapeWeights<2> w = weightsAt("uGIMP", grid, xs);
    ASSERT_EQ(w.hoop.size(), w.N.size());
    for (std::size_t q = 0; q < xs.size(); ++q) {
        const double r1 = std::max(xs[q].x() - l, 0.0), r2 = xs[q].x() + l;
        const double ring = 0.5 * (r2 * r2 - r1 * r1);
        double sumN = 0, sumT = 0, rN = 0, rT = 0, rG = 0, zN = 0;
        Vector2 sumGrad = Vector2::Zero();
        for (int a = 0; a < w.stride; ++a) {
            const std::size_t k = q * w.stride + a;
            if (w.node[k] < 0) continue;
            const Vector2 xi = grid.nodePosition(w.node[k]);
            sumN += w.N[k];
            sumT += w.hoop[k];
            sumGrad += w.dN[k];
            rN += w.N[k] * xi.x();
            rT += w.hoop[k] * xi.x();
            rG += w.dN[k].x() * xi.x();
            zN += w.N[k] * xi.y();
        }
        EXPECT_NEAR(sumN, 1.0, 1e-12) << q;
        EXPECT_NEAR(sumT, (r2 - r1) / ring, 1e-9 * sumT) << q;   // 1 / mean radius of the ring
        EXPECT_NEAR(rN, (r2 * r2 * r2 - r1 * r1 * r1) / 3 / ring, 1e-12) << q;
        EXPECT_NEAR(rT, 1.0, 1e-12) << q;
        EXPECT_NEAR(rG, 1.0, 1e-12) << q;
        EXPECT_NEAR(sumGrad.y(), 0.0, 1e-10) << q;
        EXPECT_NEAR(zN, xs[q].y(), 1e-12) << q;
        EXPECT_NEAR(sumGrad.x(), 0.0, 1e-10) << q;
    }
    // The same particle 300 cells out: N and r_p T_i within 1e-4 of plane strain's N.
    Grid<2> far(Vector2(0, 0), Vector2(0.1, 0.1), 400, 10);
    far.setAxisymmetric(true);
    Grid<2> flat(Vector2(0, 0), Vector2(0.1, 0.1), 400, 10);
    const ShapeWeights<2> ringW = weightsAt("uGIMP", far, {{30.437, 0.52}});
    const ShapeWeights<2> flatW = weightsAt("uGIMP", flat, {{30.437, 0.52}});
    for (int a = 0; a < ringW.stride; ++a) {
        EXPECT_NEAR(ringW.N[a], flatW.N[a], 1e-4);
        EXPECT_NEAR(ringW.hoop[a] * 30.437, flatW.N[a], 1e-4);
    }
    EXPECT_TRUE(flatW.hoop.empty());
}
