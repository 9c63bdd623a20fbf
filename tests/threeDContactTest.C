// Multi-field contact in 3D (seed appendix G after Bardenhagen et al. 2000):
// - the Coulomb law on one node: the approach stopped, the sliding slowed by mu D against
//   its own direction (any direction across the normal), a slow slide stopped, never
//   reversed; a separating body left alone;
// - a block on a fixed rigid plate (rigidSurface normals from the plate's triangles, MUSL)
//   under gravity tilted along a diagonal of the plate: it slides with
//   a = g (sin(theta) - mu cos(theta)) along the tilt, within 1 %, and sticks where
//   mu > tan(theta). (With massGradient normals the block's leading edge catches on the
//   plate, in the plane as in 3D: doc/contact.md);
// - the same block on the plate drawn as STL wears it by Archard's law (toolWear in 3D): the
//   worn volume (k/H) N s within 3 %, all of it on the top face, carried by the surface file;
// - two elastic spheres meeting off-centre with friction: the momentum of the pair is kept to
//   1e-9 (the pair's normals opposite, G.4) and no kinetic energy is made;
// - a rigid box drives the nodes inside it and in front of its faces, not those beyond an
//   edge, nor those level with a face beyond its edge (the plane rule).
#include "case/CaseInitialiser.H"
#include "contact/ContactLaw.H"
#include "dictionary/Dictionary.H"
#include "run/Simulation.H"
#include "support/CaseRunner.H"
#include "support/StlSurfaces.H"
#include "io/SurfaceVtk.H"
#include "normals/RigidSolidSurface.H"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <cstdio>
#include <string>

using namespace gpic;
using namespace gpic::test;
using Vector3 = Space<3>::Vector;

// The plane blade's nodes (tests/contactTest.C) in 3D, the blade a box 0.1 wide: the node one
// cell ahead of its foot, level with the foot, is beyond the foot's edge. Counted as facing
// it, it pushed the sand below the foot along: a finite blade's draft force (seed 4.7 across
// the width, tutorials/geotechnics/bladeWidth) tripled once its front particles crossed into
// the next cell, where the plane blade's held.
TEST(RigidSolidSurface, facesTheNodesInsideAndInFrontOfAFaceButNotBeyondAnEdge)
{
    const RigidSolidSurface blade(Dictionary::parse("type box; min (0.3 0 0.2); max (0.32 0.1 0.45);", "constant/bodies"));
    EXPECT_TRUE(blade.facesNode(Vector3(0.31, 0.05, 0.3)));    // inside
    EXPECT_TRUE(blade.facesNode(Vector3(0.32, 0.05, 0.3)));    // on the front face
    EXPECT_TRUE(blade.facesNode(Vector3(0.32, 0.05, 0.2)));    // on the foot's edge
    EXPECT_TRUE(blade.facesNode(Vector3(0.33, 0.05, 0.3)));    // in front of the front face
    EXPECT_TRUE(blade.facesNode(Vector3(0.31, 0.05, 0.19)));   // below the foot
    EXPECT_TRUE(blade.facesNode(Vector3(0.31, 0.11, 0.3)));    // beside the side face
    EXPECT_FALSE(blade.facesNode(Vector3(0.33, 0.05, 0.2)));   // level with the foot, ahead of it
    EXPECT_FALSE(blade.facesNode(Vector3(0.33, 0.05, 0.19)));  // below and ahead
    EXPECT_FALSE(blade.facesNode(Vector3(0.33, 0.1, 0.3)));    // level with the side face, ahead
    EXPECT_FALSE(blade.facesNode(Vector3(0.31, 0.1, 0.19)));   // level with the side face, below
    EXPECT_FALSE(blade.facesNode(Vector3(0.33, 0.11, 0.19)));  // beyond the foot's corner

    // Standing on the grid's floor x3 = 0.2 (a silo's wall), the foot's face has no material
    // below it: the floor's node level with it, in front of the front face, faces the wall.
    RigidSolidSurface wall(Dictionary::parse("type box; min (0.3 0 0.2); max (0.32 0.1 0.45);", "constant/bodies"));
    wall.place(Particles<3>{}, 0, 0.01, Vector3(0, 0, 0.2), Vector3(1, 1, 1));
    EXPECT_TRUE(wall.facesNode(Vector3(0.33, 0.05, 0.2)));    // on the floor, in front of the face
    EXPECT_FALSE(wall.facesNode(Vector3(0.33, 0.1, 0.3)));    // level with the side face, ahead: as before
}

