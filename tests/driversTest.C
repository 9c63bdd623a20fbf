// Rigid-body drivers (constant/rigidBodies): the velocity a prescribed driver gives from a
// constant, a table, an expression and a rotation; the servo stop at a target force; and a
// weighted body, which must fall freely as x0 + g t^2/2 and come to rest where the material
// carries its weight.
#include "bodies/Expression.H"
#include "bodies/TimeFunction.H"
#include "rigidBodyDrivers/PrescribedVelocityDriver.H"
#include "rigidBodyDrivers/WeightedDriver.H"
#include "support/CaseRunner.H"

#include <algorithm>
#include <cmath>

using namespace gpic;
using namespace gpic::test;

namespace {

const double pi = 3.14159265358979323846;

//- The driver of the one body in a constant/rigidBodies text.
std::unique_ptr<RigidBodyDriver<2>> driver(const std::string& entry)
{
    const Dictionary d = Dictionary::parse("body { " + entry + " }", "constant/rigidBodies");
    return RigidBodyDriver<2>::New(d.subDict("body"));
}

//- The InputError message of a driver, or "" when it constructs.
std::string driverError(const std::string& text)
{
    try {
        const Dictionary d = Dictionary::parse(text, "constant/rigidBodies");
        RigidBodyDriver<2>::New(d.subDict("body"));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

// ---------------------------------------------------------------- expressions and tables

TEST(Drivers, expressionsFollowTheRulesOfArithmetic)
{
    const auto at = [](const std::string& text, double t) { return Expression(text, "f", 1)(t); };
    EXPECT_NEAR(at("0.1*sin(2*pi*t)", 0.25), 0.1, 1e-15);
    EXPECT_DOUBLE_EQ(at("-t^2", 3), -9);          // unary minus binds looser than ^
    EXPECT_DOUBLE_EQ(at("2^3^2", 0), 512);        // ^ is right-associative
    EXPECT_DOUBLE_EQ(at("1 - 2 - 3", 0), -4);     // - is left-associative
    EXPECT_DOUBLE_EQ(at("12 / 3 / 2", 0), 2);
    EXPECT_DOUBLE_EQ(at("abs(-2) + sqrt(16) / exp(0) * (1 + 1)", 0), 10);
    EXPECT_DOUBLE_EQ(at("cos(pi)", 0), -1);
    EXPECT_DOUBLE_EQ(at("2.5e-1 * t", 4), 1);
    EXPECT_FALSE(Expression("2*pi", "f", 1).dependsOnTime());
}

TEST(Drivers, aBadExpressionNamesFileLineAndTheValidNames)
{
    const std::string e1 = driverError("body\n{\n    type prescribedVelocity;\n    velocity (\"0.1*sinn(t)\" 0);\n}\n");
    EXPECT_TRUE(contains(e1, "constant/rigidBodies:4:")) << e1;
    EXPECT_TRUE(contains(e1, "unknown name 'sinn'")) << e1;
    EXPECT_TRUE(contains(e1, "valid names: t, pi, sin, cos, exp, sqrt, abs")) << e1;
    for (const char* bad : {"(t", "t*", "2 3", "sin t", "t + ", "", "x"}) {
        try {
            Expression(bad, "constant/rigidBodies", 7);
            ADD_FAILURE() << "no error for \"" << bad << "\"";
        } catch (const InputError& e) {
            EXPECT_TRUE(contains(e.what(), "constant/rigidBodies:7: expression \"" + std::string(bad) + "\"")) << e.what();
        }
    }
    // Deep nesting is refused, not a stack overflow.
    EXPECT_THROW(Expression(std::string(100000, '(') + "t" + std::string(100000, ')'), "f", 1), InputError);
}

TEST(Drivers, anExpressionThatIsNotFiniteStopsTheRunNamingIt)
{
    const auto d = driver("type prescribedVelocity; velocity (\"sqrt(t - 1)\" 0);");
    EXPECT_NEAR(d->velocity(2.0, Vector2::Zero()).x(), 1.0, 1e-15);
    try {
        d->velocity(0.5, Vector2::Zero());
        FAIL() << "no error";
    } catch (const RunError& e) {
        EXPECT_TRUE(contains(e.what(), "expression \"sqrt(t - 1)\" (constant/rigidBodies:1) is")) << e.what();
        EXPECT_TRUE(contains(e.what(), "at t = 0.5 s")) << e.what();
    }
}

TEST(Drivers, aVelocityTableIsPiecewiseLinearAndHoldsItsEnds)
{
    const auto d = driver("type prescribedVelocity; velocity table ((0 0 0) (1 1 -2) (3 1 -2) (4 0 0));");
    const Vector2 x(0.3, 0.7);
    EXPECT_TRUE(d->velocity(0.5, x).isApprox(Vector2(0.5, -1.0), 1e-15));
    EXPECT_TRUE(d->velocity(2.0, x).isApprox(Vector2(1.0, -2.0), 1e-15));
    EXPECT_TRUE(d->velocity(3.25, x).isApprox(Vector2(0.75, -1.5), 1e-15));
    EXPECT_TRUE(d->velocity(9.0, x).isZero(0.0));   // after the last row: its value
    EXPECT_TRUE(d->velocity(-1.0, x).isZero(0.0));  // before the first row: its value

    // Its integral, exact: area under the trapezoids.
    const auto table = TimeFunction({0, 1, 3, 4}, {0, 1, 1, 0});
    EXPECT_DOUBLE_EQ(table.integral(0, 4), 3.0);
    EXPECT_DOUBLE_EQ(table.integral(0.5, 3.5), 0.375 + 2.0 + 0.375);
    EXPECT_DOUBLE_EQ(table.integral(4, 6), 0.0);
}

TEST(Drivers, aVelocityExpressionIsEvaluatedPerComponent)
{
    const auto d = driver("type prescribedVelocity; velocity (\"0.1*sin(2*pi*t)\" -0.5);");
    for (double t : {0.0, 0.1, 0.25, 0.8}) {
        const Vector2 v = d->velocity(t, Vector2(5, 5));
        EXPECT_NEAR(v.x(), 0.1 * std::sin(2 * pi * t), 1e-15);
        EXPECT_EQ(v.y(), -0.5);
    }
}

TEST(Drivers, aRotatingBodyTurnsAboutACentreThatMovesWithIt)
{
    // v(x) = v_c + omega e_z x (x - c(t)), c(t) = c(0) + v_c t.
    const auto d = driver("type prescribedVelocity; velocity (0.5 0); omega 2; centre (1 0);");
    const double t = 2.0;
    const Vector2 c(1.0 + 0.5 * t, 0.0);
    EXPECT_TRUE(d->velocity(t, c).isApprox(Vector2(0.5, 0.0), 1e-14));
    EXPECT_TRUE(d->velocity(t, c + Vector2(0, 1)).isApprox(Vector2(0.5 - 2.0, 0.0), 1e-14));
    EXPECT_TRUE(d->velocity(t, c + Vector2(1, 0)).isApprox(Vector2(0.5, 2.0), 1e-14));
    // Unit brackets document a value and change nothing.
    const auto u = driver("type prescribedVelocity; velocity [m/s] (0.5 0); omega [rad/s] 2; centre (1 0);");
    EXPECT_TRUE(u->velocity(t, c + Vector2(1, 0)).isApprox(Vector2(0.5, 2.0), 1e-14));

    // With v_c an expression, c(t) is its integral: c_x(t) = 1 + 0.1 (1 - cos 2 pi t) / (2 pi).
    const auto w = driver("type prescribedVelocity; velocity (\"0.1*sin(2*pi*t)\" 0); "
                          "omega table ((0 0) (1 3)); centre (1 0);");
    const auto* pw = dynamic_cast<const PrescribedVelocityDriver<2>*>(w.get());
    ASSERT_NE(pw, nullptr);
    for (double s : {0.01, 0.3, 0.3 + 1e-6, 0.75, 0.2}) {  // forward, a small step, and back again
        const double cx = 1.0 + 0.1 * (1.0 - std::cos(2 * pi * s)) / (2 * pi);
        EXPECT_NEAR(pw->centre(s).x(), cx, 1e-13) << "t = " << s;
        const Vector2 v = w->velocity(s, Vector2(cx, 1.0));  // one metre above the centre
        EXPECT_NEAR(v.x(), 0.1 * std::sin(2 * pi * s) - 3.0 * s, 1e-12) << "t = " << s;
        EXPECT_NEAR(v.y(), 0.0, 1e-15);
    }
}

TEST(Drivers, aTurningBodyKeepsItsShapeStepByStep)
{
    // One full turn in 100 steps about a centre that translates: each point must come back
    // to its start shifted by v_c T, at its original distance from the centre. A first-order
    // step x += dt v(t + dt, x) would grow the radius by about pi omega dt per turn (3 % here).
    const double omega = 2.0, T = 2 * pi / omega, dt = T / 100;
    const auto d = driver("type prescribedVelocity; velocity (0.5 0); omega 2; centre (1 0);");
    Vector2 x(1.0, 0.25);
    double t = 0;
    for (int step = 0; step < 100; ++step, t += dt) {
        x = d->move(t, dt, x);
        const Vector2 c(1.0 + 0.5 * (t + dt), 0.0);
        ASSERT_NEAR((x - c).norm(), 0.25, 1e-12) << "step " << step;
    }
    EXPECT_NEAR(x.x(), 1.0 + 0.5 * T, 1e-12);
    EXPECT_NEAR(x.y(), 0.25, 1e-12);
}

TEST(Drivers, badDriverInputNamesTheKeyword)
{
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; omega 1; }"), "omega needs centre"));
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; }"), "needs velocity"));
    const std::string table = driverError("body\n{\n type prescribedVelocity;\n velocity table ((0 0 0) (0 1 1));\n}");
    EXPECT_TRUE(contains(table, "constant/rigidBodies:4:")) << table;
    EXPECT_TRUE(contains(table, "increase strictly")) << table;
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; velocity table ((0 0) (1 1)); }"),
                         "each row is (t x y)"));
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; velocity (1 2 3); }"),
                         "expected (x y) with numbers or \"expressions of t\""));
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; omega (1 2); centre (0 0); }"),
                         "expected a number, an \"expression of t\" or table"));
    EXPECT_TRUE(contains(driverError("body { type prescribedVelocity; velocity (0 1); targetForce (0 0); }"),
                         "a non-zero force"));
    EXPECT_TRUE(contains(driverError("body { type weighted; free (0 0); }"), "no free direction"));
    EXPECT_TRUE(contains(driverError("body { type weighted; free (0 2); }"), "1 (free) or 0 (prescribed)"));
    EXPECT_TRUE(contains(driverError("body { type weighted; damping 1; }"), "damping must lie in [0, 1)"));
}

