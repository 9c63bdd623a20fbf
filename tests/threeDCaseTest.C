// 3D cases from their files, through picInit and picSolver as a user runs them (the reader
// picks the dimension from constant/grid):
// - plane strain recovered: a confined column settling under gravity, run as a plane case
//   and as a 3D slab one cell thick between symmetry faces, ends with the same stresses,
//   positions and velocities to round-off (1e-9 of the largest stress);
// - a block falling freely in 3D (gravity along -x3) drops by g t^2 / 2 to within the
//   explicit step's own error, g t dt, and keeps its place across gravity (bodyMotion);
// - a 3D run stopped and restarted from its time directory ends with the same particle file,
//   byte for byte, as the straight run; the time directories hold 3D particles and grids;
// - the 3D bodies (box, sphere, cylinder on a slanted axis, extruded polygon) hold the
//   volume of their closed forms, and a geostatic initial stress is vertical along x3;
// - what is plane-only (polar materials, an axisymmetric grid, plane shapes) is refused in a
//   3D case with one line saying so;
// - picFieldMap maps the particles a slice cuts; toolFill counts the material in a region the
//   tool carries;
// - every scheme, transfer, shape function, the cell-mean dilatation, damping and mass
//   scaling of the slab give the plane run; the stages geostaticFill (along -x3), openGate
//   (a disc in the floor), moveTool and excavate; a rigid body turned about a slanted axis
//   exactly; a rigid plate's oedometric force (read back by picForces), and its settlement under a dead load when it is
//   load-driven (weighted); the column collapse as a slab.
#include "case/CaseFiles.H"
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

using namespace gpic;
using namespace gpic::test;

