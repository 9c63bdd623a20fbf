// What a design study compares tools by: the toolWear function object (Archard wear along a
// rigid tool's face), the work a tool does (forces' <body>:W) and what it carries (toolFill). Wear: an elastic
// block (60 x 30 mm, rho 1000) slides over a fixed rigid plate, the tool, under its own
// weight W = rho g A, from v0 = 0.05 m/s. The plate's top face carries p = rho g H and the
// block slides over it at v(t) = v0 - mu g t until it stops (Coulomb friction, mu g the
// deceleration). Archard's local law, dh/dt = (k/H) p v, integrates to
//     worn volume V = (k/H) W d,  d the distance slid: v0 t (mu 0) or v0^2 / (2 mu g),
//     depth h = (k/H) p d where the block covered the face throughout.
// The wear is also checked against the distance the block actually slid (bodyMotion), which
// separates the wear integral from the friction law's own accuracy.
// Work: a plate moving at V drags a block at rest until it moves with it. Friction works on
// the block through the relative distance V^2 / (2 mu g) and on the plate through twice that:
// the plate spends W = m V^2, half as the block's kinetic energy and half lost to friction,
// whatever mu.
// Fill: under a frictionless block at rest the plate slides at V; a region fixed to the plate
// that starts over the block leaves it, so the mass inside falls as rho H (overlap), the
// overlap 0.06 m - V t.
#include "support/Applications.H"
#include "support/BlockOnPlate.H"
#include "support/CaseRunner.H"

#include <cmath>
#include <iomanip>

using namespace gpic;
using namespace gpic::test;

namespace {

constexpr double g = 9.81, rho = 1000, width = 0.06, height = 0.03, v0 = 0.05, kOverH = 1e-3 / 1e6;

fs::path slidingBlock(const fs::path& dir, double mu, double endTime, const std::string& plate = "type fixed;",
                      const std::string& blockVelocity = "(0.05 0)")
{
    std::ostringstream control;
    control << "endTime " << endTime << "; deltaT 1; adjustTimeStep yes; maxCourant 0.4;\n"
            << "writeControl runTime; writeInterval " << endTime << ";\n"
            << "functions {\n"
               "  motion { type bodyMotion; writeInterval 50; }\n"
               "  forces { type forces; bodies (plate); writeInterval 50; }\n"
               "  fill { type toolFill; body plate; region { type rectangle; min (0.07 0.02); max (0.13 0.06); }\n"
               "         writeInterval 50; }\n"
               "  wear { type toolWear; body plate; wearCoefficient 1e-3; hardness 1e6; resolution 0.005;\n"
               "         faces { top { from (0.18 0.02); to (0.02 0.02); } } writeInterval 50; }\n"
               "}\n";
    writeDictionary(dir / "system/controlDict", control.str());
    std::ostringstream contact;
    contact << "law coulombFriction; mu " << mu << "; normals rigidSurface; correctRemapped yes;\n";
    writeBlockOnPlate(dir, contact.str(), plate, blockVelocity);
    return dir;
}

struct Wear {
    double volume, maxDepth, middleDepth, slid;
    double time;  //- of the last row (rows every 50 steps: short of endTime by up to 50 steps)
};

Wear runWear(const fs::path& dir)
{
    runAndKeep(dir);
    const auto wear = readColumns(dir / "postProcessing/wear/0/wear.dat");
    const auto motion = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    const auto profile = readColumns(dir / "postProcessing/wear/0/wearProfile.dat");
    // The middle of the face at the last row: x = 0.1 lies under the block throughout.
    double middle = 0;
    for (std::size_t k = 0; k < profile.at("time").size(); ++k)
        if (profile.at("time")[k] == wear.at("time").back() && std::abs(profile.at("x")[k] - 0.1025) < 1e-9)
            middle = profile.at("depth")[k];
    return {wear.at("top:volume").back(), wear.at("top:maxDepth").back(), middle,
            motion.at("block:x").back() - motion.at("block:x").front(), wear.at("time").back()};
}

} // namespace

TEST(ToolWear, frictionlessSlidingWearsAsArchardAtConstantSpeed)
{
    ScratchDir scratch("toolWear");
    const double endTime = 0.1;
    const Wear w = runWear(slidingBlock(scratch.path() / "frictionless", 0.0, endTime));
    const double W = rho * g * width * height, p = rho * g * height, d = v0 * w.time;
    EXPECT_GT(w.time, 0.95 * endTime);
    std::cout << "frictionless: slid " << w.slid << " m (closed form " << d << "), volume " << w.volume
              << " (closed form " << kOverH * W * d << "), middle depth " << w.middleDepth << " (" << kOverH * p * d
              << ")\n";
    EXPECT_NEAR(w.slid, d, 0.01 * d);
    EXPECT_NEAR(w.volume, kOverH * W * d, 0.01 * kOverH * W * d);
    EXPECT_NEAR(w.middleDepth, kOverH * p * d, 0.1 * kOverH * p * d);
    EXPECT_GE(w.maxDepth, w.middleDepth);
}