// ---------------------------------------------------------------- target force

TEST(Drivers, aTargetForceStopsTheBodyWhenTheMaterialPushesBackHardEnough)
{
    auto d = driver("type prescribedVelocity; velocity (0 -0.01); targetForce (0 100);");
    const auto* p = dynamic_cast<const PrescribedVelocityDriver<2>*>(d.get());
    d->attach(RigidBodyInfo<2>{1.0, Vector2::Zero(), 0.0, Vector2(0, -0.01), Vector2::Zero()});
    RigidBodyLoad<2> load;
    load.force = Vector2(500, 99.9);  // large, but not along the target
    d->advance(0.0, 1e-3, load);
    EXPECT_FALSE(p->stopped());
    EXPECT_EQ(d->velocity(1e-3, Vector2::Zero()).y(), -0.01);
    load.force = Vector2(0, 100.0);
    d->advance(1e-3, 1e-3, load);
    EXPECT_TRUE(p->stopped());
    EXPECT_TRUE(d->velocity(2e-3, Vector2::Zero()).isZero(0.0));
    load.force = Vector2(0, 10.0);  // unloading does not restart it
    d->advance(2e-3, 1e-3, load);
    EXPECT_TRUE(d->velocity(3e-3, Vector2::Zero()).isZero(0.0));

    // A restart finds the body at rest although its prescribed motion is not: it had stopped.
    auto r = driver("type prescribedVelocity; velocity (0 -0.01); targetForce (0 100);");
    r->attach(RigidBodyInfo<2>{1.0, Vector2::Zero(), 0.0, Vector2::Zero(), Vector2::Zero()});
    EXPECT_TRUE(r->velocity(0.5, Vector2::Zero()).isZero(0.0));
    // ... but a run from t = 0 with the body at rest moves it.
    auto s = driver("type prescribedVelocity; velocity (0 -0.01); targetForce (0 100);");
    s->attach(RigidBodyInfo<2>{1.0, Vector2::Zero(), 0.0, Vector2::Zero(), Vector2::Zero()});
    EXPECT_EQ(s->velocity(0.0, Vector2::Zero()).y(), -0.01);
}