namespace {

//- The files of a case, each a dictionary's text.
struct Scene {
    std::string grid, materials, bodies, g;
    std::string control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.05;\ndeltaT 1e-4;\n"
                          "writeControl adjustableRunTime;\nwriteInterval 0.025;\n";
    std::string schemes;
};

void write(const fs::path& dir, const Scene& s)
{
    writeDictionary(dir / "constant/grid", s.grid);
    writeDictionary(dir / "constant/materials", s.materials);
    writeDictionary(dir / "constant/bodies", s.bodies);
    if (!s.g.empty()) writeDictionary(dir / "constant/g", s.g);
    writeDictionary(dir / "system/controlDict", s.control);
    if (!s.schemes.empty()) writeDictionary(dir / "system/mpmSchemes", s.schemes);
}

//- A grid open on all six sides.
const char* const freeSides = "boundaries { left { type free; } right { type free; } bottom { type free; } top { type free; } "
                              "back { type free; } front { type free; } }\n";

const char* const sand = "sand { type mohrCoulomb; rho 2000; E 2e6; nu 0.3; phi 30; psi 0; c 0; }\n";

//- A column of sand 0.1 m wide and high in a box with smooth walls, settling under gravity:
//  the plane case, or the slab of one 0.02 m cell between symmetry faces.
Scene column(int dimensions)
{
    Scene s;
    s.materials = sand;
    if (dimensions == 2) {
        s.grid = "origin (0 0); cellSize 0.02; nCells (5 6);\n"
                 "boundaries { left { type symmetry; } right { type symmetry; } bottom { type fixed; } "
                 "top { type free; } }\n";
        s.bodies = "column { material sand; shape { type rectangle; min (0 0); max (0.1 0.1); } particlesPerCell 2; }\n";
        s.g = "value (0 -9.81);\n";
    } else {
        s.grid = "origin (0 0 0); cellSize 0.02; nCells (5 6 1);\n"
                 "boundaries { left { type symmetry; } right { type symmetry; } bottom { type fixed; } "
                 "top { type free; } back { type symmetry; } front { type symmetry; } }\n";
        s.bodies = "column { material sand; shape { type box; min (0 0 0); max (0.1 0.1 0.02); } particlesPerCell 2; }\n";
        s.g = "value (0 -9.81 0);\n";
    }
    return s;
}

//- An elastic cube (0.1 m, rubber) in a box with smooth walls and a fixed floor, a steel
//  plate one cell thick on it (the oedometer of the rigid-plate tests; the control is theirs).
Scene plateOnCube()
{
    Scene s;
    s.materials = "rubber { type linearElastic; rho 1000; E 1e6; nu 0.3; }\nsteel { type linearElastic; rho 7800; "
                  "E 2e11; nu 0.3; }\n";
    s.grid = "origin (0 0 0); cellSize 0.025; nCells (4 6 4);\n"
             "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } "
             "back { type slip; } front { type slip; } }\n";
    s.bodies = "cube { material rubber; shape { type box; min (0 0 0); max (0.1 0.1 0.1); } particlesPerCell 2; }\n"
               "plate { material steel; shape { type box; min (0 0.1 0); max (0.1 0.125 0.1); } particlesPerCell 2; }\n";
    return s;
}

//- The message of the InputError that picInit (then the solver's reader) throws for `dir`.
std::string refusal(const fs::path& dir)
{
    try {
        initialiseCase(dir.string());
        RunOptions options;
        options.caseDir = dir.string();
        options.quiet = true;
        Simulation<3> s(options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

namespace {
//- The column of column(2) and column(3) with these schemes and controlDict additions, run
//  to its end: the slab's particles against their plane twins.
void expectSlabIsPlane(const std::string& schemes, const std::string& control = "")
{
    ScratchDir scratch{"slab"};
    const fs::path plane = scratch.path() / "plane", slab = scratch.path() / "slab";
    Scene s2 = column(2), s3 = column(3);
    s2.schemes = s3.schemes = schemes;
    s2.control += control;
    s3.control += control;
    write(plane, s2);
    write(slab, s3);
    const auto p2 = runAndKeep<2>(plane);
    const auto p3 = runAndKeep<3>(slab);
    const Particles<2>& a = p2->solver().particles();
    const Particles<3>& b = p3->solver().particles();
    ASSERT_EQ(b.size(), 2 * a.size()) << "two layers of particles across the slab";
    // The slab's particles by their plane place at the start (the sort reorders both sets).
    std::map<std::pair<double, double>, std::size_t> planeIndex;
    for (std::size_t q = 0; q < a.size(); ++q) planeIndex[{a.x0[q].x(), a.x0[q].y()}] = q;
    double sMax = 0;
    for (std::size_t q = 0; q < a.size(); ++q) sMax = std::max(sMax, a.sigma[q].cwiseAbs().maxCoeff());
    ASSERT_GT(sMax, 500.0) << "the column carries its weight (rho g H = 1962 Pa)";
    double worstStress = 0, worstPlace = 0, worstShear = 0, worstOut = 0;
    for (std::size_t k = 0; k < b.size(); ++k) {
        const auto it = planeIndex.find({b.x0[k].x(), b.x0[k].y()});
        ASSERT_NE(it, planeIndex.end()) << "slab particle " << k << " has no plane twin";
        const std::size_t q = it->second;
        for (int c : {XX, YY, ZZ, XY}) worstStress = std::max(worstStress, std::abs(b.sigma[k][c] - a.sigma[q][c]));
        worstShear = std::max({worstShear, std::abs(b.sigma[k][YZ]), std::abs(b.sigma[k][XZ])});
        worstOut = std::max({worstOut, std::abs(b.v[k].z()), std::abs(b.x[k].z() - b.x0[k].z())});
        worstPlace = std::max({worstPlace, std::abs(b.x[k].x() - a.x[q].x()), std::abs(b.x[k].y() - a.x[q].y())});
    }
    EXPECT_LT(worstStress, 1e-9 * sMax) << schemes << control;
    EXPECT_LT(worstPlace, 1e-12) << schemes << control;
    EXPECT_LT(worstShear, 1e-12 * sMax) << "no shear out of the plane; " << schemes << control;
    EXPECT_LT(worstOut, 1e-15) << "nothing moves out of the plane; " << schemes << control;
}
} // namespace

TEST(ThreeDCase, aSlabBetweenSymmetryFacesGivesThePlaneStrainRunToRoundOff)
{
    expectSlabIsPlane("");  // the defaults: MUSL, bilinear, FLIP relaxing over 0.02 s
}

TEST(ThreeDCase, everySchemeAndTransferOfTheSlabGivesThePlaneRun)
{
    // The 3D form of each update scheme, shape function, transfer, the cell-mean dilatation,
    // damping and mass scaling reduces to the plane one on the slab.
    for (const char* update : {"USL", "USF", "MUSL"})
        expectSlabIsPlane(std::string("updateScheme ") + update + ";\ntransfer PIC;\n");
    for (const char* transfer : {"FLIP", "APIC", "XPIC"})
        expectSlabIsPlane(std::string("updateScheme USL;\ntransfer ") + transfer + ";\n");
    for (const char* shape : {"uGIMP", "quadraticBSpline"})
        expectSlabIsPlane(std::string("shapeFunction ") + shape + ";\n");
    expectSlabIsPlane("volumetricStrain cellMean;\n");
    expectSlabIsPlane("", "damping 0.2;\n");
    expectSlabIsPlane("", "massScaling { factor 4; }\n");
}

TEST(ThreeDCase, aBlockFallsFreelyAlongGravityAndKeepsItsPlaceAcrossIt)
{
    ScratchDir scratch{"fall"};
    Scene s;
    s.materials = "rubber { type linearElastic; rho 1000; E 1e5; nu 0.3; }\n";
    s.grid = "origin (0 0 0); cellSize 0.05; nCells (6 6 20);\n" +
             std::string(freeSides);
    s.bodies = "block { material rubber; shape { type box; min (0.1 0.1 0.8); max (0.2 0.25 0.9); } "
               "particlesPerCell 2; }\n";
    s.g = "value (0 0 -9.81);\n";
    const double dt = 1e-4, T = 0.2;
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.2;\ndeltaT 1e-4;\n"
                "writeControl adjustableRunTime;\nwriteInterval 0.1;\n"
                "functions { motion { type bodyMotion; writeInterval 100; } }\n";
    write(scratch.path(), s);
    runAndKeep<3>(scratch.path());  // ended: its files closed
    const auto rows = readColumns(scratch.path() / "postProcessing/motion/0/bodyMotion.dat");
    ASSERT_EQ(rows.at("time").size(), 21u);
    for (std::size_t r = 0; r < rows.at("time").size(); ++r) {
        const double t = rows.at("time")[r];
        const double drop = 0.85 - rows.at("block:z")[r];
        EXPECT_NEAR(drop, 0.5 * 9.81 * t * t, 9.81 * t * dt + 1e-12) << "t = " << t;
        EXPECT_NEAR(rows.at("block:vz")[r], -9.81 * t, 1e-9) << "t = " << t;
        EXPECT_NEAR(rows.at("block:x")[r], 0.15, 1e-12);
        EXPECT_NEAR(rows.at("block:y")[r], 0.175, 1e-12);
    }
    EXPECT_NEAR(rows.at("time").back(), T, 1e-12);
}

TEST(ThreeDCase, aRestartedRunEndsWithTheStraightRunsParticleFileByteForByte)
{
    ScratchDir scratch{"restart3d"};
    const fs::path straight = scratch.path() / "straight", split = scratch.path() / "split";
    Scene s = column(3);
    s.control += "writeGrid yes;\n";
    write(straight, s);
    write(split, s);
    runAndKeep<3>(straight);
    setEntry(split / "system/controlDict", "endTime", "0.025");
    runAndKeep<3>(split);
    setEntry(split / "system/controlDict", "endTime", "0.05");
    continueRun<3>(split);
    const std::string a = readText(straight / "0.05/particles.vtp"), b = readText(split / "0.05/particles.vtp");
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "the restarted run's particles differ from the straight run's";

    // The files are 3D: the particles' third coordinate and the grid's third axis.
    Particles<3> p;
    double t = 0;
    readParticles((straight / "0.05/particles.vtp").string(), p, t);
    EXPECT_EQ(t, 0.05);
    double zMax = 0;
    for (const auto& x : p.x) zMax = std::max(zMax, x.z());
    EXPECT_NEAR(zMax, 0.015, 1e-12) << "the upper layer of particles across the slab";
    const GridVtkInfo grid = readGridInfo((straight / "0.05/grid.vti").string());
    EXPECT_EQ(grid.dimensions, (std::array<int, 3>{6, 7, 2}));
    EXPECT_EQ(grid.spacing[2], 0.02);
}

TEST(ThreeDCase, theSolidBodiesHoldTheVolumesOfTheirClosedForms)
{
    ScratchDir scratch{"solids"};
    Scene s;
    s.materials = sand;
    s.grid = "origin (0 0 0); cellSize 0.01; nCells (60 30 30);\n"
             "boundaries { left { type fixed; } right { type fixed; } bottom { type fixed; } top { type fixed; } "
             "back { type fixed; } front { type fixed; } }\n";
    s.bodies =
        "box { material sand; shape { type box; min (0.01 0.01 0.01); max (0.09 0.15 0.12); } particlesPerCell 2; }\n"
        "ball { material sand; shape { type sphere; centre (0.2 0.15 0.15); radius 0.1; } particlesPerCell 2; }\n"
        "rod { material sand; shape { type cylinder; point1 (0.33 0.05 0.05); point2 (0.43 0.25 0.25); radius 0.04; } "
        "particlesPerCell 2; }\n"
        "wedge { material sand; shape { type extrudedPolygon; points ((0.46 0.02) (0.58 0.02) (0.46 0.2)); "
        "zMin 0.05; zMax 0.25; } particlesPerCell 2; initialStress { type geostatic; K0 0.5; surface 0.3; } }\n";
    s.g = "value (0 0 -10);\n";
    write(scratch.path(), s);
    initialiseCase(scratch.path().string());
    Particles<3> p;
    double t = 0;
    std::vector<std::string> materials, bodies;
    readParticles((scratch.path() / "0/particles.vtp").string(), p, t, &materials, &bodies);
    ASSERT_EQ(bodies, (std::vector<std::string>{"box", "ball", "rod", "wedge"}));
    std::vector<double> V(4, 0.0);
    for (std::size_t q = 0; q < p.size(); ++q) V[static_cast<std::size_t>(p.body[q])] += p.V[q];
    const double pi = M_PI;
    EXPECT_NEAR(V[0], 0.08 * 0.14 * 0.11, 1e-12);                         // exact on the lattice
    EXPECT_NEAR(V[1] / (4.0 / 3.0 * pi * 1e-3), 1.0, 0.03);
    EXPECT_NEAR(V[2] / (pi * 0.04 * 0.04 * std::sqrt(0.1 * 0.1 + 2 * 0.2 * 0.2)), 1.0, 0.05);
    EXPECT_NEAR(V[3] / (0.5 * 0.12 * 0.18 * 0.2), 1.0, 0.03);
    // The geostatic stress of the wedge: vertical along x3, K0 across it (eqs. 3.3.1-3.3.2).
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (p.body[q] != 3) continue;
        const double sV = -2000 * 10 * (0.3 - p.x[q].z());
        ASSERT_NEAR(p.sigma[q][ZZ], sV, 1e-9);
        ASSERT_NEAR(p.sigma[q][XX], 0.5 * sV, 1e-9);
        ASSERT_NEAR(p.sigma[q][YY], 0.5 * sV, 1e-9);
        ASSERT_EQ(p.sigma[q][XY], 0.0);
    }
}

TEST(ThreeDCase, planeOnlyModelsGridsAndShapesAreRefusedInOneLine)
{
    ScratchDir scratch{"planeOnly"};
    const auto attempt = [&](const std::string& tag, const std::function<void(Scene&)>& change) {
        Scene s = column(3);
        change(s);
        const fs::path dir = scratch.path() / tag;
        write(dir, s);
        return refusal(dir);
    };
    const std::string polar = attempt("polar", [](Scene& s) {
        s.materials = "sand { type cosseratElastic; rho 2000; E 2e6; nu 0.3; Gc 1e5; lc 0.01; }\n";
    });
    EXPECT_NE(polar.find("material type 'cosseratElastic'"), std::string::npos) << polar;
    EXPECT_NE(polar.find("plane (2D) scenes only"), std::string::npos) << polar;
    EXPECT_EQ(polar.find('\n'), std::string::npos) << polar;

    const std::string axisymmetric =
        attempt("axisymmetric", [](Scene& s) { s.grid = "geometry axisymmetric;\n" + s.grid; });
    EXPECT_NE(axisymmetric.find("geometry axisymmetric is a plane scene"), std::string::npos) << axisymmetric;

    const std::string rectangle = attempt("rectangle", [](Scene& s) {
        s.bodies = "column { material sand; shape { type rectangle; min (0 0); max (0.1 0.1); } particlesPerCell 2; }\n";
    });
    EXPECT_NE(rectangle.find("shape type 'rectangle'"), std::string::npos) << rectangle;
    EXPECT_NE(rectangle.find("plane (2D) scenes only"), std::string::npos) << rectangle;

}

TEST(ThreeDCase, aRigidPlatePressingABoxOfElasticMaterialFeelsTheOedometricForce)
{
    // An elastic cube (L = 0.1 m) in a box with smooth walls and a fixed floor, pressed by a
    // rigid plate (prescribedVelocity) at v = 0.01 m/s: uniaxial strain, so the material
    // pushes the plate up with F = M A d / L, M = E (1 - nu) / ((1 + nu)(1 - 2 nu)), d = v t,
    // within 3 % (the wave the start sets off adds about rho c v A, 1.4 %); its moment about
    // the plate's centre is nil, and the plate has done the work F d / 2 on the material
    // (within 3 %).
    ScratchDir scratch{"plate3d"};
    Scene s = plateOnCube();
    writeDictionary(scratch.path() / "constant/rigidBodies", "plate { type prescribedVelocity; velocity (0 -0.01 0); }\n");
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.2;\ndeltaT 1;\nadjustTimeStep yes;\n"
                "maxCourant 0.5;\nwriteControl adjustableRunTime;\nwriteInterval 0.1;\n"
                "functions { forces { type forces; bodies (plate); CofR (0.05 0.1125 0.05); writeInterval 25; } }\n";
    write(scratch.path(), s);
    runAndKeep<3>(scratch.path());
    const auto rows = readColumns(scratch.path() / "postProcessing/forces/0/forces.dat");
    const double M = 1e6 * 0.7 / (1.3 * 0.4), A = 0.01, L = 0.1, v = 0.01;
    std::size_t checked = 0;
    for (std::size_t r = 0; r < rows.at("time").size(); ++r) {
        const double t = rows.at("time")[r];
        if (t < 0.05) continue;  // the first waves
        const double F = M * A * v * t / L;
        EXPECT_NEAR(rows.at("plate:Fy")[r], F, 0.03 * F) << "t = " << t;
        EXPECT_NEAR(rows.at("plate:Fx")[r], 0.0, 1e-9 * F);
        EXPECT_NEAR(rows.at("plate:Fz")[r], 0.0, 1e-9 * F);
        for (const char* m : {"plate:Mx", "plate:My", "plate:Mz"}) EXPECT_NEAR(rows.at(m)[r], 0.0, 1e-9 * F * L) << m;
        EXPECT_NEAR(rows.at("plate:dy")[r], -v * t, 1e-9);
        ++checked;
    }
    EXPECT_GT(checked, 10u);
    const double d = v * rows.at("time").back(), W = 0.5 * M * A * d * d / L;
    EXPECT_NEAR(rows.at("plate:W").back(), W, 0.03 * W);

    // picForces reads the 3D forces.dat (its window mean is the table's), and refuses its
    // plane-only modes in one line.
    const AppResult forces = runApplication("picForces", scratch.path(), "-window 0.1 0.2");
    ASSERT_EQ(forces.exitCode, 0) << forces.err;
    EXPECT_NE(forces.out.find("plate:Fz"), std::string::npos) << forces.out;
    EXPECT_TRUE(fs::exists(scratch.path() / "postProcessing/picForces/forces.png"));
    const AppResult grid = runApplication("picForces", scratch.path(), "-source grid");
    EXPECT_EQ(grid.exitCode, 1) << grid.err;
    ASSERT_EQ(grid.errorLines.size(), 1u) << grid.err;
    EXPECT_NE(grid.errorLines[0].find("picForces -source grid works on plane and axisymmetric cases"), std::string::npos)
        << grid.err;
}

TEST(ThreeDCase, aWeightedPlateUnderADeadLoadSettlesOnTheElasticBoxToTheOedometricSettlement)
{
    // The scene above with the plate load-driven (weighted, free along x2 only, damped) under a
    // dead load F = 100 N and no gravity: it comes to rest where the material carries F,
    // d = F L / (M A) = 0.743 mm (within 3 %), and does not move across.
    ScratchDir scratch{"weighted3d"};
    Scene s = plateOnCube();
    writeDictionary(scratch.path() / "constant/rigidBodies",
                    "plate { type weighted; free (0 1 0); addedForce (0 -100 0); damping 0.5; }\n");
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.4;\ndeltaT 1;\nadjustTimeStep yes;\n"
                "maxCourant 0.5;\nwriteControl adjustableRunTime;\nwriteInterval 0.4;\ndamping 0.2;\n"
                "functions { forces { type forces; bodies (plate); writeInterval 50; } }\n";
    write(scratch.path(), s);
    runAndKeep<3>(scratch.path());
    const auto rows = readColumns(scratch.path() / "postProcessing/forces/0/forces.dat");
    const double M = 1e6 * 0.7 / (1.3 * 0.4), A = 0.01, L = 0.1, F = 100;
    const double d = F * L / (M * A);
    std::printf("weighted plate settled %.4g mm (oedometric %.4g mm), carried %.4g N\n", -1e3 * rows.at("plate:dy").back(),
                1e3 * d, rows.at("plate:Fy").back());
    EXPECT_NEAR(-rows.at("plate:dy").back(), d, 0.03 * d);
    EXPECT_NEAR(rows.at("plate:Fy").back(), F, 0.03 * F);
    EXPECT_EQ(rows.at("plate:dx").back(), 0.0);
    EXPECT_EQ(rows.at("plate:dz").back(), 0.0);
}

TEST(ThreeDCase, aRigidBoxSpinningInFreeFlightTurnsAsOnePieceAboutItsCentre)
{
    // A weighted box free to turn (0.2 x 0.1 x 0.06 m, inertia principal along the axes),
    // given the velocity field omega x (x - c) of a spin of 2 rad/s about x3 through its centre,
    // flies with no gravity and no material: its angular momentum, taken from its particles at
    // the start, keeps it spinning steadily about that principal axis, so after T = pi/4 s every
    // particle is where the exact turn by omega T about c puts it (1e-9 m) and moves at
    // omega x (x - c).
    ScratchDir scratch{"spin3d"};
    Scene s;
    // Soft, so that the time step of the wave speed (which a rigid body's material still sets) is large.
    s.materials = "steel { type linearElastic; rho 7800; E 1e6; nu 0.3; }\n";
    s.grid = "origin (0 0 0); cellSize 0.02; nCells (20 20 6);\n" +
             std::string(freeSides);
    s.bodies = "box { material steel; shape { type box; min (0.1 0.15 0.03); max (0.3 0.25 0.09); } particlesPerCell 2;\n"
               "      velocity (\"-2*(y-0.2)\" \"2*(x-0.2)\" 0); }\n";
    s.g = "value (0 0 0);\n";
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.785398163397448;\ndeltaT 7.85398163397448e-4;\n"
                "writeControl timeStep;\nwriteInterval 1000;\n";
    write(scratch.path(), s);
    writeDictionary(scratch.path() / "constant/rigidBodies", "box { type weighted; free (1 1 1); freeRotation (1 1 1); }\n");
    initialiseCase(scratch.path().string());
    Particles<3> start;
    double t0 = 0;
    readParticles((scratch.path() / "0/particles.vtp").string(), start, t0);
    const auto run = runAndKeep<3>(scratch.path());
    const auto& p = run->solver().particles();
    ASSERT_EQ(p.size(), start.size());
    const Space<3>::Vector c(0.2, 0.2, 0.06);
    const double turn = 2.0 * 0.785398163397448, cs = std::cos(turn), sn = std::sin(turn);
    std::map<long, std::size_t> startOf;  // the solver sorts its particles: match them by id
    for (std::size_t q = 0; q < start.size(); ++q) startOf[static_cast<long>(start.id[q])] = q;
    double worst = 0, worstV = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const Space<3>::Vector r = start.x[startOf.at(static_cast<long>(p.id[q]))] - c;
        const Space<3>::Vector exact = c + Space<3>::Vector(cs * r.x() - sn * r.y(), sn * r.x() + cs * r.y(), r.z());
        worst = std::max(worst, (p.x[q] - exact).norm());
        const Space<3>::Vector d = p.x[q] - c;
        worstV = std::max(worstV, (p.v[q] - Space<3>::Vector(-2 * d.y(), 2 * d.x(), 0)).norm());
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(worstV, 1e-9);
}

TEST(ThreeDCase, aGeostaticFillAlongMinusX3EndsAtTheK0StressOfTheColumn)
{
    // An elastic column (H = 0.2 m) in a box with smooth walls, filled layer by layer against
    // gravity along -x3 with K0 = nu / (1 - nu), the elastic mass's own ratio (eq. 3.3.2): at
    // rest, sigma33 = -rho g (H - z) and sigma11 = sigma22 = K0 sigma33, within 3 % of
    // rho g H (a layer of cells' worth of the discretisation).
    ScratchDir scratch{"fill3d"};
    Scene s;
    s.materials = "soil { type linearElastic; rho 2000; E 5e6; nu 0.3; }\n";
    s.grid = "origin (0 0 0); cellSize 0.025; nCells (2 2 9);\n"
             "boundaries { left { type slip; } right { type slip; } bottom { type slip; } top { type slip; } "
             "back { type fixed; } front { type free; } }\n";
    s.bodies = "column { material soil; shape { type box; min (0 0 0); max (0.05 0.05 0.2); } particlesPerCell 2; }\n";
    s.g = "value (0 0 -9.81);\n";
    s.control = "startFrom latestTime;\nstartTime 0;\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
                "writeControl adjustableRunTime;\nwriteInterval 10;\n"
                "stages { fill { type geostaticFill; K0 0.428571428571; until { equilibrium 1e-5; maxTime 1; } } }\n";
    write(scratch.path(), s);
    const auto run = runAndKeep<3>(scratch.path());
    ASSERT_NE(run->stages(), nullptr);
    EXPECT_TRUE(run->stages()->done());
    ASSERT_EQ(run->stages()->records().size(), 1u);
    EXPECT_FALSE(run->stages()->records().front().timedOut) << run->stages()->records().front().reason;
    const Particles<3>& p = run->solver().particles();
    ASSERT_EQ(p.size(), 2u * 2 * 2 * 2 * 2 * 8);
    const double rhoGH = 2000 * 9.81 * 0.2, K0 = 0.3 / 0.7;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double sV = -2000 * 9.81 * (0.2 - p.x[q].z());
        EXPECT_NEAR(p.sigma[q][ZZ], sV, 0.03 * rhoGH) << "z = " << p.x[q].z();
        EXPECT_NEAR(p.sigma[q][XX], K0 * sV, 0.03 * rhoGH) << "z = " << p.x[q].z();
        EXPECT_NEAR(p.sigma[q][YY], K0 * sV, 0.03 * rhoGH) << "z = " << p.x[q].z();
    }
}

TEST(ThreeDCase, anOpenedDiscInTheFloorLetsOnlyTheMaterialAboveItOut)
{
    // Sand settled in a box (stage `run` with the outlet closed), then `openGate`: the disc
    // (radius 0.03 m, centred under the box) in the rough floor lets material out; the
    // massFlow rows say none left before the gate opened and some after, the mass out plus
    // the mass left is the mass filled, and every particle gone started above the disc's
    // reach (within a cell and the sand's spreading of it).
    ScratchDir scratch{"gate3d"};
    Scene s;
    s.materials = sand;
    s.grid = "origin (0 0 0); cellSize 0.02; nCells (8 10 8);\n"
             "boundaries { left { type slip; } right { type slip; } "
             "bottom { type fixed; opening { centre (0.08 0.08); radius 0.03; } } top { type free; } "
             "back { type slip; } front { type slip; } }\n";
    s.bodies = "sand { material sand; shape { type box; min (0 0 0); max (0.16 0.12 0.16); } particlesPerCell 2; }\n";
    s.g = "value (0 -9.81 0);\n";
    s.control = "startFrom latestTime;\nstartTime 0;\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
                "writeControl adjustableRunTime;\nwriteInterval 10;\n"
                "stages { settle { type run; damping 0.8; openings { bottom closed; } until { duration 0.1; } }\n"
                "         discharge { type openGate; side bottom; until { duration 0.15; } } }\n"
                "functions { silo { type massFlow; writeInterval 20; }\n"
                "            core { type massFlow; writeInterval 20; region { type cylinder; point1 (0.08 0 0.08); "
                "point2 (0.08 0.2 0.08); radius 0.03; } } }\n";
    write(scratch.path(), s);
    std::size_t filled = 0;
    double totalMass = 0;
    {
        const auto run = runAndKeep<3>(scratch.path());
        filled = 8 * 6 * 8 * 8;
        const Particles<3>& p = run->solver().particles();
        ASSERT_LT(p.size(), filled) << "material has left through the disc";
        double left = 0;
        for (std::size_t q = 0; q < p.size(); ++q) left += p.m[q];
        totalMass = left + run->solver().removedMass();
        // What is left holds every particle that started outside the disc's reach.
        std::size_t outside = 0;
        for (std::size_t q = 0; q < p.size(); ++q) {
            const double r = std::hypot(p.x0[q].x() - 0.08, p.x0[q].z() - 0.08);
            if (r > 0.03 + 0.06) ++outside;
        }
        std::size_t startedOutside = 0;
        for (int i = 0; i < 16; ++i)
            for (int k = 0; k < 16; ++k)
                if (std::hypot((i + 0.5) * 0.01 - 0.08, (k + 0.5) * 0.01 - 0.08) > 0.09) startedOutside += 12;
        EXPECT_EQ(outside, startedOutside) << "only material above the disc has gone";
    }
    EXPECT_NEAR(totalMass, 2000.0 * 0.16 * 0.12 * 0.16, 1e-9);
    const auto rows = readColumns(scratch.path() / "postProcessing/silo/0/massFlow.dat");
    bool opened = false;
    for (std::size_t r = 0; r < rows.at("time").size(); ++r) {
        const double t = rows.at("time")[r];
        if (t <= 0.1) {
            EXPECT_EQ(rows.at("out")[r], 0.0) << "t = " << t << ": the gate is closed";
        }
        if (t > 0.2 && rows.at("out")[r] > 0.01) opened = true;
        EXPECT_NEAR(rows.at("mass")[r] + rows.at("out")[r], 2000.0 * 0.16 * 0.12 * 0.16, 1e-9);
    }
    EXPECT_TRUE(opened) << "kilograms through the disc once the gate opened";

    // A region of any shape: the cylinder above the disc holds, at the start, the particles
    // whose centres lie within 0.03 m of its axis (2 g each), and never more than the silo.
    std::size_t inCore = 0;
    for (int i = 0; i < 16; ++i)
        for (int k = 0; k < 16; ++k)
            if (std::hypot((i + 0.5) * 0.01 - 0.08, (k + 0.5) * 0.01 - 0.08) <= 0.03) inCore += 12;
    const auto core = readColumns(scratch.path() / "postProcessing/core/0/massFlow.dat");
    ASSERT_EQ(core.at("time").size(), rows.at("time").size());
    EXPECT_NEAR(core.at("mass").front(), 2000.0 * 1e-6 * static_cast<double>(inCore), 1e-12);
    for (std::size_t r = 0; r < core.at("time").size(); ++r) EXPECT_LT(core.at("mass")[r], rows.at("mass")[r]);
}

namespace {
//- Where a deposit ends: the first column of cells, counted from the wall at x = 0, whose
//  highest particle lies below `thin` (the definition of the columnCollapse tutorial).
template <int D> double front(const Particles<D>& p, double h, double thin)
{
    std::map<int, double> height;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const int b = static_cast<int>(p.x[q].x() / h);
        height[b] = std::max(height[b], p.x[q].y());
    }
    int b = 0;
    while (height.count(b + 1) && height[b + 1] >= thin) ++b;
    return (b + 1) * h;
}
} // namespace

TEST(ThreeDCase, theColumnCollapseAsASlabRunsOutAsThePlaneColumnWithin3Percent)
{
    // The columnCollapse tutorial's sand column (L0 = 0.1 m, a = 2, 10 mm cells, default
    // schemes) collapsing to rest, as a plane case and as a slab one cell thick between
    // symmetry faces: the runouts (L_inf - L0) / L0 within 3 % (seed-free check of
    // plane strain recovered on a long, plastic, chaotic run).
    ScratchDir scratch{"collapse3d"};
    const std::string control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\ndeltaT 1;\n"
                                "adjustTimeStep yes;\nmaxCourant 0.5;\nwriteControl adjustableRunTime;\nwriteInterval 1;\n";
    Scene plane, slab;
    plane.materials = slab.materials = "sand { type mohrCoulomb; rho 2650; E 1e6; nu 0.3; phi 30; psi 0; c 0; }\n";
    plane.control = slab.control = control;
    plane.grid = "origin (0 0); cellSize 0.01; nCells (70 21);\nboundaries { left { type symmetry; } "
                 "right { type slip; } bottom { type fixed; } top { type free; } }\n";
    slab.grid = "origin (0 0 0); cellSize 0.01; nCells (70 21 1);\nboundaries { left { type symmetry; } "
                "right { type slip; } bottom { type fixed; } top { type free; } back { type symmetry; } "
                "front { type symmetry; } }\n";
    plane.bodies = "column { material sand; shape { type rectangle; min (0 0); max (0.1 0.2); } particlesPerCell 2; }\n";
    slab.bodies = "column { material sand; shape { type box; min (0 0 0); max (0.1 0.2 0.01); } particlesPerCell 2; }\n";
    plane.g = "value (0 -9.81);\n";
    slab.g = "value (0 -9.81 0);\n";
    write(scratch.path() / "plane", plane);
    write(scratch.path() / "slab", slab);
    const auto a = runAndKeep<2>(scratch.path() / "plane");
    const auto b = runAndKeep<3>(scratch.path() / "slab");
    const double L0 = 0.1;
    const double runoutPlane = (front(a->solver().particles(), 0.01, 0.1 * L0) - L0) / L0;
    const double runoutSlab = (front(b->solver().particles(), 0.01, 0.1 * L0) - L0) / L0;
    EXPECT_GT(runoutPlane, 1.5) << "the column has collapsed";
    EXPECT_NEAR(runoutSlab, runoutPlane, 0.03 * runoutPlane);
    EXPECT_LT(a->solver().maxParticleSpeed(), 0.05) << "at rest";
    EXPECT_LT(b->solver().maxParticleSpeed(), 0.05) << "at rest";
}

TEST(ThreeDCase, aRigidBodyTurnsAboutASlantedAxisThroughAPointExactly)
{
    // prescribedVelocity with omega about axis (1 1 1) through the box's centre: after t its
    // particles are where Rodrigues' rotation by omega t takes them (to 1e-12 m), the body
    // keeps its shape, and the centre stays put.
    ScratchDir scratch{"turn3d"};
    Scene s;
    s.materials = "tool { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n";
    s.grid = "origin (0 0 0); cellSize 0.05; nCells (12 12 12);\n" +
             std::string(freeSides);
    s.bodies = "block { material tool; shape { type box; min (0.2 0.25 0.25); max (0.4 0.35 0.35); } "
               "particlesPerCell 2; }\n";
    writeDictionary(scratch.path() / "constant/rigidBodies",
                    "block { type prescribedVelocity; omega 2; centre (0.3 0.3 0.3); axis (1 1 1); }\n");
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.5;\ndeltaT 1e-3;\n"
                "writeControl adjustableRunTime;\nwriteInterval 1;\n";
    write(scratch.path(), s);
    const auto run = runAndKeep<3>(scratch.path());
    const Particles<3>& p = run->solver().particles();
    const double t = run->time();
    EXPECT_NEAR(t, 0.5, 1e-9);
    const Eigen::Vector3d c(0.3, 0.3, 0.3);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(2.0 * t, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();
    double worst = 0;
    for (std::size_t q = 0; q < p.size(); ++q) worst = std::max(worst, (p.x[q] - (c + R * (p.x0[q] - c))).norm());
    EXPECT_LT(worst, 1e-12);
}

TEST(ThreeDCase, moveToolEndsAtItsDisplacementAndExcavateDigsTheRegionFromTheTop)
{
    // Stages in 3D: moveTool pushes the rigid plate of the oedometer scene until it has moved
    // 1 mm (at 0.01 m/s: 0.1 s, within a step); then excavate digs the top 0.04 m of the
    // cube's middle in layers of one cell, each to equilibrium: the particles left in the
    // region are the ones below the cut.
    ScratchDir scratch{"stages3d"};
    Scene s = plateOnCube();
    s.control = "startFrom latestTime;\nstartTime 0;\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
                "writeControl adjustableRunTime;\nwriteInterval 10;\n"
                "stages {\n"
                "  push { type moveTool; body plate; drivers { plate { type prescribedVelocity; velocity (0 -0.01 0); } }\n"
                "         until { displacement 0.001; } }\n"
                "  dig { type excavate; body cube; bodies (cube); region { type box; min (0.025 0.05 0.025); "
                "max (0.075 0.2 0.075); } layerThickness 0.025; until { equilibrium 1e-4; maxTime 0.5; } }\n"
                "}\n";
    write(scratch.path(), s);
    const auto run = runAndKeep<3>(scratch.path());
    const auto& records = run->stages()->records();
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].name, "push");
    EXPECT_NE(records[0].reason.find("displacement"), std::string::npos) << records[0].reason;
    EXPECT_NEAR(records[0].endTime, 0.1, 2e-4);
    EXPECT_EQ(records[1].type, "excavate");
    const Particles<3>& p = run->solver().particles();
    std::size_t inRegion = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const Eigen::Vector3d& x0 = p.x0[q];
        const bool under = x0.x() > 0.025 && x0.x() < 0.075 && x0.z() > 0.025 && x0.z() < 0.075;
        if (p.body[q] != 0 || !under) continue;
        EXPECT_LT(x0.y(), 0.05) << "a particle of the dug region is left";
        ++inRegion;
    }
    EXPECT_EQ(inRegion, 4u * 4 * 4) << "the region's particles below the cut stay";
    EXPECT_EQ(p.size(), 4u * 4 * 4 * 8 - 4u * 4 * 4) << "the cube less the dug particles (the plate sleeps in dig)";
}