TEST(ThreeDContact, theCoulombLawStopsTheApproachAndSlowsTheSlideAgainstItsDirection)
{
    const Dictionary dict = Dictionary::parse("law coulombFriction; mu 0.3;\n", "contactProperties");
    const auto law = ContactLaw<3>::New(dict, {"a", "b"});
    const Vector3 n = Vector3(1, 2, 2) / 3.0;  // unit
    const Vector3 vRef(0.1, -0.2, 0.3);
    const Vector3 across = Vector3(2, -1, 0).normalized();  // normal to n
    ASSERT_NEAR(across.dot(n), 0.0, 1e-15);
    // Approaching at 0.5 and sliding at 2 across n: the approach goes, the slide loses 0.3 x 0.5.
    const Vector3 v = vRef + 0.5 * n + 2.0 * across;
    const Vector3 c = law->correct(v, vRef, n, 0, 1);
    EXPECT_NEAR((c - vRef).dot(n), 0.0, 1e-15);
    EXPECT_NEAR(((c - vRef) - (2.0 - 0.3 * 0.5) * across).norm(), 0.0, 1e-14);
    // Sliding at 0.1 < mu D: stopped, not reversed.
    const Vector3 slow = law->correct(vRef + 0.5 * n + 0.1 * across, vRef, n, 0, 1);
    EXPECT_NEAR((slow - vRef).norm(), 0.0, 1e-15);
    // Separating: untouched.
    const Vector3 away = vRef - 0.5 * n + 2.0 * across;
    EXPECT_EQ(law->correct(away, vRef, n, 0, 1), away);
}

namespace {

//- An elastic block (0.1 x 0.1 x 0.06 m) on a fixed steel plate, gravity tilted by theta from
//  -x3 towards the diagonal (cos 30, sin 30) of the plate; friction mu. The block's velocity
//  at 0.2 s.
Vector3 slideVelocity(const fs::path& dir, double thetaDeg, double mu,
                      const std::string& plateShape = "type box; min (0.02 0.02 0.02); max (0.38 0.30 0.06);",
                      const std::string& functions = "")
{
    const double th = thetaDeg * M_PI / 180, phi = M_PI / 6, g = 9.81;
    std::ostringstream gravity;
    gravity.precision(17);
    gravity << "value (" << g * std::sin(th) * std::cos(phi) << " " << g * std::sin(th) * std::sin(phi) << " "
            << -g * std::cos(th) << ");\n";
    writeDictionary(dir / "constant/g", gravity.str());
    writeDictionary(dir / "constant/grid", "origin (0 0 0); cellSize 0.02; nCells (20 16 8);\nboundaries { left { "
                                           "type slip; } right { type slip; } bottom { type slip; } top { type slip; } "
                                           "back { type slip; } front { type free; } }\n");
    writeDictionary(dir / "constant/materials", "rubber { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n"
                                                "steel { type linearElastic; rho 7800; E 1e6; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies",
                    "plate { material steel; shape { " + plateShape + " } particlesPerCell 2; }\n"
                    "block { material rubber; shape { type box; min (0.06 0.06 0.06); max (0.16 0.16 0.12); } "
                    "particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/rigidBodies", "plate { type fixed; }\n");
    writeDictionary(dir / "constant/contactProperties",
                    "law coulombFriction; mu " + std::to_string(mu) + "; normals rigidSurface; correctRemapped yes;\n");
    writeDictionary(dir / "system/controlDict", "startFrom latestTime; startTime 0; stopAt endTime;\nendTime 0.2;\n"
                                                "deltaT 2e-4; writeControl adjustableRunTime; writeInterval 1;\n" +
                                                    functions);
    const auto run = runAndKeep<3>(dir);
    const Particles<3>& p = run->solver().particles();
    Vector3 momentum = Vector3::Zero();
    double mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == 1) {
            momentum += p.m[q] * p.v[q];
            mass += p.m[q];
        }
    return momentum / mass;
}

} // namespace