namespace {

//- An elastic block (1 m wide, 0.5 m high, E = 1 MPa, nu = 0.3) in a smooth box with a fixed
//  bottom, and a steel plate 0.2 m thick resting on it: `plateDriver` drives the plate.
fs::path writePlateOnBlock(const ScratchDir& scratch, const std::string& plateDriver, double endTime,
                           double damping)
{
    const fs::path dir = scratch.path() / "plateOnBlock";
    fs::create_directories(dir / "system");
    fs::create_directories(dir / "constant");
    std::ofstream(dir / "system/controlDict")
        << "endTime " << endTime << ";\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
        << "writeControl adjustableRunTime;\nwriteInterval " << endTime << ";\ndamping " << damping << ";\n"
        << "functions { forces { type forces; bodies (plate); writeInterval 5; } }\n";
    std::ofstream(dir / "constant/grid")
        << "origin (0 0);\ncellSize 0.1;\nnCells (10 8);\n"
        << "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } }\n";
    std::ofstream(dir / "constant/materials")
        << "soil { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n"
        << "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n";
    std::ofstream(dir / "constant/bodies")
        << "block { material soil; particlesPerCell 2; shape { type rectangle; min (0 0); max (1 0.5); } }\n"
        << "plate { material steel; particlesPerCell 2; shape { type rectangle; min (0 0.5); max (1 0.7); } }\n";
    std::ofstream(dir / "constant/g") << "value (0 -9.81);\n";
    std::ofstream(dir / "constant/rigidBodies") << "plate { " << plateDriver << " }\n";
    return dir;
}

} // namespace