TEST(ToolWear, frictionStopsTheBlockAndTheWearWithIt)
{
    ScratchDir scratch("toolWear");
    const double mu = 0.05, stop = v0 / (mu * g);  // 0.102 s
    const fs::path dir = slidingBlock(scratch.path() / "frictional", mu, 1.5 * stop);
    const Wear w = runWear(dir);
    const double W = rho * g * width * height, d = v0 * v0 / (2 * mu * g);
    std::cout << "mu " << mu << ": slid " << w.slid << " m (closed form " << d << "), volume " << w.volume
              << " (closed form " << kOverH * W * d << ", from the distance slid " << kOverH * W * w.slid << ")\n";
    EXPECT_NEAR(w.slid, d, 0.03 * d);
    EXPECT_NEAR(w.volume, kOverH * W * w.slid, 0.02 * kOverH * W * w.slid);
    EXPECT_NEAR(w.volume, kOverH * W * d, 0.03 * kOverH * W * d);

    // picForces -wear: the last profile as CSV and its deepest point, the file's own figure.
    const AppResult r = runApplication("picForces", dir, "-wear");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream csv(dir / "postProcessing/picForces/wear.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "face,s,x,y,depth");
    int rows = 0;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, 32);  // 0.16 m of face in 5 mm bins
    std::ostringstream deepest;
    deepest << "largest depth " << std::setprecision(6) << w.maxDepth << " m";
    EXPECT_NE(r.out.find(deepest.str()), std::string::npos) << r.out;
}

TEST(ToolWear, refusesABodyThatIsNotRigidAndASceneWithoutBodyFields)
{
    ScratchDir scratch("toolWear");
    fs::path dir = slidingBlock(scratch.path() / "notRigid", 0.0, 0.001);
    std::string control;
    {
        std::ifstream in(dir / "system/controlDict");
        control.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string text = control;
        text.replace(text.find(from), from.size(), to);
        return text;
    };
    writeDictionary(dir / "system/controlDict", replaced("type toolWear; body plate;", "type toolWear; body block;"));
    try {
        runAndKeep(dir);
        ADD_FAILURE() << "a deformable body was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("toolWear wear: 'block' is not a rigid body"), std::string::npos)
            << e.what();
    }
    dir = slidingBlock(scratch.path() / "oneField", 0.0, 0.001);
    writeDictionary(dir / "constant/contactProperties", "law noSlip;\n");
    try {
        runAndKeep(dir);
        ADD_FAILURE() << "a scene with one velocity field was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("does not slide"), std::string::npos) << e.what();
    }
}

TEST(ToolWork, aPlateDraggingABlockUpToItsSpeedSpendsMVSquared)
{
    ScratchDir scratch("toolWork");
    const double V = 0.05, mu = 0.2, m = rho * width * height;
    const fs::path dir = slidingBlock(scratch.path() / "drag", mu, 3 * V / (mu * g),
                                      "type prescribedVelocity; velocity (0.05 0);", "(0 0)");
    runAndKeep(dir);
    const auto forces = readColumns(dir / "postProcessing/forces/0/forces.dat");
    const auto motion = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    const double W = forces.at("plate:W").back();
    std::cout << "plate's work " << W << " J/m (m V^2 = " << m * V * V << "), block's speed "
              << motion.at("block:vx").back() << " m/s\n";
    EXPECT_NEAR(motion.at("block:vx").back(), V, 0.02 * V);  // carried along by then
    EXPECT_NEAR(W, m * V * V, 0.02 * m * V * V);
}

TEST(ToolFill, aRegionFixedToASlidingPlateLeavesTheBlockItStartedUnder)
{
    ScratchDir scratch("toolFill");
    const double V = 0.05, endTime = 0.3;
    const fs::path dir = slidingBlock(scratch.path() / "fill", 0.0, endTime,
                                      "type prescribedVelocity; velocity (0.05 0);", "(0 0)");
    runAndKeep(dir);
    const auto fill = readColumns(dir / "postProcessing/fill/0/fill.dat");
    const auto& t = fill.at("time");
    ASSERT_GT(t.size(), 10u);
    EXPECT_NEAR(fill.at("mass").front(), rho * width * height, 1e-9);  // the whole block at the start
    // Particles count by their centres, 2.5 mm apart: the mass falls in steps of a column.
    const double column = rho * height * 0.0025;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double overlap = std::max(0.0, width - V * t[k]);
        EXPECT_NEAR(fill.at("mass")[k], rho * height * overlap, column) << "t = " << t[k];
        EXPECT_NEAR(fill.at("dx")[k], V * t[k], 1e-9);
        EXPECT_NEAR(fill.at("travel")[k], V * t[k], 1e-9);
        EXPECT_NEAR(fill.at("rotation")[k], 0.0, 1e-9);
    }
    EXPECT_LT(fill.at("mass").back(), 0.8 * rho * width * height);
}
