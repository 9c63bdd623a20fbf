// Bodies from CAD surfaces (STL, bodies/TriSurface.H):
// - ASCII and binary STL read to the same solid, placed by scale, rotation and translation;
// - a filled body holds the volume its surface encloses within a tenth of one particle layer
//   (the surface's area times the particle spacing), converging with the cell: a sphere, a
//   box turned 30 degrees about a slanted axis and a torus (verification 2 of "Three
//   dimensions, part 2"); the tessellations' own volumes against the smooth solids';
// - the enclosed volume of a sphere's tessellation converges to 4/3 pi R^3 at second order;
// - a rigid tool drawn as STL is written in every time directory (<body>.vtp, indexed in the
//   .pvd) where its particles carry it: turned about a slanted axis, its corners lie where
//   Rodrigues' rotation puts them (1e-12 m), and a restarted run writes the same surface;
// - a tool drawn as an ASCII STL of named solids reports the force on each part (forces):
//   the plate pressing an elastic cube, its underside taking the force, the parts adding up;
// - a surface that cannot bound a solid (open, not manifold, turned inward, folded, crossing
//   itself, with a degenerate facet) or a file that is missing or not STL is refused in one
//   line naming the file, the keyword and the first fault.
#include "bodies/TriSurface.H"
#include "case/CaseInitialiser.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "io/ParticlesVtk.H"
#include "io/SurfaceVtk.H"
#include "run/Simulation.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"
#include "support/StlSurfaces.H"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <fstream>
#include <sstream>
#include <cstdio>
#include <string>

using namespace gpic;
using namespace gpic::test;