TEST(Drivers, aFootingPushedToATargetForceStopsThereAndHoldsIt)
{
    // The plate is pushed into the block at 5 mm/s until the block pushes back with 20 kN/m,
    // then held still: the block (damped) settles with the plate's face where it stopped.
    ScratchDir scratch("targetForce");
    const double target = 20e3;
    const fs::path dir = writePlateOnBlock(
        scratch, "type prescribedVelocity; velocity (0 -0.005); targetForce (0 " + std::to_string(target) + ");",
        4.0, 0.7);
    std::ofstream(dir / "constant/g") << "value (0 0);\n";  // the target alone loads the block
    runCase(dir);
    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    const auto& t = c["time"];
    const auto& Fy = c["plate:Fy"];
    const auto& dy = c["plate:dy"];
    // Stopped: no movement over the second half of the run.
    const std::size_t half = t.size() / 2;
    EXPECT_LT(dy.back(), -1e-3);
    EXPECT_NEAR(dy[half], dy.back(), 1e-12);
    // The target was reached (the stop overshoots by at most one step of loading) and is held:
    // a uniaxially strained elastic block keeps the force of the displacement it was given.
    EXPECT_GE(*std::max_element(Fy.begin(), Fy.end()), 0.99 * target);  // rows every 5 steps
    EXPECT_NEAR(Fy.back(), target, 0.03 * target);
}

