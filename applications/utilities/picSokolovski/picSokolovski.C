// picSokolovski: the passive earth pressure on a rough wall pushed into a weighty soil, by
// Sokolovski's method of characteristics (PassivePressure.H): the reference for the seed's
// blade cases (Case 4.7: phi 35, blade friction 0.2; Case 6.2.5: corn, phi 26, delta 14 deg).
// For each wall depth h it prints the passive force P_p, its components on the seed's axes
// and K_p = 2 P_p/(gamma h^2), refining the net until P_p changes by less than -tol.
//
//     picSokolovski -phi 35 -mu 0.2 -rho 1500 -h 0.1 0.15 0.21 0.27 0.3
//     picSokolovski -phi 26 -delta 14 -rho 778 -h 0.15 0.25 0.35 -profile -csv corn.csv
//     picSokolovski -phi 30 -delta 20 -gamma 18e3 -c 5e3 -q 10e3 -h 2 -wallAngle 80
//
// -profile writes, per depth, postProcessing/picSokolovski/ (under -case):
//     wall_h<h>.csv       depth, distance along the wall, sigma_n, tau, sigma_n/(gamma depth)
//     rupture_h<h>.csv    the rupture line (x, depth) with its stresses, surface to wall foot
//     profile_h<h>.png    the wall stresses against depth, and the wall with the rupture line
// See README.md in this directory for the seed's cases and how they compare.
#include "applicationMain.H"

#include "Gnuplot.H"
#include "PassivePressure.H"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

const double degree = M_PI / 180;

std::string number(double value, int precision = 6)
{
    std::ostringstream out;
    out.precision(precision);
    out << value;
    return out.str();
}

//- The problem from the command line; InputError for missing or clashing options.
PassiveProblem readProblem(const po::variables_map& vm)
{
    auto given = [&](const char* key) { return vm.count(key) > 0 && !vm[key].defaulted(); };
    auto value = [&](const char* key) { return vm[key].as<double>(); };
    if (!given("phi")) throw InputError("", 0, "-phi is required (friction angle in degrees)");
    if (given("delta") && given("mu")) throw InputError("", 0, "give either -delta (degrees) or -mu (tan delta), not both");
    if (given("gamma") && given("rho")) throw InputError("", 0, "give either -gamma (N/m^3) or -rho (kg/m^3) with -g, not both");
    if (!given("gamma") && !given("rho") && !given("q") && !given("c"))
        throw InputError("", 0, "give the unit weight: -gamma (N/m^3) or -rho (kg/m^3) [-g 9.81]");
    if (given("mu") && !(value("mu") >= 0)) throw InputError("", 0, "-mu must be >= 0");
    if (given("g") && !given("rho")) throw InputError("", 0, "-g goes with -rho (the unit weight is rho g)");
    if (given("rho") && !(value("rho") >= 0 && value("g") >= 0))
        throw InputError("", 0, "-rho and -g must be >= 0");

    PassiveProblem p;
    p.phi = value("phi") * degree;
    p.delta = given("mu") ? std::atan(value("mu")) : (given("delta") ? value("delta") * degree : 0.0);
    p.gamma = given("gamma") ? value("gamma") : (given("rho") ? value("rho") * value("g") : 0.0);
    p.c = value("c");
    p.q = value("q");
    p.wallAngle = value("wallAngle") * degree;
    return p;
}

void writeWallCsv(const PassiveSolution& s, double gamma, const fs::path& file)
{
    std::ofstream out(file);
    out << "depth [m],distance [m],sigma_n [Pa],tau [Pa],sigma_n/(gamma depth)\n" << std::setprecision(10);
    for (const WallStress& w : s.wall)
        out << w.depth << ',' << w.distance << ',' << w.normal << ',' << w.shear << ','
            << (gamma > 0 && w.depth > 0 ? w.normal / (gamma * w.depth) : NAN) << '\n';
    if (!out) throw RunError("cannot write " + file.string());
}