TEST(ThreeDCase, picFieldMapDrawsTheParticlesASliceCuts)
{
    // An elastic block (0.1 x 0.1 x 0.0875 m, 25 mm cells, 2 x 2 x 2 particles a cell: layers
    // 12.5 mm apart, half-size 6.25 mm, 8 x 8 x 7 particles) as picInit writes it: the plane
    // x3 = 0.053 m cuts the layer at 0.05625 m alone (64 particles), which the map holds at
    // their (x1, x2) with their x3; x2 = 0.03 cuts the layer at 0.03125 (56 particles at
    // (x1, x3)); without -slice, the plane x3 through the particles' middle, the layer at
    // 0.04375 m (64); a bad slice is one line.
    ScratchDir scratch{"fieldMap3d"};
    Scene s = plateOnCube();
    s.bodies = "cube { material rubber; shape { type box; min (0 0 0); max (0.1 0.1 0.0875); } particlesPerCell 2; }\n";
    write(scratch.path(), s);
    initialiseCase(scratch.path().string());
    const auto rowsOf = [&](const std::string& args, const std::string& stem) {
        const AppResult r = runApplication("picFieldMap", scratch.path(), "-time 0 " + args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        std::ifstream in(scratch.path() / "postProcessing/picFieldMap/0" / (stem + ".csv"));
        std::string line;
        std::getline(in, line);
        std::vector<std::array<double, 3>> rows;
        for (std::array<double, 3> row{}; std::getline(in, line);) {
            std::replace(line.begin(), line.end(), ',', ' ');
            std::istringstream(line) >> row[0] >> row[1] >> row[2];
            rows.push_back(row);
        }
        return rows;
    };
    const auto x3 = rowsOf("-field initialPosition:z -slice x3 0.053", "initialPosition_z");
    ASSERT_EQ(x3.size(), 64u);
    for (const auto& row : x3) {
        EXPECT_NEAR(row[2], 0.05625, 1e-12);
        const double layer = (row[0] - 0.00625) / 0.0125;  // x1 on the particles' lattice
        EXPECT_NEAR(layer, std::round(layer), 1e-9) << row[0];
    }
    const auto x2 = rowsOf("-field initialPosition:y -slice x2 0.03", "initialPosition_y");
    ASSERT_EQ(x2.size(), 56u);
    for (const auto& row : x2) EXPECT_NEAR(row[2], 0.03125, 1e-12);
    const auto middle = rowsOf("-field initialPosition:z", "initialPosition_z");
    ASSERT_EQ(middle.size(), 64u);
    for (const auto& row : middle) EXPECT_NEAR(row[2], 0.04375, 1e-12);
    const AppResult bad = runApplication("picFieldMap", scratch.path(), "-time 0 -field mass -slice x4 0.05");
    EXPECT_EQ(bad.exitCode, 1);
    ASSERT_EQ(bad.errorLines.size(), 1u) << bad.err;
    EXPECT_NE(bad.errorLines[0].find("valid axes: x1, x2, x3"), std::string::npos) << bad.err;
}

TEST(ThreeDCase, toolFillCountsTheMaterialInARegionTheToolCarries)
{
    // A rigid plate (prescribedVelocity 0.1 m/s along x1) above an elastic block at rest (no
    // gravity, a free cell between them: they share no node), and a region fixed to the plate
    // reaching down into the block, 45 mm long along x1: it holds 4 of the block's particle
    // columns (12.5 mm apart) at the start and 3 after 10 mm; the region moves with the plate
    // (dx = v t to round-off), without turning, and its path is v t.
    ScratchDir scratch{"toolFill3d"};
    Scene s = plateOnCube();
    s.grid = "origin (0 0 0); cellSize 0.025; nCells (8 4 4);\n"
             "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } "
             "back { type slip; } front { type slip; } }\n";
    s.bodies = "block { material rubber; shape { type box; min (0 0 0); max (0.2 0.05 0.1); } particlesPerCell 2; }\n"
               "plate { material steel; shape { type box; min (0 0.075 0); max (0.05 0.1 0.1); } particlesPerCell 2; }\n";
    s.g = "value (0 0 0);\n";
    s.control = "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.1;\ndeltaT 1e-4;\n"
                "writeControl adjustableRunTime;\nwriteInterval 0.05;\n"
                "functions { fill { type toolFill; body plate; region { type box; min (0 0 0); max (0.045 0.05 0.1); } "
                "writeInterval 500; } }\n";
    write(scratch.path(), s);
    writeDictionary(scratch.path() / "constant/rigidBodies", "plate { type prescribedVelocity; velocity (0.1 0 0); }\n");
    runAndKeep<3>(scratch.path());
    const auto rows = readColumns(scratch.path() / "postProcessing/fill/0/fill.dat");
    ASSERT_EQ(rows.at("time").size(), 3u);
    const double particle = 1000 * std::pow(0.0125, 3), layer = 4 * 8 * particle;  // a column: 4 x 8 particles
    EXPECT_NEAR(rows.at("mass")[0], 4 * layer, 1e-12);
    EXPECT_NEAR(rows.at("mass")[2], 3 * layer, 1e-12);
    for (std::size_t r = 0; r < 3; ++r) {
        const double t = rows.at("time")[r];
        EXPECT_NEAR(rows.at("dx")[r], 0.1 * t, 1e-12) << "t = " << t;
        EXPECT_NEAR(rows.at("dy")[r], 0.0, 1e-12);
        EXPECT_NEAR(rows.at("travel")[r], 0.1 * t, 1e-12);
        EXPECT_NEAR(rows.at("rotation")[r], 0.0, 1e-5);
    }
}
