// The decomposition of a case into subdomains (libpic/parallel/Decomposition.H): the owner of
// every cell by the methods of system/decomposeParDict, against what each promises.
// - simple: n blocks along each axis, equal in cells to within one layer;
// - hierarchical: slabs of equal weight, each cut again by its own weight: a column of particles in the left third of the
//   grid split four ways gives each subdomain a quarter of the particles (simple: all in one
//   or two subdomains);
// - scotch: subdomains of equal particle count to 10 %, each one connected piece of cells,
//   the same partition on a second call;
// - decomposeParDict mistakes (counts that do not multiply to numberOfSubdomains, an unknown
//   method, an axis twice in `order`) refused naming the keyword; cellDecomposition files
//   read back as written, a wrong cell count refused.
#include "dictionary/Dictionary.H"
#include "core/error.H"
#include "parallel/CellDecompositionFile.H"
#include "parallel/Decomposition.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <queue>

using namespace gpic;

namespace {

DecompositionSettings settings(const std::string& text, int dimension)
{
    return readDecomposeParDict(Dictionary::parse(text, "system/decomposeParDict"), dimension);
}

//- Particles per cell: 8 in every cell with i < columnWidth, none elsewhere.
template <int D> std::vector<int> column(const Grid<D>& grid, int columnWidth)
{
    std::vector<int> perCell(static_cast<std::size_t>(grid.nCells()), 0);
    for (int c = 0; c < grid.nCells(); ++c)
        if (c % grid.cells(0) < columnWidth) perCell[c] = 8;
    return perCell;
}

std::vector<long> particlesBySubdomain(const std::vector<int>& owner, const std::vector<int>& perCell, int n)
{
    std::vector<long> count(static_cast<std::size_t>(n), 0);
    for (std::size_t c = 0; c < owner.size(); ++c) count[owner[c]] += perCell[c];
    return count;
}

std::string errorOf(const std::string& text, int dimension)
{
    try {
        settings(text, dimension);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Decomposition, simpleCutsEqualBlocksOfCells)
{
    const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1), 10, 6);
    const auto owner = decomposeCells(grid, std::vector<int>(60, 1), settings("numberOfSubdomains 6; method simple; simpleCoeffs { n (2 3); }", 2));
    // Cell (i, j) is in block (i / 5, j / 2): owner i / 5 + 2 (j / 2).
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 10; ++i) EXPECT_EQ(owner[i + 10 * j], i / 5 + 2 * (j / 2)) << i << ' ' << j;
}

TEST(Decomposition, hierarchicalBalancesTheParticlesNotTheCells)
{
    const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1), 60, 20);
    const auto perCell = column(grid, 20);  // 20 x 20 cells of 8 particles: 3200
    const auto owner = decomposeCells(grid, perCell, settings("numberOfSubdomains 4; method hierarchical; hierarchicalCoeffs { n (4 1); }", 2));
    for (long n : particlesBySubdomain(owner, perCell, 4)) EXPECT_EQ(n, 800);
    const auto blocks = decomposeCells(grid, perCell, settings("numberOfSubdomains 4; method simple; simpleCoeffs { n (4 1); }", 2));
    const auto counts = particlesBySubdomain(blocks, perCell, 4);
    EXPECT_EQ(*std::max_element(counts.begin(), counts.end()), 2400);  // cells 0..14 and 15..29
    // Without particles the weights fall back to cells: equal slabs.
    const auto empty = decomposeCells(grid, std::vector<int>(1200, 0), settings("numberOfSubdomains 4; method hierarchical; hierarchicalCoeffs { n (4 1); }", 2));
    EXPECT_EQ(std::count(empty.begin(), empty.end(), 0), 300);
}

TEST(Decomposition, hierarchicalCutsEachSlabByItsOwnWeight)
{
    // 3D: a heap in one corner (i < 20, k < 20 - i): cut along x into 2, each half along z
    // into 2. A cut falls between cell layers: within half a layer (at most 7 % here).
    const Grid<3> grid(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.1, 0.1), {40, 4, 40});
    std::vector<int> perCell(static_cast<std::size_t>(grid.nCells()), 0);
    long total = 0;
    for (int k = 0; k < 40; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 40; ++i)
                if (i < 20 && k < 20 - i) perCell[i + 40 * (j + 4 * k)] = 8, total += 8;
    const auto owner = decomposeCells(grid, perCell, settings("numberOfSubdomains 4; method hierarchical; hierarchicalCoeffs { n (2 1 2); order xzy; }", 3));
    const auto counts = particlesBySubdomain(owner, perCell, 4);
    for (long n : counts) EXPECT_NEAR(static_cast<double>(n), total / 4.0, 0.08 * total / 4.0) << n;
}