TEST(ThreeDContact, aBlockSlidesDownATiltedPlateAtTheCoulombRateAndSticksBelowTheFrictionAngle)
{
    ScratchDir scratch{"slide3d"};
    const double g = 9.81, th = 30 * M_PI / 180, t = 0.2;
    const Vector3 along(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);  // the tilt's direction on the plate
    const Vector3 slip = slideVelocity(scratch.path() / "slip", 30, 0.2);
    const double expected = g * (std::sin(th) - 0.2 * std::cos(th)) * t;  // a t, 0.641 m/s
    std::printf("sliding at %.4f m/s along the tilt after %g s (Coulomb: %.4f)\n", slip.dot(along), t, expected);
    EXPECT_NEAR(slip.dot(along), expected, 0.01 * expected) << slip.transpose();
    EXPECT_LT((slip - slip.dot(along) * along).norm(), 0.01 * expected) << "slides along the tilt: " << slip.transpose();
    const Vector3 stick = slideVelocity(scratch.path() / "stick", 30, 0.7);  // tan 30 = 0.577
    EXPECT_LT(stick.norm(), 0.02 * expected) << stick.transpose();
}

TEST(ThreeDContact, twoSpheresMeetingOffCentreWithFrictionKeepTheirMomentumAndLoseEnergyOnlyInTheImpact)
{
    // The seed's two disks (4.4: rubber, E 1000 Pa, 0.1 m/s each way, USF and pure FLIP as the
    // twoDisks tutorial) as spheres of 0.2 m on 0.04 m cells, their centres 0.04 m apart across
    // the plane of approach: an oblique impact with friction, apart again by 3.2 s.
    ScratchDir scratch{"spheres3d"};
    const fs::path dir = scratch.path();
    writeDictionary(dir / "constant/grid", "origin (0 0 0); cellSize 0.04; nCells (25 25 15);\nboundaries { left { "
                                           "type free; } right { type free; } bottom { type free; } top { type free; } "
                                           "back { type free; } front { type free; } }\n");
    writeDictionary(dir / "constant/materials", "rubber { type linearElastic; rho 1000; E 1000; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies",
                    "a { material rubber; shape { type sphere; centre (0.2 0.8 0.28); radius 0.2; } "
                    "particlesPerCell 2; velocity (0.1 -0.1 0); }\n"
                    "b { material rubber; shape { type sphere; centre (0.8 0.2 0.32); radius 0.2; } "
                    "particlesPerCell 2; velocity (-0.1 0.1 0); }\n");
    writeDictionary(dir / "constant/g", "value (0 0 0);\n");
    writeDictionary(dir / "constant/contactProperties", "law coulombFriction; mu 0.1; correctRemapped no;\n");
    writeDictionary(dir / "system/mpmSchemes", "updateScheme USF; transfer FLIP;\n");
    writeDictionary(dir / "system/controlDict", "startFrom latestTime; startTime 0; stopAt endTime;\nendTime 3.2;\n"
                                                "deltaT 1e-3; writeControl adjustableRunTime; writeInterval 4;\n"
                                                "functions { motion { type bodyMotion; writeInterval 100; } }\n");
    runAndKeep<3>(dir);
    const auto col = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    const auto& t = col.at("time");
    const auto& E = col.at("E");
    const double E0 = E.front(), p0 = col.at("a:px").front();
    for (std::size_t k = 0; k < t.size(); ++k) {
        for (const char* axis : {"px", "py", "pz"}) {
            EXPECT_NEAR(col.at(std::string("a:") + axis)[k] + col.at(std::string("b:") + axis)[k], 0.0, 1e-9 * p0)
                << axis << " at t = " << t[k];
        }
        if (t[k] < 1.2) {
            EXPECT_NEAR(E[k], E0, 1e-9 * E0) << "before contact, t = " << t[k];
        }
    }
    const double loss = (E0 - E.back()) / E0;
    std::printf("energy lost in the impact: %.2f %% (the seed's disks: a few per cent)\n", 100 * loss);
    EXPECT_GT(loss, 0.005);
    EXPECT_LT(loss, 0.10);
    EXPECT_LT(col.at("a:px").back(), -0.5 * p0) << "sphere a rebounds";
}