void writeRuptureCsv(const PassiveSolution& s, const fs::path& file)
{
    std::ofstream out(file);
    out << "x [m],depth [m],sigma_xx [Pa],sigma_yy [Pa],tau_xy [Pa]\n" << std::setprecision(10);
    for (const RupturePoint& r : s.ruptureLine)
        out << r.x << ',' << r.y << ',' << r.sigmaXX << ',' << r.sigmaYY << ',' << r.tauXY << '\n';
    if (!out) throw RunError("cannot write " + file.string());
}

//- Left: sigma_n and tau down the wall (depth downwards, as the seed's Fig. 6.21). Right: the
//  wall and the rupture line, to scale.
bool plotProfile(const PassiveSolution& s, const PassiveProblem& p, const fs::path& wallCsv,
                 const fs::path& ruptureCsv, const fs::path& png)
{
    const double foot = s.h / std::tan(p.wallAngle);
    std::ostringstream script;
    script << "set datafile separator ','\nset terminal pngcairo size 1300,560 noenhanced font ',10'\n"
           << "set output " << gnuplotQuoted(png.string()) << '\n'
           << "set multiplot layout 1,2 title " << gnuplotQuoted(
                  "picSokolovski: phi " + number(p.phi / degree, 4) + " deg, delta " + number(p.delta / degree, 4) +
                  " deg, h " + number(s.h) + " m: P_p " + number(s.Pp, 5) + " N/m, K_p " + number(s.Kp, 5))
           << "\nset grid\nset key bottom right\nset yrange [*:*] reverse\n"
           << "set xlabel 'stress on the wall [kPa]'\nset ylabel 'depth [m]'\n"
           << "plot " << gnuplotQuoted(wallCsv.string()) << " skip 1 using ($3/1000):1 with lines lw 2 title 'normal stress', \\\n     "
           << gnuplotQuoted(wallCsv.string()) << " skip 1 using ($4/1000):1 with lines lw 2 title 'shear stress'\n"
           << "set size ratio -1\nset xlabel 'x, along the push [m]'\nset key bottom right\n"
           << "plot " << gnuplotQuoted(ruptureCsv.string()) << " skip 1 using 1:2 with lines lw 2 title 'rupture line', \\\n     "
           << "'-' using 1:2 with lines lw 4 lc rgb 'black' title 'wall'\n0,0\n" << foot << ',' << s.h << "\ne\n"
           << "unset multiplot\n";
    return runGnuplot(script.str(), png.string(), wallCsv.string());
}