namespace {

//- The surface a `shape`-like dictionary in <dir>/constant/bodies names.
TriSurface readIn(const fs::path& dir, const std::string& keywords)
{
    const Dictionary d = Dictionary::parse(keywords + "\n", (dir / "constant/bodies").string());
    return TriSurface::read(d);
}

//- The one-line message reading `surface` (written as ASCII STL) gives, or "" when accepted.
std::string refusalOf(const fs::path& dir, const StlSurface& surface)
{
    writeAsciiStl(dir / "constant/triSurface/bad.stl", surface);
    try {
        readIn(dir, "file \"triSurface/bad.stl\";");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

//- Fill `shape` with 2 x 2 x 2 particles per cell of size h; the volume the particles stand for.
double filledVolume(const fs::path& dir, const std::string& shape, double h, const Eigen::Vector3d& extent)
{
    fs::remove_all(dir);
    const Eigen::Vector3d n = (extent / h).array().ceil();
    writeDictionary(dir / "constant/grid",
                    "origin (0 0 0); cellSize " + std::to_string(h) + "; nCells (" + std::to_string(int(n.x())) + " " +
                        std::to_string(int(n.y())) + " " + std::to_string(int(n.z())) +
                        ");\nboundaries { left { type fixed; } right { type fixed; } bottom { type fixed; } "
                        "top { type fixed; } back { type fixed; } front { type fixed; } }\n");
    writeDictionary(dir / "constant/materials", "sand { type linearElastic; rho 2000; E 1e7; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies", "solid { material sand; shape { " + shape + " } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/g", "value (0 0 -9.81);\n");
    writeDictionary(dir / "system/controlDict", "startFrom latestTime; startTime 0; stopAt endTime; endTime 1e-4;\n"
                                                "deltaT 1e-4; writeControl timeStep; writeInterval 1;\n");
    initialiseCase(dir.string());
    Particles<3> p;
    double t = 0;
    readParticles((dir / "0/particles.vtp").string(), p, t);
    double V = 0;
    for (std::size_t q = 0; q < p.size(); ++q) V += p.V[q];
    return V;
}

} // namespace

TEST(ThreeDSurface, asciiAndBinaryStlReadToTheSameSolidPlacedByScaleRotationAndTranslation)
{
    ScratchDir scratch{"stlRead"};
    const StlSurface box = boxSurface({0, 0, 0}, {100, 200, 300});  // in millimetres
    writeAsciiStl(scratch.path() / "constant/triSurface/ascii.stl", box);
    writeBinaryStl(scratch.path() / "constant/triSurface/binary.stl", box);
    const std::string placement = "scale 0.001; rotation { axis (0 0 1); angle 90; } translation (1 2 3);";
    const TriSurface a = readIn(scratch.path(), "file \"triSurface/ascii.stl\"; " + placement);
    const TriSurface b = readIn(scratch.path(), "file \"triSurface/binary.stl\"; " + placement);
    ASSERT_EQ(a.corners().size(), 8u);  // the facets' shared corners merged
    ASSERT_EQ(b.corners().size(), 8u);
    EXPECT_NEAR(a.volume(), 0.1 * 0.2 * 0.3, 1e-15);
    EXPECT_NEAR(b.volume(), 0.1 * 0.2 * 0.3, 1e-9);  // the binary format's single precision
    // Turned a quarter about x3: x1 spans -0.2 ... 0, x2 0 ... 0.1; then shifted by (1 2 3).
    for (const TriSurface* s : {&a, &b}) {
        const auto [lo, hi] = s->bounds();
        EXPECT_LT((lo - Eigen::Vector3d(0.8, 2.0, 3.0)).norm(), 1e-7);
        EXPECT_LT((hi - Eigen::Vector3d(1.0, 2.1, 3.3)).norm(), 1e-7);
        EXPECT_TRUE(s->inside({0.9, 2.05, 3.15}));
        EXPECT_TRUE(s->inside({1.0, 2.05, 3.15}));  // on the surface counts as inside
        EXPECT_FALSE(s->inside({1.01, 2.05, 3.15}));
        EXPECT_FALSE(s->inside({0.05, 0.1, 0.15}));  // where the unplaced file's box was
    }
}

TEST(ThreeDSurface, theEnclosedVolumeOfATessellatedSphereConvergesAtSecondOrder)
{
    const double exact = 4.0 / 3.0 * M_PI;
    double previous = 0;
    for (int levels = 1; levels <= 4; ++levels) {
        const StlSurface s = sphereSurface({0, 0, 0}, 1.0, levels);
        const double error = std::abs(TriSurface(s.corners, s.facets, "sphere").volume() - exact) / exact;
        if (levels > 1) {
            EXPECT_NEAR(previous / error, 4.0, 0.4) << "at " << levels << " levels";  // h^2
        }
        previous = error;
    }
    EXPECT_LT(previous, 3e-3);
}

TEST(ThreeDSurface, aFilledBodyHoldsItsSurfacesVolumeWithinATenthOfAParticleLayer)
{
    ScratchDir scratch{"stlFill"};
    const fs::path surfaces = scratch.path() / "surfaces";
    const StlSurface sphere = sphereSurface({0.15, 0.15, 0.15}, 0.1, 4);
    const StlSurface box = boxSurface({-0.1, -0.05, -0.04}, {0.1, 0.05, 0.04});
    const StlSurface torus = torusSurface({0.15, 0.15, 0.1}, 0.08, 0.03, 96, 48);
    writeBinaryStl(surfaces / "sphere.stl", sphere);
    writeAsciiStl(surfaces / "box.stl", box);
    writeBinaryStl(surfaces / "torus.stl", torus);
    struct Solid {
        std::string shape;
        double volume;  //- enclosed by the tessellation
        double area;
        double exact;   //- of the smooth solid
        double tessellation;  //- how far the tessellation's volume may lie from it
    };
    const std::string at = "\"" + surfaces.string();
    const Solid solids[] = {
        {"type triSurface; file " + at + "/sphere.stl\";", TriSurface(sphere.corners, sphere.facets, "").volume(),
         sphere.area(), 4.0 / 3.0 * M_PI * 1e-3, 3e-3},
        // Turned 30 degrees about (1 1 1) and moved into the grid: a box the lattice cuts askew.
        {"type triSurface; file " + at + "/box.stl\"; rotation { axis (1 1 1); angle 30; } translation (0.15 0.15 0.15);",
         0.2 * 0.1 * 0.08, box.area(), 0.2 * 0.1 * 0.08, 1e-12},
        {"type triSurface; file " + at + "/torus.stl\";", TriSurface(torus.corners, torus.facets, "").volume(),
         // Inscribed polygons of 96 and 48 sides: the tube's section and the ring's length
         // short by (2 pi / 48)^2 / 6 and (2 pi / 96)^2 / 6, 0.36 % in all.
         torus.area(), 2 * M_PI * M_PI * 0.08 * 0.03 * 0.03, 4e-3},
    };
    for (const Solid& solid : solids) {
        EXPECT_NEAR(solid.volume / solid.exact, 1.0, solid.tessellation) << solid.shape;
        double coarseError = 0;
        for (const double h : {0.02, 0.01}) {
            const double V = filledVolume(scratch.path() / "case", solid.shape, h, {0.3, 0.3, 0.3});
            const double layer = solid.area * h / 2;  // 2 particles per cell: spacing h / 2
            const double error = std::abs(V - solid.volume);
            std::printf("%s: %g m cells, filled %.5g of %.5g m^3, off by %.3f layers\n", solid.shape.c_str(), h, V,
                        solid.volume, error / layer);
            // The bar is one layer; the lattice's sub-cell centres do ten times better.
            EXPECT_LT(error, 0.15 * layer) << solid.shape << " on " << h << " m cells";
            if (h == 0.01 && error > 0.01 * layer) {
                EXPECT_LT(error, 0.5 * coarseError) << solid.shape << ": no convergence with the cell";
            }
            coarseError = error;
        }
    }
}

TEST(ThreeDSurface, aSurfaceThatCannotBoundASolidIsRefusedNamingTheFirstFault)
{
    ScratchDir scratch{"stlFaults"};
    const fs::path dir = scratch.path();
    const StlSurface cube = boxSurface({0, 0, 0}, {1, 1, 1});
    const auto expectRefused = [&](const StlSurface& s, const std::string& fault) {
        const std::string message = refusalOf(dir, s);
        EXPECT_NE(message.find(fault), std::string::npos) << message;
        EXPECT_NE(message.find("constant/bodies:1"), std::string::npos) << message;
        EXPECT_NE(message.find("triSurface/bad.stl"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    };
    EXPECT_EQ(refusalOf(dir, cube), "");

    StlSurface open = cube;
    open.facets.pop_back();
    expectRefused(open, "is not closed: its edge");

    StlSurface folded = cube;
    std::swap(folded.facets[3][1], folded.facets[3][2]);
    expectRefused(folded, "is not oriented consistently");

    StlSurface inward = cube;
    for (auto& t : inward.facets) std::swap(t[1], t[2]);
    expectRefused(inward, "faces inward: the volume it encloses comes out -1");

    // Two cubes sharing one edge: four facets meet there.
    StlSurface twoCubes = cube;
    const StlSurface other = boxSurface({1, 1, 0}, {2, 2, 1});
    for (const auto& t : other.facets) {
        std::array<int, 3> f;
        for (int k = 0; k < 3; ++k) {
            const auto& c = other.corners[t[k]];
            int index = -1;
            for (std::size_t i = 0; i < twoCubes.corners.size(); ++i)
                if ((twoCubes.corners[i] - c).norm() == 0) index = static_cast<int>(i);
            if (index < 0) {
                twoCubes.corners.push_back(c);
                index = static_cast<int>(twoCubes.corners.size()) - 1;
            }
            f[k] = index;
        }
        twoCubes.facets.push_back(f);
    }
    expectRefused(twoCubes, "is not manifold");

    // Two cubes overlapping: closed, turned outward, but crossing each other.
    StlSurface overlapping = cube;
    const StlSurface shifted = boxSurface({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
    for (const auto& t : shifted.facets)
        overlapping.facets.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    overlapping.corners.insert(overlapping.corners.end(), shifted.corners.begin(), shifted.corners.end());
    expectRefused(overlapping, "intersects itself");

    StlSurface degenerate = cube;
    degenerate.facets.push_back({0, 1, 1});
    expectRefused(degenerate, "has a degenerate facet (number 13");

    // A missing file, and a file that is not STL.
    try {
        readIn(dir, "file \"triSurface/none.stl\";");
        ADD_FAILURE() << "a missing file was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot open surface file \"triSurface/none.stl\""), std::string::npos)
            << e.what();
    }
    writeDictionary(dir / "constant/triSurface/notStl.stl", "a; b;");
    try {
        readIn(dir, "file \"triSurface/notStl.stl\";");
        ADD_FAILURE() << "a file that is not STL was accepted";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_TRUE(m.find("is not an STL file") != std::string::npos || m.find("holds no facet") != std::string::npos)
            << m;
    }
    try {
        readIn(dir, "file \"triSurface/bad.stl\"; scale 0;");
        ADD_FAILURE() << "scale 0 was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("scale must be > 0"), std::string::npos) << e.what();
    }
}

TEST(ThreeDSurface, aRigidToolFromStlIsWrittenInEveryTimeDirectoryWhereItsParticlesCarryIt)
{
    ScratchDir scratch{"stlTool"};
    const fs::path straight = scratch.path() / "straight", restarted = scratch.path() / "restarted";
    // A sphere of 0.08 m turned at 2 rad/s about (1 1 1) through a point off its centre.
    const StlSurface ball = sphereSurface({0.3, 0.3, 0.3}, 0.08, 2);
    for (const fs::path& dir : {straight, restarted}) {
        writeAsciiStl(dir / "constant/triSurface/ball.stl", ball);
        writeDictionary(dir / "constant/grid", "origin (0 0 0); cellSize 0.05; nCells (12 12 12);\nboundaries { "
                                               "left { type free; } right { type free; } bottom { type free; } top { "
                                               "type free; } back { type free; } front { type free; } }\n");
        writeDictionary(dir / "constant/materials", "steel { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n");
        writeDictionary(dir / "constant/bodies", "ball { material steel; shape { type triSurface; file "
                                                 "\"triSurface/ball.stl\"; } particlesPerCell 2; }\n");
        writeDictionary(dir / "constant/rigidBodies",
                        "ball { type prescribedVelocity; omega 2; centre (0.28 0.3 0.32); axis (1 1 1); }\n");
        writeDictionary(dir / "system/controlDict", "startFrom latestTime; startTime 0; stopAt endTime;\nendTime 0.5;\n"
                                                    "deltaT 1e-3; writeControl adjustableRunTime; writeInterval 0.25;\n");
    }
    runAndKeep<3>(straight);
    const Eigen::Vector3d c(0.28, 0.3, 0.32);
    for (const double t : {0.0, 0.25, 0.5}) {
        const std::string name = t == 0 ? "0" : (t == 0.25 ? "0.25" : "0.5");
        const SurfaceVtkInfo surface = readSurface((straight / name / "ball.vtp").string());
        EXPECT_EQ(surface.time, t);
        ASSERT_EQ(surface.corners.size(), ball.corners.size());
        ASSERT_EQ(surface.facets.size(), ball.facets.size());
        // The reader numbers the corners as it meets them; the facets keep the file's order.
        const Eigen::Matrix3d R = Eigen::AngleAxisd(2.0 * t, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();
        double worst = 0;
        for (std::size_t f = 0; f < ball.facets.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector3d drawn = ball.corners[ball.facets[f][k]];
                worst = std::max(worst, (surface.corners[surface.facets[f][k]] - (c + R * (drawn - c))).norm());
            }
        EXPECT_LT(worst, 1e-12) << "at t = " << t;
    }
    std::ifstream pvd(straight / "straight.pvd");
    std::stringstream index;
    index << pvd.rdbuf();
    for (const char* entry : {"part=\"2\" file=\"0/ball.vtp\"", "part=\"2\" file=\"0.25/ball.vtp\"",
                              "part=\"2\" file=\"0.5/ball.vtp\""})
        EXPECT_NE(index.str().find(entry), std::string::npos) << entry << " not in\n" << index.str();

    // Stopped at 0.25 s and restarted: the same surface at 0.5 s, byte for byte.
    setEntry(restarted / "system/controlDict", "endTime", "0.25");
    runAndKeep<3>(restarted);
    setEntry(restarted / "system/controlDict", "endTime", "0.5");
    continueRun<3>(restarted);
    EXPECT_EQ(readText(restarted / "0.5/ball.vtp"), readText(straight / "0.5/ball.vtp"));
}

TEST(ThreeDSurface, aToolDrawnWithNamedPartsReportsTheForceOnEachPart)
{
    // The rigid plate of the oedometric test (threeDCaseTest) drawn as an ASCII STL of three
    // solids: its top, its underside and its four sides, the underside not first. Pressed into
    // the elastic cube (smooth walls, fixed floor) at 0.01 m/s, the material pushes on the
    // underside alone: the underside takes the plate's force within 1 %, the top and the sides
    // less than 1 % of it, and the parts add up to the plate's force to round-off. The
    // surface reads as three parts; a binary copy of it, which has no names, as one.
    ScratchDir scratch{"stlParts"};
    const fs::path dir = scratch.path();
    const StlSurface plate = boxSurface({0, 0.1, 0}, {0.1, 0.125, 0.1});
    std::vector<std::string> partOf;
    for (const auto& t : plate.facets) {
        const Eigen::Vector3d n = (plate.corners[t[1]] - plate.corners[t[0]]).cross(plate.corners[t[2]] - plate.corners[t[0]]);
        partOf.push_back(n.y() > 0 ? "top" : n.y() < 0 ? "underside" : "sides");
    }
    if (partOf[0] == "underside") std::swap(partOf[0], partOf[1]);  // not first in the file
    ASSERT_NE(partOf.front(), "underside");
    writeAsciiStl(dir / "constant/triSurface/plate.stl", plate, partOf);
    writeBinaryStl(dir / "constant/triSurface/plateBinary.stl", plate);
    const TriSurface named = readIn(dir, "file \"triSurface/plate.stl\";");
    ASSERT_EQ(named.partNames().size(), 3u);
    for (std::size_t f = 0; f < named.facets().size(); ++f) {
        const Eigen::Vector3d n = named.facetNormal(static_cast<int>(f));
        const std::string& part = named.partNames()[static_cast<std::size_t>(named.partOf(static_cast<int>(f)))];
        EXPECT_EQ(part, n.y() > 0.5 ? "top" : n.y() < -0.5 ? "underside" : "sides") << "facet " << f;
    }
    EXPECT_EQ(readIn(dir, "file \"triSurface/plateBinary.stl\";").partNames().size(), 1u);

    writeDictionary(dir / "constant/grid", "origin (0 0 0); cellSize 0.025; nCells (4 6 4);\nboundaries { left { type "
                                           "slip; } right { type slip; } bottom { type fixed; } top { type free; } back "
                                           "{ type slip; } front { type slip; } }\n");
    writeDictionary(dir / "constant/materials", "rubber { type linearElastic; rho 1000; E 1e6; nu 0.3; }\nsteel { type "
                                                "linearElastic; rho 7800; E 2e11; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies",
                    "cube { material rubber; shape { type box; min (0 0 0); max (0.1 0.1 0.1); } particlesPerCell 2; }\n"
                    "plate { material steel; shape { type triSurface; file \"triSurface/plate.stl\"; } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/rigidBodies", "plate { type prescribedVelocity; velocity (0 -0.01 0); }\n");
    writeDictionary(dir / "system/controlDict",
                    "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.1;\ndeltaT 1;\nadjustTimeStep yes;\n"
                    "maxCourant 0.5;\nwriteControl adjustableRunTime;\nwriteInterval 0.1;\n"
                    "functions { forces { type forces; bodies (plate); writeInterval 25; } }\n");
    runAndKeep<3>(dir);
    const auto rows = readColumns(dir / "postProcessing/forces/0/forces.dat");
    std::size_t checked = 0;
    for (std::size_t r = 0; r < rows.at("time").size(); ++r) {
        if (rows.at("time")[r] < 0.05) continue;  // the first waves
        const double F = rows.at("plate:Fy")[r];
        ASSERT_GT(F, 0.0);
        EXPECT_NEAR(rows.at("plate.underside:Fy")[r], F, 0.01 * F);
        for (const char* part : {"plate.top", "plate.sides"})
            for (const char* c : {":Fx", ":Fy", ":Fz"}) EXPECT_LT(std::abs(rows.at(std::string(part) + c)[r]), 0.01 * F);
        for (const char* c : {"Fx", "Fy", "Fz"}) {
            double sum = 0;
            for (const char* part : {"plate.top", "plate.underside", "plate.sides"}) sum += rows.at(std::string(part) + ":" + c)[r];
            EXPECT_NEAR(sum, rows.at(std::string("plate:") + c)[r], 1e-9 * F) << c;
        }
        ++checked;
    }
    EXPECT_GT(checked, 3u);
}