TEST(ThreeDContact, theTwoDisksWithFrictionAsASlabBetweenSymmetryFacesGiveThePlaneRun)
{
    // The seed's two disks (4.4) with Coulomb friction, through the start of their impact, as
    // the plane case and as a 3D slab one cell thick between symmetry faces: the symmetry
    // faces reflect the bodies' mass gradients, so the contact normals are the plane ones and
    // the slab's stresses and velocities are the plane run's to round-off.
    ScratchDir scratch{"disksSlab"};
    const fs::path plane = scratch.path() / "plane", slab = scratch.path() / "slab";
    copyCase(tutorialPath("verification/twoDisks"), plane);
    copyCase(tutorialPath("verification/twoDisks"), slab);
    for (const fs::path& dir : {plane, slab}) {
        writeDictionary(dir / "constant/contactProperties", "law coulombFriction; mu 0.1; correctRemapped no;\n");
        setEntry(dir / "system/controlDict", "endTime", "1.6");
        setEntry(dir / "system/controlDict", "writeInterval", "1.6");
    }
    writeDictionary(slab / "constant/grid", "origin (0 0 0); cellSize 0.04; nCells (25 25 1);\nboundaries { left { "
                                            "type free; } right { type free; } bottom { type free; } top { type free; "
                                            "} back { type symmetry; } front { type symmetry; } }\n");
    writeDictionary(slab / "constant/bodies",
                    "upperLeft { material rubber; shape { type cylinder; point1 (0.2 0.8 0); point2 (0.2 0.8 0.04); "
                    "radius 0.2; } particlesPerCell 2; velocity (0.1 -0.1 0); }\n"
                    "lowerRight { material rubber; shape { type cylinder; point1 (0.8 0.2 0); point2 (0.8 0.2 0.04); "
                    "radius 0.2; } particlesPerCell 2; velocity (-0.1 0.1 0); }\n");
    const auto a = runAndKeep<2>(plane);
    const auto b = runAndKeep<3>(slab);
    const Particles<2>& p = a->solver().particles();
    const Particles<3>& q = b->solver().particles();
    ASSERT_EQ(q.size(), 2 * p.size());
    std::map<std::pair<double, double>, std::size_t> twin;
    for (std::size_t k = 0; k < p.size(); ++k) twin[{p.x0[k].x(), p.x0[k].y()}] = k;
    double sMax = 0, dStress = 0, dVelocity = 0;
    for (std::size_t k = 0; k < q.size(); ++k) {
        const std::size_t m = twin.at({q.x0[k].x(), q.x0[k].y()});
        for (int c : {XX, YY, ZZ, XY}) {
            sMax = std::max(sMax, std::abs(p.sigma[m][c]));
            dStress = std::max(dStress, std::abs(q.sigma[k][c] - p.sigma[m][c]));
        }
        dVelocity = std::max(dVelocity, (q.v[k].head<2>() - p.v[m]).norm());
    }
    ASSERT_GT(a->solver().timers().seconds("contact"), 0.0) << "the disks have met";
    ASSERT_GT(sMax, 100.0) << "the impact stresses the disks";
    EXPECT_LT(dStress, 1e-9 * sMax);
    EXPECT_LT(dVelocity, 1e-9 * 0.1);
}