void run(const po::variables_map& vm)
{
    const PassiveProblem problem = readProblem(vm);
    if (!vm.count("h")) throw InputError("", 0, "-h is required: one or more wall depths in m");
    const auto depths = vm["h"].as<std::vector<double>>();
    const int n0 = vm["n"].as<int>();
    const double tolerance = vm["tol"].as<double>();
    const PassivePressure reference(problem, n0);  // checks the data once, up front
    for (double h : depths)
        if (!(std::isfinite(h) && h > 0)) throw InputError("", 0, "-h: the wall depth " + number(h) + " must be > 0");

    std::cout << "picSokolovski: passive pressure by the method of characteristics (Sokolovski 1965)\n"
              << "    phi " << number(problem.phi / degree) << " deg, delta " << number(problem.delta / degree)
              << " deg, gamma " << number(problem.gamma) << " N/m^3, c " << number(problem.c) << " Pa, q "
              << number(problem.q) << " Pa, wall " << number(problem.wallAngle / degree)
              << " deg from the free surface\n"
              << "    Rankine K_p = tan^2(45 + phi/2) = " << number(rankinePassive(problem.phi)) << "; fan angle at the wall top "
              << number(reference.wallPsi() / degree) << " deg\n"
              << "    F_x1, F_x2: the force of the wall on the soil, x1 along the push, x2 up (the soil pushes\n"
              << "    the wall up: F_x2 < 0). K_p = 2 P_p/(gamma h^2), K_pn = 2 F_n/(gamma h^2). x_s: where the\n"
              << "    rupture line meets the free surface, from the wall top.\n\n";

    std::ostringstream table;
    table << std::fixed;
    const char* header = "h [m],P_p [N/m],F_x1 [N/m],F_x2 [N/m],K_p,K_pn,x_s [m],n,change\n";
    std::printf("%8s %12s %12s %12s %9s %9s %8s %5s %9s\n", "h [m]", "P_p [N/m]", "F_x1 [N/m]", "F_x2 [N/m]", "K_p",
                "K_pn", "x_s [m]", "n", "change");
    const fs::path outDir = fs::path(vm["case"].as<std::string>()) / "postProcessing" / "picSokolovski";
    for (double h : depths) {
        const ConvergedPassive c = solveConverged(problem, h, n0, tolerance);
        const PassiveSolution& s = c.solution;
        const double xs = s.ruptureLine.front().x;
        std::printf("%8.4f %12.2f %12.2f %12.2f %9.4f %9.4f %8.4f %5d %9.1e\n", h, s.Pp, s.Fx1, s.Fx2, s.Kp, s.Kpn,
                    xs, c.resolution, c.change);
        table << std::setprecision(6) << h << ',' << s.Pp << ',' << s.Fx1 << ',' << s.Fx2 << ',' << s.Kp << ','
              << s.Kpn << ',' << xs << ',' << c.resolution << ',' << std::scientific << c.change << std::fixed << '\n';
        if (vm.count("profile")) {
            std::error_code ec;
            fs::create_directories(outDir, ec);
            if (ec) throw RunError("cannot create " + outDir.string() + ": " + ec.message());
            const std::string tag = "_h" + number(h);
            const fs::path wallCsv = outDir / ("wall" + tag + ".csv"), ruptureCsv = outDir / ("rupture" + tag + ".csv");
            writeWallCsv(s, problem.gamma, wallCsv);
            writeRuptureCsv(s, ruptureCsv);
            plotProfile(s, problem, wallCsv, ruptureCsv, outDir / ("profile" + tag + ".png"));
        }
    }
    if (vm.count("profile")) std::cout << "\nwrote " << outDir.string() << "/{wall,rupture}_h*.csv, profile_h*.png\n";
    if (vm.count("csv")) {
        const std::string file = vm["csv"].as<std::string>();
        std::ofstream out(file);
        out << header << table.str();
        if (!out) throw RunError("cannot write " + file);
        std::cout << "wrote " << file << '\n';
    }
}

} // namespace

int main(int argc, char** argv)
{
    po::options_description options("picSokolovski options");
    options.add_options()
        ("phi", po::value<double>(), "angle of internal friction [deg], 0 < phi < 90")
        ("delta", po::value<double>(), "wall friction angle [deg], 0 <= delta <= phi (default 0)")
        ("mu", po::value<double>(), "wall friction coefficient tan(delta), instead of -delta")
        ("gamma", po::value<double>(), "unit weight [N/m^3]")
        ("rho", po::value<double>(), "density [kg/m^3], with -g, instead of -gamma")
        ("g", po::value<double>()->default_value(9.81, "9.81"), "gravity [m/s^2], with -rho")
        ("c", po::value<double>()->default_value(0.0), "cohesion [Pa]; the wall adhesion is c tan(delta)/tan(phi)")
        ("q", po::value<double>()->default_value(0.0), "surcharge on the free surface [Pa]")
        ("wallAngle", po::value<double>()->default_value(90.0),
         "angle from the free surface to the wall through the soil [deg]; 90: vertical")
        ("h", po::value<std::vector<double>>()->multitoken(), "wall depth(s) [m], e.g. -h 0.1 0.2 0.3")
        ("n", po::value<int>()->default_value(40), "initial net resolution (fan rays per 45 deg)")
        ("tol", po::value<double>()->default_value(1e-5, "1e-5"), "relative change of P_p at which refining stops")
        ("csv", po::value<std::string>(), "also write the table to this CSV file")
        ("profile", "write the wall stresses, the rupture line and a PNG per depth");
    return gpic::applicationMain(
        argc, argv,
        "picSokolovski: passive earth pressure on a rough wall by Sokolovski's method of characteristics",
        options, [](const po::variables_map& vm) { run(vm); });
}
