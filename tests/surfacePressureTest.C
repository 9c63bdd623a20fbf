// The surfacePressure load (constant/loads): which particles carry a pressure on a segment of
// a body's surface, that their forces add up to p times the segment length along the inward
// normal, that an arc or a polyline is loaded piece by piece (the resultant of a pressure
// inside a quarter ring, plane strain and axisymmetric), that bad segments are refused with the file, line and what is wrong, and that an
// elastic column loaded over its whole top settles to the one-dimensional (oedometric)
// state of plane strain:
//     sigma22 = -p,   sigma11 = sigma33 = nu/(1 - nu) sigma22,   eps22 = -p / (K + 4G/3).
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "grid/Grid.H"
#include "loads/SurfacePressure.H"
#include "support/CaseRunner.H"

#include <cmath>
#include <numeric>

using namespace gpic;
using namespace gpic::test;

namespace {

//- A 1 x 0.5 m block of 2 x 2 particles per 0.1 m cell (body "block") in a 1.5 x 1 m grid.
struct Block {
    Grid<2> grid{Vector2(0, 0), Vector2(0.1, 0.1), 15, 10};
    Particles<2> p;
    std::vector<std::string> bodies{"block"};

    Block()
    {
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 20; ++i)
                p.add(Vector2(0.025 + 0.05 * i, 0.025 + 0.05 * j), 1.0, 0.0025, Vector2(0.025, 0.025), 0, 0);
    }
};

//- The load of constant/loads sub-dictionary `name` in `text`, initialised on `block`.
std::unique_ptr<ParticleLoad<2>> load(const std::string& text, const Block& block)
{
    const Dictionary dict = Dictionary::parse(text, "constant/loads");
    auto l = ParticleLoad<2>::New(dict.subDict("pad"));
    l->initialise(block.p, block.grid, block.bodies);
    return l;
}

Vector2 totalForce(const ParticleLoad<2>& l, const Particles<2>& p, double t, std::size_t* loaded = nullptr)
{
    std::vector<Vector2> f(p.size(), Vector2::Zero());
    l.addForces(t, p, f);
    if (loaded) *loaded = std::count_if(f.begin(), f.end(), [](const Vector2& v) { return v.norm() > 0; });
    return std::accumulate(f.begin(), f.end(), Vector2(Vector2::Zero()));
}