// ---------------------------------------------------------------- weighted bodies

TEST(Drivers, aWeightedBodyFallsFreelyAsX0PlusGtSquaredOverTwo)
{
    ScratchDir scratch("freeFall");
    const fs::path dir = scratch.path() / "freeFall";
    fs::create_directories(dir / "system");
    fs::create_directories(dir / "constant");
    // 25 000 steps of 2 us: semi-implicit Euler gives x0 + g t^2/2 + g t dt/2 (from rest), an
    // error of g t dt / 2 = 4.9e-7 m at t = 0.05 s.
    const double T = 0.05, dt = 2e-6, g = 9.81;
    std::ofstream(dir / "system/controlDict")
        << "endTime " << T << ";\ndeltaT " << dt << ";\nwriteControl timeStep;\nwriteInterval 100000;\n"
        << "functions { forces { type forces; writeInterval 250; } }\n";
    std::ofstream(dir / "constant/grid")
        << "origin (0 0);\ncellSize 0.1;\nnCells (4 4);\n"
        << "boundaries { left { type free; } right { type free; } bottom { type free; } top { type free; } }\n";
    std::ofstream(dir / "constant/materials") << "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n";
    std::ofstream(dir / "constant/bodies")
        << "ball { material steel; particlesPerCell 2; shape { type rectangle; min (0.1 0.2); max (0.3 0.3); } }\n";
    std::ofstream(dir / "constant/g") << "value (0 " << -g << ");\n";
    std::ofstream(dir / "constant/rigidBodies") << "ball { type weighted; free (1 1); }\n";
    const auto simulation = runAndKeep(dir);

    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    ASSERT_GE(c["time"].size(), 99u);
    for (std::size_t k = 0; k < c["time"].size(); ++k) {
        const double t = c["time"][k];
        EXPECT_NEAR(c["ball:dy"][k], -0.5 * g * t * t, 1e-6) << "t = " << t;
        EXPECT_NEAR(c["ball:dy"][k], -0.5 * g * t * t - 0.5 * g * t * dt, 1e-10) << "t = " << t;
        EXPECT_EQ(c["ball:dx"][k], 0.0);
        EXPECT_NEAR(c["ball:Fy"][k], 0.0, 1e-9);  // nothing to push on
    }
    for (const Vector2& v : simulation->solver().particles().v) EXPECT_NEAR(v.y(), -g * T, 1e-10);
}

TEST(Drivers, aWeightedPlateSettlesWhereTheBlockCarriesItsWeight)
{
    // Plate m = 7850 x 1 x 0.2 = 1570 kg/m on the block; with the block's sides smooth and its
    // bottom fixed the block is in uniaxial strain: once at rest the reaction is m g, and the
    // top has settled by (m g / W) H / M + rho g H^2 / (2 M), M = K + 4G/3 (eq. H.2.1).
    // Damped as in the seed's equilibrium stages (alpha = 0.5 on the block and on the plate):
    // undamped, the one-step lag of the reaction would let the plate ring ever louder.
    ScratchDir scratch("weighted");
    const fs::path dir = writePlateOnBlock(scratch, "type weighted; free (0 1); damping 0.5;", 3.0, 0.5);
    runCase(dir);
    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    const double g = 9.81, m = 7850 * 0.2, W = 1.0, H = 0.5, rho = 1000, E = 1e6, nu = 0.3;
    const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    const double settlement = (m * g / W) * H / M + rho * g * H * H / (2 * M);
    // Mean over the last 0.5 s.
    double Fy = 0, dy = 0;
    int n = 0;
    for (std::size_t k = 0; k < c["time"].size(); ++k) {
        if (c["time"][k] < 2.5) continue;
        Fy += c["plate:Fy"][k];
        dy += c["plate:dy"][k];
        ++n;
    }
    ASSERT_GT(n, 10);
    Fy /= n;
    dy /= n;
    EXPECT_NEAR(Fy, m * g, 0.01 * m * g);
    // 3 %: five cells over the block's height and lumped mass.
    EXPECT_NEAR(-dy, settlement, 0.03 * settlement);
    EXPECT_EQ(c["plate:dx"].back(), 0.0);  // x is prescribed (0)
}