TEST(ThreeDContact, theBlockSlidingOnAToolDrawnInCadWearsItByArchardsLaw)
{
    // The sliding block on the plate drawn as STL (each of its facets split in four, four times:
    // edges of 0.0225 m and less), toolWear on the plate: Archard's worn volume is (k/H) N s, N = m g cos
    // theta the block's weight across the plate and s the distance it slid, within 3 %; the
    // wear lies on the top face alone, under the block's path, and the surface file carries
    // it as wearDepth (volume over area per facet).
    ScratchDir scratch{"wear3d"};
    const fs::path dir = scratch.path();
    const StlSurface plate = subdivided(boxSurface({0.02, 0.02, 0.02}, {0.38, 0.30, 0.06}), 4);
    writeBinaryStl(dir / "constant/triSurface/plate.stl", plate);
    const double k = 1e-4, H = 2e9, th = 30 * M_PI / 180, g = 9.81, mu = 0.2, t = 0.2;
    const Vector3 v = slideVelocity(dir, 30, mu, "type triSurface; file \"triSurface/plate.stl\";",
                                    "functions { wear { type toolWear; body plate; wearCoefficient 1e-4; hardness 2e9; "
                                    "writeInterval 100; } motion { type bodyMotion; writeInterval 100; } }\n");
    const auto wear = readColumns(dir / "postProcessing/wear/0/wear.dat");
    const auto motion = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    ASSERT_NEAR(wear.at("time").back(), t, 1e-9);
    const Vector3 along(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);
    const double s = (motion.at("block:x").back() - motion.at("block:x").front()) * along.x() +
                     (motion.at("block:y").back() - motion.at("block:y").front()) * along.y();
    const double m = 1000 * 0.1 * 0.1 * 0.06, N = m * g * std::cos(th), expected = k / H * N * s;
    std::printf("slid %.4f m at %.3f m/s: worn %.4g m^3, Archard %.4g m^3\n", s, v.dot(along), wear.at("volume").back(), expected);
    EXPECT_NEAR(wear.at("volume").back(), expected, 0.03 * expected);
    const SurfaceVtkInfo surface = readSurface((dir / "postProcessing/wear/0/plateWear.vtp").string());
    ASSERT_EQ(surface.fields.size(), 1u);
    ASSERT_EQ(surface.fields[0].name, "wearDepth");
    ASSERT_EQ(surface.fields[0].values.size(), plate.facets.size());
    double onTop = 0, elsewhere = 0, deepest = 0;
    for (std::size_t f = 0; f < plate.facets.size(); ++f) {
        const auto& c = plate.corners;
        const auto& tri = plate.facets[f];
        const Eigen::Vector3d n = (c[tri[1]] - c[tri[0]]).cross(c[tri[2]] - c[tri[0]]);
        const double volume = surface.fields[0].values[f] * 0.5 * n.norm();
        (n.z() > 0 && std::abs(c[tri[0]].z() - 0.06) < 1e-12 ? onTop : elsewhere) += volume;
        deepest = std::max(deepest, surface.fields[0].values[f]);
        // Nothing wears far from the block's track (it starts on x1, x2 in [0.06, 0.16] and
        // slides about 0.06 m along (cos 30, sin 30)).
        const Eigen::Vector3d centre = (c[tri[0]] + c[tri[1]] + c[tri[2]]) / 3;
        if (centre.x() > 0.30 || centre.y() > 0.28) EXPECT_EQ(surface.fields[0].values[f], 0.0) << "facet " << f;
    }
    // (The binary STL holds single-precision corners: the areas here differ from the run's by 1e-7.)
    EXPECT_NEAR(onTop, wear.at("volume").back(), 1e-6 * expected);
    EXPECT_LT(elsewhere, 1e-12 * expected);
    EXPECT_NEAR(deepest, wear.at("maxDepth").back(), 1e-9 * deepest);
}