//- The InputError message of loading `text`, or "" when it is accepted.
std::string refusal(const std::string& text, const Block& block)
{
    try {
        load(text, block);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(SurfacePressure, forcesAddUpToPressureTimesLengthAlongTheInwardNormal)
{
    const Block block;
    // The top (y = 0.5) from x = 0.13 to 0.71: the ends cut particle domains (0.05 wide).
    auto top = load("pad { type surfacePressure; body block; from (0.13 0.5); to (0.71 0.5); pressure 2e3; }", block);
    std::size_t loaded = 0;
    const Vector2 f = totalForce(*top, block.p, 0.0, &loaded);
    EXPECT_NEAR(f.y(), -2e3 * 0.58, 1e-12 * 2e3);  // pushes down, p |to - from| exactly
    EXPECT_NEAR(f.x(), 0.0, 1e-12 * 2e3);
    // Only the top row: 0.10-0.15, ..., 0.70-0.75 are the 13 domains the segment covers.
    EXPECT_EQ(loaded, 13u);
    for (std::size_t q : static_cast<const SurfacePressure&>(*top).loaded())
        EXPECT_DOUBLE_EQ(block.p.x[q].y(), 0.475);

    // The left side (x = 0) walked downwards: the load pushes in +x whatever the walk.
    auto side = load("pad { type surfacePressure; body block; from (0 0.4); to (0 0.05); pressure 1e3; }", block);
    const Vector2 g = totalForce(*side, block.p, 0.0, &loaded);
    EXPECT_NEAR(g.x(), 1e3 * 0.35, 1e-12 * 1e3);
    EXPECT_NEAR(g.y(), 0.0, 1e-12 * 1e3);
    EXPECT_EQ(loaded, 7u);
}

TEST(SurfacePressure, rampAndTableGiveThePressureInTime)
{
    const Block block;
    auto ramped = load("pad { type surfacePressure; body block; from (0 0.5); to (1 0.5); pressure 4e3; rampTime 2; }", block);
    EXPECT_NEAR(totalForce(*ramped, block.p, 0.0).y(), 0.0, 1e-9);
    EXPECT_NEAR(totalForce(*ramped, block.p, 0.5).y(), -1e3, 1e-9);   // a quarter of the ramp
    EXPECT_NEAR(totalForce(*ramped, block.p, 5.0).y(), -4e3, 1e-9);   // held after the ramp
    auto table = load("pad { type surfacePressure; body block; from (0 0.5); to (1 0.5); "
                      "pressure table ((0 0) (1 3e3) (2 1e3)); }", block);
    EXPECT_NEAR(totalForce(*table, block.p, 1.5).y(), -2e3, 1e-9);
}

TEST(SurfacePressure, segmentsOffTheSurfaceAreRefused)
{
    const Block block;
    const std::string head = "pad { type surfacePressure; pressure 1e3; ";
    // Each refusal names the file and line of the load and what is wrong.
    const std::string wrongBody = refusal(head + "body soil; from (0 0.5); to (1 0.5); }", block);
    EXPECT_NE(wrongBody.find("constant/loads:1"), std::string::npos) << wrongBody;
    EXPECT_NE(wrongBody.find("valid choices: block"), std::string::npos) << wrongBody;
    const std::string above = refusal(head + "body block; from (0 0.8); to (1 0.8); }", block);
    EXPECT_NE(above.find("within one cell"), std::string::npos) << above;
    const std::string inside = refusal(head + "body block; from (0 0.25); to (1 0.25); }", block);
    EXPECT_NE(inside.find("not on the surface"), std::string::npos) << inside;
    const std::string overhang = refusal(head + "body block; from (0.5 0.5); to (1.3 0.5); }", block);
    EXPECT_NE(overhang.find("leaves body 'block' between (1 0.5) and (1.3 0.5)"), std::string::npos) << overhang;
    const std::string point = refusal(head + "body block; from (0.5 0.5); to (0.5 0.5); }", block);
    EXPECT_NE(point.find("zero length"), std::string::npos) << point;
}

//- A quarter ring (a = 0.1, b = 0.2 m about the origin) of 2 x 2 particles per 0.01 m cell.
struct QuarterRing : Block {
    QuarterRing(bool axisymmetric)
    {
        grid = Grid<2>(Vector2(0, 0), Vector2(0.01, 0.01), 25, 25);
        grid.setAxisymmetric(axisymmetric);
        bodies = {"shell"};
        p = Particles<2>();
        for (int j = 0; j < 50; ++j)
            for (int i = 0; i < 50; ++i) {
                const Vector2 x(0.0025 + 0.005 * i, 0.0025 + 0.005 * j);
                if (x.norm() >= 0.1 && x.norm() <= 0.2) p.add(x, 1.0, 2.5e-5, Vector2(0.0025, 0.0025), 0, 0);
            }
    }
};

TEST(SurfacePressure, anArcOrAPolylineIsLoadedPieceByPiece)
{
    // The inside of the quarter ring: the pressure pushes the body away from the centre.
    const QuarterRing plane(false), axisymmetric(true);
    const std::string arc = "pad { type surfacePressure; body shell; pressure 1e3; "
                            "arc { centre (0 0); radius 0.1; startAngle 0; endAngle 90; } }";
    // Plane strain: p R (1, 1), the integral of the inward normal over the arc (exact on chords).
    auto flat = load(arc, plane);
    EXPECT_NEAR((totalForce(*flat, plane.p, 0.0) - Vector2(100, 100)).norm(), 0, 1e-9);
    const auto& loaded = static_cast<const SurfacePressure&>(*flat);
    for (std::size_t k = 0; k < loaded.loaded().size(); ++k) {
        const Vector2 x = plane.p.x[loaded.loaded()[k]];
        EXPECT_LT(x.norm(), 0.1 + 0.01) << "a loaded particle away from the arc";
        EXPECT_LT(loaded.outwardNormals()[k].dot(x.normalized()), -0.99);  // towards the centre
    }
    // Axisymmetric rings: p R^2 (pi/4, 1/2) per radian, to the chords' 1-degree error.
    auto rings = load(arc, axisymmetric);
    const Vector2 f = totalForce(*rings, axisymmetric.p, 0.0);
    EXPECT_NEAR(f.x(), 1e3 * 0.01 * M_PI / 4, 1e-4 * f.x());
    EXPECT_NEAR(f.y(), 1e3 * 0.01 / 2, 1e-4 * f.y());

    // A polyline along the ring's two straight ends: the bottom (z = 0) and the axis side.
    auto ends = load("pad { type surfacePressure; body shell; pressure 1e3; "
                     "points ((0.2 0) (0.1 0)); }", plane);
    EXPECT_NEAR((totalForce(*ends, plane.p, 0.0) - Vector2(0, 100)).norm(), 0, 1e-9);
    auto corner = load("pad { type surfacePressure; body shell; pressure 1e3; "
                       "points ((0.2 0) (0.1 0) (0.1 0.02)); }", plane);
    // 0.1 m of the bottom pushed up, then 0.02 m of the inner side pushed in +x: below
    // y = 0.02 the particles next to x = 0.1 have their faces on that line.
    const Vector2 g = totalForce(*corner, plane.p, 0.0);
    EXPECT_NEAR(g.y(), 100, 1e-9);
    EXPECT_NEAR(g.x(), 20, 1e-9);

    // Exactly one loaded part, and no zero-length piece.
    const std::string both = refusal("pad { type surfacePressure; body shell; pressure 1; from (0 0.1); to (0.1 0); "
                                     "points ((0.2 0) (0.1 0)); }", plane);
    EXPECT_NE(both.find("exactly one loaded part"), std::string::npos) << both;
    const std::string repeated = refusal("pad { type surfacePressure; body shell; pressure 1; "
                                         "points ((0.2 0) (0.2 0) (0.1 0)); }", plane);
    EXPECT_NE(repeated.find("zero length"), std::string::npos) << repeated;
    const std::string turn = refusal("pad { type surfacePressure; body shell; pressure 1; "
                                     "arc { centre (0 0); radius 0.1; startAngle 0; endAngle 0; } }", plane);
    EXPECT_NE(turn.find("endAngle"), std::string::npos) << turn;
}

TEST(SurfacePressure, loadedColumnSettlesToTheOedometricState)
{
    // A 1 x 2 m elastic column between smooth walls on a fixed base, no gravity, loaded by
    // p = 10 kPa over its whole top (ramped over 0.1 s), damped (alpha = 0.8) to rest.
    const double p = 1e4, E = 1e7, nu = 0.3, H = 2.0;
    const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu)), M = K + 4 * G / 3;
    ScratchDir scratch("surfacePressure");
    const fs::path dir = scratch.path() / "column";
    fs::create_directories(dir / "system");
    fs::create_directories(dir / "constant");
    std::ofstream(dir / "system/controlDict")
        << "endTime 1;\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\nwriteControl adjustableRunTime;\n"
           "writeInterval 1;\ndamping 0.8;\n";
    std::ofstream(dir / "constant/grid")
        << "origin (0 0);\ncellSize 0.1;\nnCells (10 20);\n"
           "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } }\n";
    std::ofstream(dir / "constant/materials")
        << "soil { type linearElastic; rho 2000; E " << E << "; nu " << nu << "; }\n";
    std::ofstream(dir / "constant/bodies")
        << "column { material soil; particlesPerCell 2; shape { type rectangle; min (0 0); max (1 " << H << "); } }\n";
    std::ofstream(dir / "constant/loads")
        << "top { type surfacePressure; body column; from (0 2); to (1 2); pressure " << p << "; rampTime 0.1; }\n";
    const auto simulation = runAndKeep(dir);
    const Particles<2>& s = simulation->solver().particles();

    // The particles carry the load at their centres, which the shape functions share between
    // the two node rows of the top cell: the surface row takes N = (y_q - 1.9)/0.1 of it
    // (3/4 at the start, less as the column settles), so the top cell carries that fraction
    // of p and every cell below the full p. Below the top cell the state is the closed form
    // to 0.5 % of p and of the oedometric strain. Measured: 7e-4 for both, the size of the
    // strain itself (increments are taken on the settled geometry); the top cell 4e-4.
    double yTop = 0;  // the loaded row, now
    for (std::size_t q = 0; q < s.size(); ++q) yTop = std::max(yTop, s.x[q].y());
    const double share = (yTop - (H - 0.1)) / 0.1;
    double stressError = 0, strainError = 0, topCell = 0;
    for (std::size_t q = 0; q < s.size(); ++q) {
        if (s.x0[q].y() > H - 0.1) {
            topCell = std::max(topCell, std::abs(s.sigma[q][YY] + share * p));
            continue;
        }
        stressError = std::max({stressError, std::abs(s.sigma[q][YY] + p),
                                std::abs(s.sigma[q][XX] + nu / (1 - nu) * p)});
        strainError = std::max(strainError, std::abs(s.eps[q][YY] + p / M) * M / p);
    }
    EXPECT_LT(stressError / p, 5e-3);
    EXPECT_LT(strainError, 5e-3);
    EXPECT_LT(topCell / p, 5e-3);
    EXPECT_LT(simulation->solver().maxParticleSpeed(), 1e-4);
}