TEST(Drivers, aWeightedBodyTakesItsVelocityFromItsParticlesOnARestart)
{
    // Restart-safe: the state of the free motion is the particles' mean velocity.
    auto d = driver("type weighted; free (0 1); velocity (0.2 0); addedForce (0 -10);");
    d->attach(RigidBodyInfo<2>{2.0, Vector2::Zero(), 0.0, Vector2(0.7, -0.3), Vector2(0, -9.81)});
    const double t0 = 1.5, dt = 1e-3;
    EXPECT_TRUE(d->velocity(t0, Vector2::Zero()).isApprox(Vector2(0.2, -0.3), 1e-15));  // x prescribed
    // Before any reaction: weight and added force, a = g + F/m.
    const double a0 = -9.81 - 10.0 / 2.0;
    EXPECT_NEAR(d->velocity(t0 + dt, Vector2::Zero()).y(), -0.3 + dt * a0, 1e-13);
    RigidBodyLoad<2> load;
    load.force = Vector2(3, 29.62);  // the material pushes up with m g + 10 N/m
    d->advance(t0, dt, load);
    EXPECT_NEAR(d->velocity(t0 + dt, Vector2::Zero()).y(), -0.3 + dt * a0, 1e-13);  // the step taken
    EXPECT_NEAR(d->velocity(t0 + 2 * dt, Vector2::Zero()).y(), -0.3 + dt * a0, 1e-13);  // balanced now
}

// ---------------------------------------------------------------- weighted bodies that turn

TEST(Drivers, aWeightedBodyWithFreeRotationSpinsUpAsMomentTimesTimeOverInertia)
{
    // A body of inertia I = 0.5 kg m (per metre) about its centre c = (1, 0), no weight: the
    // material's moment M = 3 N m/m acts one step late, the added moment 1 N m/m at once, so
    // omega(t_k) = (1 k + 3 (k - 1)) dt / I after k steps, and every point keeps its distance
    // from c while it turns.
    auto d = driver("type weighted; free (1 1); freeRotation 1; addedMoment 1;");
    RigidBodyInfo<2> info;
    info.mass = 2.0;
    info.centroid = Vector2(1, 0);
    info.inertia = 0.5;
    d->attach(info);
    const double dt = 1e-3, I = 0.5;
    RigidBodyLoad<2> load;
    load.moment = 3.0;  // about the origin; with no force, about c as well
    Vector2 x(1.0, 0.3);
    double t = 0;
    for (int k = 1; k <= 200; ++k, t += dt) {
        x = d->move(t, dt, x);
        d->advance(t, dt, load);
    }
    const double omega = (1.0 * 200 + 3.0 * 199) * dt / I;
    // v(x) = omega e3 x (x - c): 0.3 m above c it moves along -x1 at 0.3 omega.
    EXPECT_NEAR(d->velocity(t, Vector2(1.0, 0.3)).x(), -0.3 * omega, 1e-12);
    EXPECT_NEAR(d->velocity(t, Vector2(1.0, 0.0)).norm(), 0.0, 1e-15);  // c stays: no force
    EXPECT_NEAR((x - Vector2(1, 0)).norm(), 0.3, 1e-13);
    // The turn is the sum of omega dt over the steps, each step turning exactly.
    double turn = 0;
    for (int k = 1; k <= 200; ++k) turn += (1.0 * k + 3.0 * (k - 1)) * dt / I * dt;
    EXPECT_NEAR(std::atan2(x.y(), x.x() - 1.0), pi / 2 + turn, 1e-12);
}