TEST(Decomposition, scotchGivesConnectedSubdomainsOfEqualParticles)
{
    if (!scotchAvailable()) GTEST_SKIP() << "a build without Scotch";
    const Grid<3> grid(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.1, 0.1), {24, 6, 12});
    const auto perCell = column(grid, 8);
    const auto s = settings("numberOfSubdomains 4; method scotch;", 3);
    const auto owner = decomposeCells(grid, perCell, s);
    const auto counts = particlesBySubdomain(owner, perCell, 4);
    const double mean = 8.0 * 8 * 6 * 12 / 4;
    for (long n : counts) EXPECT_NEAR(static_cast<double>(n), mean, 0.1 * mean) << n;
    EXPECT_EQ(owner, decomposeCells(grid, perCell, s));  // repeatable
    // Each subdomain one piece: a walk over face neighbours of equal owner reaches all its cells.
    for (int part = 0; part < 4; ++part) {
        const auto first = std::find(owner.begin(), owner.end(), part);
        ASSERT_NE(first, owner.end());
        std::vector<char> seen(owner.size(), 0);
        std::queue<int> next;
        next.push(static_cast<int>(first - owner.begin()));
        seen[next.front()] = 1;
        long reached = 0;
        while (!next.empty()) {
            const int c = next.front();
            next.pop();
            ++reached;
            const int i = c % 24, j = (c / 24) % 6, k = c / 144;
            const int step[3] = {1, 24, 144}, at[3] = {i, j, k}, size[3] = {24, 6, 12};
            for (int a = 0; a < 3; ++a)
                for (int d : {-1, 1})
                    if (at[a] + d >= 0 && at[a] + d < size[a]) {
                        const int n = c + d * step[a];
                        if (!seen[n] && owner[n] == part) seen[n] = 1, next.push(n);
                    }
        }
        EXPECT_EQ(reached, std::count(owner.begin(), owner.end(), part)) << "subdomain " << part;
    }
}

TEST(Decomposition, mistakesInDecomposeParDictAreRefusedByKeyword)
{
    EXPECT_NE(errorOf("numberOfSubdomains 4; method simple; simpleCoeffs { n (2 3); }", 2).find("multiply to 6, not numberOfSubdomains 4"), std::string::npos);
    EXPECT_NE(errorOf("numberOfSubdomains 4; method simple; simpleCoeffs { n (2 2); }", 3).find("expected 3 counts"), std::string::npos);
    EXPECT_NE(errorOf("numberOfSubdomains 4; method metis;", 2).find("simple"), std::string::npos);
    EXPECT_NE(errorOf("numberOfSubdomains 2; method hierarchical; hierarchicalCoeffs { n (2 1); order xx; }", 2).find("order"), std::string::npos);
    EXPECT_NE(errorOf("numberOfSubdomains 0; method simple;", 2).find("numberOfSubdomains >= 1"), std::string::npos);
    const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1), 3, 3);
    EXPECT_THROW(decomposeCells(grid, std::vector<int>(9, 1), settings("numberOfSubdomains 4; method simple; simpleCoeffs { n (4 1); }", 2)), InputError);
}

TEST(Decomposition, cellDecompositionFileReadsBackAsWritten)
{
    const std::string path = (std::filesystem::temp_directory_path() / "gpicCellDecomposition").string();
    CellDecomposition d{3, {}};
    for (int c = 0; c < 100; ++c) d.owner.push_back(c % 3);
    writeCellDecomposition(path, d);
    const auto back = readCellDecomposition(path, 100);
    EXPECT_EQ(back.subdomains, 3);
    EXPECT_EQ(back.owner, d.owner);
    EXPECT_THROW(readCellDecomposition(path, 99), InputError);
    std::filesystem::remove(path);
}
