// Shape functions: partition of unity (sum N = 1) and of its gradient (sum grad N = 0)
// inside the grid, exact reproduction of a linear field (x = sum N_i x_i), and for uGIMP a
// gradient that stays continuous when a particle crosses a cell face (Bardenhagen & Kober
// 2004), where the bilinear one jumps by 1/h.
#include "dictionary/Dictionary.H"
#include "shapeFunctions/ShapeFunction.H"

#include <gtest/gtest.h>

#include <random>

using namespace gpic;

namespace {

ShapeWeights weightsAt(const std::string& type, const Grid& grid, const std::vector<Vector2>& xs)
{
    Dictionary dict;
    auto shape = Registry<ShapeFunction>::select(type, dict, dict, "shapeFunction");
    Particles p;
    const Vector2 half = 0.25 * grid.cellSize();  // 2 x 2 particles per cell
    for (const auto& x : xs) p.add(x, 1.0, 1.0, half, 0, 0);
    ShapeWeights w;
    shape->evaluate(grid, p, w);
    return w;
}

class ShapeFunctionProperties : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(ShapeFunctionProperties, partitionOfUnityAndLinearReproduction)
{
    const Grid grid(Vector2(-1, 2), Vector2(0.5, 0.25), 8, 8);
    std::mt19937 random(7);
    // Away from the edges by a particle half-size, where the support is complete.
    std::uniform_real_distribution<double> ux(-1 + 0.5, 3 - 0.5), uy(2 + 0.25, 4 - 0.25);
    std::vector<Vector2> xs;
    for (int k = 0; k < 200; ++k) xs.emplace_back(ux(random), uy(random));
    const ShapeWeights w = weightsAt(GetParam(), grid, xs);
    for (std::size_t q = 0; q < xs.size(); ++q) {
        double sumN = 0;
        Vector2 sumGrad = Vector2::Zero(), reproduced = Vector2::Zero();
        Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero();
        for (int a = 0; a < w.stride; ++a) {
            const std::size_t k = q * w.stride + a;
            if (w.node[k] < 0) continue;
            sumN += w.N[k];
            sumGrad += w.dN[k];
            reproduced += w.N[k] * grid.nodePosition(w.node[k]);
            gradX += grid.nodePosition(w.node[k]) * w.dN[k].transpose();
        }
        EXPECT_NEAR(sumN, 1.0, 1e-12);
        EXPECT_NEAR(sumGrad.norm(), 0.0, 1e-10);
        EXPECT_NEAR((reproduced - xs[q]).norm(), 0.0, 1e-12);
        // grad of x is the identity: strain of a linear velocity field is exact.
        EXPECT_NEAR((gradX - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-10);
    }
}

INSTANTIATE_TEST_SUITE_P(AllShapes, ShapeFunctionProperties, ::testing::Values("bilinear", "uGIMP"));

TEST(ShapeFunctions, uGimpGradientIsContinuousAcrossACellFaceWhereBilinearJumps)
{
    const Grid grid(Vector2(0, 0), Vector2(1, 1), 4, 4);
    const double eps = 1e-9;
    const std::vector<Vector2> xs{{2 - eps, 1.5}, {2 + eps, 1.5}};
    auto gradOfNode = [&](const ShapeWeights& w, int q, int node) {
        for (int a = 0; a < w.stride; ++a)
            if (w.node[q * w.stride + a] == node) return w.dN[q * w.stride + a].x();
        return 0.0;
    };
    const int node = grid.node(2, 1);  // the node on the face x = 2
    const ShapeWeights gimp = weightsAt("uGIMP", grid, xs);
    EXPECT_NEAR(gradOfNode(gimp, 0, node), gradOfNode(gimp, 1, node), 1e-6);
    const ShapeWeights bilinear = weightsAt("bilinear", grid, xs);
    EXPECT_NEAR(gradOfNode(bilinear, 0, node) - gradOfNode(bilinear, 1, node), 0.5 * 2 / 1.0, 1e-6);
}