TEST(Drivers, aTurningBodyTakesItsSpinFromItsParticlesOnARestart)
{
    auto d = driver("type weighted; free (1 1); freeRotation 1;");
    RigidBodyInfo<2> info;
    info.mass = 2.0;
    info.inertia = 0.5;
    info.angularVelocity = 3.0;
    d->attach(info);
    EXPECT_NEAR(d->velocity(0.7, Vector2(0, 1)).x(), -3.0, 1e-14);
    EXPECT_NEAR(d->velocity(0.7, Vector2(2, 0)).y(), 6.0, 1e-14);
}

TEST(Drivers, badFreeRotationInputNamesTheKeyword)
{
    EXPECT_TRUE(contains(driverError("body { type weighted; freeRotation 2; }"), "1 (turns freely about e3) or 0"));
    EXPECT_TRUE(contains(driverError("body { type weighted; addedMoment 3; }"), "an added moment needs freeRotation"));
}

#if GPIC_WITH_3D
namespace {
std::unique_ptr<RigidBodyDriver<3>> driver3(const std::string& entry)
{
    const Dictionary d = Dictionary::parse("body { " + entry + " }", "constant/rigidBodies");
    return RigidBodyDriver<3>::New(d.subDict("body"));
}
} // namespace

TEST(Drivers, aBodyTurnsOnlyAboutItsFreeAxes)
{
    // Inertia diag(1, 2, 3) kg m^2; the moment (5, 4, 7) N m acts from the second step on. Free
    // about x2 only: after k steps omega = (0, 4 (k - 1) dt / 2, 0), whatever the other components.
    using V = Space<3>::Vector;
    auto d = driver3("type weighted; free (1 0 1); freeRotation (0 1 0);");
    RigidBodyInfo<3> info;
    info.mass = 1.0;
    info.inertia = V(1, 2, 3).asDiagonal();
    info.angularVelocity = V(9, 0, 9);  // about fixed axes: not a motion of this body
    d->attach(info);
    RigidBodyLoad<3> load;
    load.moment = V(5, 4, 7);
    const double dt = 1e-3;
    double t = 0;
    for (int k = 1; k <= 100; ++k, t += dt) d->advance(t, dt, load);
    const double omega2 = 4.0 * 99 * dt / 2.0;
    // At x = c + e1: v = omega x e1 = (0, 0, -omega2).
    EXPECT_TRUE(d->velocity(t, V(1, 0, 0)).isApprox(V(0, 0, -omega2), 1e-12)) << d->velocity(t, V(1, 0, 0)).transpose();
    EXPECT_TRUE(contains(
        [] {
            try {
                const Dictionary dd = Dictionary::parse("body { type weighted; freeRotation (0 1); }", "constant/rigidBodies");
                RigidBodyDriver<3>::New(dd.subDict("body"));
            } catch (const InputError& e) {
                return std::string(e.what());
            }
            return std::string();
        }(),
        "(r1 r2 r3) with 1"));
}

TEST(Drivers, aBodySpinningAboutAPrincipalAxisTurnsItsPointsExactly)
{
    // No moment: a body of inertia diag(1, 2, 3) spinning at 2 rad/s about its x3 axis, a
    // principal one, spins steadily, so after N steps each point has turned by 2 N dt about x3
    // through c (Rodrigues, to round-off).
    using V = Space<3>::Vector;
    auto d = driver3("type weighted; free (1 1 1); freeRotation (1 1 1);");
    RigidBodyInfo<3> info;
    info.mass = 1.0;
    info.centroid = V(0.5, 0.2, 0.1);
    info.inertia = V(1, 2, 3).asDiagonal();
    info.angularVelocity = V(0, 0, 2);
    d->attach(info);
    const double dt = 1e-3;
    V x = info.centroid + V(0.3, 0, 0.4);
    double t = 0;
    for (int k = 0; k < 1000; ++k, t += dt) {
        x = d->move(t, dt, x);
        d->advance(t, dt, RigidBodyLoad<3>{});
    }
    const double turn = 2.0 * 1000 * dt;
    EXPECT_TRUE(x.isApprox(info.centroid + V(0.3 * std::cos(turn), 0.3 * std::sin(turn), 0.4), 1e-12)) << x.transpose();
}
#endif
