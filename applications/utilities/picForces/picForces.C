// picForces: the forces on rigid bodies after (or during) a run. Reads the forces function
// object's forces.dat, or the nodal contact forces of the time directories' grid.vti, and
// writes postProcessing/picForces/:
//     forces.csv, forces.png           force against time (-x time) or displacement
//     surface_<time>.csv, .png         normal and shear stress along a tool face (-surface)
//     wear.csv, wear.png               the toolWear function object's last wear profile (-wear)
// and prints the time average over a window (-window t0 t1), as the seed averages the blade
// forces over t = 2 ... 7 s (Case 4.7). See doc/forces.md. A 3D case's forces.dat (Fx Fy Fz
// per body) is read the same way; the grid's contact forces, -surface and -wear are plane only.
//
//     picForces                                  # postProcessing/forces/<latest>/forces.dat
//     picForces -x displacement -window 2 7
//     picForces -source grid -CofR "(0.5 0)"     # summed contactForce of every grid.vti
//     picForces -surface "(0.3 0.05) (0.3 0.4)" -time 4
//     picForces -wear                            # postProcessing/<toolWear>/<latest>/wearProfile.dat
#include "applicationMain.H"
#include "PlaneCaseOnly.H"

#include "ForcePlot.H"
#include "ForceSeries.H"
#include "GridContactForces.H"
#include "SurfaceStress.H"
#include "WearProfile.H"

#include "io/TimeDirectories.H"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

//- "(x y)" from the command line.
Vector2 parsePoint(const std::string& option, const std::string& text)
{
    static const std::regex point(R"(\s*\(\s*(\S+)\s+(\S+)\s*\)\s*)");
    std::smatch m;
    Vector2 p;
    if (std::regex_match(text, m, point)) {
        try {
            std::size_t used0 = 0, used1 = 0;
            p = Vector2(std::stod(m[1].str(), &used0), std::stod(m[2].str(), &used1));
            if (used0 == m[1].str().size() && used1 == m[2].str().size()) return p;
        } catch (const std::exception&) {
        }
    }
    throw InputError("", 0, option + ": expected \"(x y)\", found '" + text + "'");
}

//- "(x0 y0) (x1 y1)" from the command line.
std::pair<Vector2, Vector2> parseFace(const std::string& text)
{
    static const std::regex face(R"(\s*(\([^)]*\))\s*(\([^)]*\))\s*)");
    std::smatch m;
    if (!std::regex_match(text, m, face))
        throw InputError("", 0, "-surface: expected \"(x0 y0) (x1 y1)\", found '" + text + "'");
    return {parsePoint("-surface", m[1].str()), parsePoint("-surface", m[2].str())};
}

void surfaceProfile(const std::string& caseDir, const fs::path& outDir, const po::variables_map& vm)
{
    if (!vm.count("time")) throw InputError("", 0, "-surface needs -time t (the time directory to read)");
    const auto [p0, p1] = parseFace(vm["surface"].as<std::string>());
    const std::string timeDir = findTime(caseDir, vm["time"].as<double>());
    const GridContactForces grid = readGridContactForces((fs::path(caseDir) / timeDir / "grid.vti").string());
    const auto stations = surfaceStress(grid, p0, p1, vm["band"].as<double>());

    fs::create_directories(outDir);
    const std::string csv = (outDir / ("surface_" + timeDir + ".csv")).string();
    std::ofstream out(csv);
    out.precision(10);
    out << "s,x,y,length,Fn,Ft,normalStress,shearStress\n";
    double Fn = 0, Ft = 0;
    for (const auto& s : stations) {
        out << s.s << ',' << s.x.x() << ',' << s.x.y() << ',' << s.length << ',' << s.Fn << ',' << s.Ft << ','
            << s.normal << ',' << s.shear << '\n';
        Fn += s.Fn;
        Ft += s.Ft;
    }
    out.close();
    if (!out) throw RunError("cannot write " + csv);
    const double L = (p1 - p0).norm();
    if (Fn > 0.0)
        warning("", 0, "-surface: the material pulls the face away on the whole (mean normal stress < 0); is the "
                       "material to the right of (x0 y0) -> (x1 y1)? List the ends counter-clockwise around the body");
    std::printf("Face (%g %g) -> (%g %g), t = %s s: %zu stations; resultant normal %.6g N/m, shear %.6g N/m; "
                "mean normal stress %.6g Pa, shear stress %.6g Pa\n",
                p0.x(), p0.y(), p1.x(), p1.y(), timeDir.c_str(), stations.size(), -Fn, Ft, -Fn / L, Ft / L);
    std::cout << "Wrote " << csv << '\n';
    const std::string png = (outDir / ("surface_" + timeDir + ".png")).string();
    if (plotSurface(csv, png, "Stress on the face at t = " + timeDir + " s")) std::cout << "Wrote " << png << '\n';
}

void forceHistory(const std::string& caseDir, const fs::path& outDir, const po::variables_map& vm)
{
    const std::string source = vm["source"].as<std::string>();
    if (source != "forces" && source != "grid")
        throw InputError("", 0, "-source: '" + source + "' is not valid; valid choices: forces, grid");
    const std::string xAxis = vm["x"].as<std::string>();
    if (xAxis != "time" && xAxis != "displacement")
        throw InputError("", 0, "-x: '" + xAxis + "' is not valid; valid choices: time, displacement");
    if (source == "grid" && vm.count("file")) throw InputError("", 0, "-file reads a forces.dat: not with -source grid");
    if (source == "forces" && vm.count("CofR"))
        throw InputError("", 0, "-CofR applies to -source grid (the forces function object has its own CofR)");
    if (source == "grid" && xAxis == "displacement")
        throw InputError("", 0, "-x displacement needs a forces.dat (grid.vti has no body displacement)");
    std::vector<double> window;
    if (vm.count("window")) {
        window = vm["window"].as<std::vector<double>>();
        if (window.size() != 2 || !(window[0] < window[1]))
            throw InputError("", 0, "-window: expected two times t0 < t1");
    }

    const ForceSeries series =
        source == "grid"
            ? gridForceSeries(caseDir, vm.count("CofR") ? parsePoint("-CofR", vm["CofR"].as<std::string>())
                                                        : Vector2::Zero())
            : readForcesFile(vm.count("file") ? vm["file"].as<std::string>() : defaultForcesFile(caseDir));
    std::cout << "Read " << series.samples() << " samples from " << series.source << '\n';

    fs::create_directories(outDir);
    const std::string csv = (outDir / "forces.csv").string();
    writeCsv(series, csv);
    std::cout << "Wrote " << csv << '\n';
    const std::string png = (outDir / "forces.png").string();
    if (plotForces(series, csv, png, xAxis == "displacement")) std::cout << "Wrote " << png << '\n';

    if (!window.empty()) {
        std::size_t used = 0;
        const auto mean = windowMean(series, window[0], window[1], used);
        std::printf("Mean over %g <= t <= %g s (%zu samples, trapezoidal):\n", window[0], window[1], used);
        for (std::size_t c = 1; c < series.names.size(); ++c)
            std::printf("    %-24s %.10g\n", series.names[c].c_str(), mean[c]);
    }
}

void wearProfile(const std::string& caseDir, const fs::path& outDir, const po::variables_map& vm)
{
    const WearProfile profile = readWearProfile(vm.count("file") ? vm["file"].as<std::string>() : defaultWearFile(caseDir));
    std::cout << "Read the wear profile at t = " << profile.time << " s from " << profile.source << '\n';
    fs::create_directories(outDir);
    const std::string csv = (outDir / "wear.csv").string();
    writeWearCsv(profile, csv);
    std::cout << "Wrote " << csv << '\n';
    const std::string png = (outDir / "wear.png").string();
    std::ostringstream title;
    title << "Wear depth along the tool at t = " << profile.time << " s";
    if (plotWear(csv, png, profile.faces, title.str())) std::cout << "Wrote " << png << '\n';
    for (std::size_t k = 0; k < profile.faces.size(); ++k) {
        const WearStation* deepest = nullptr;
        for (const auto& st : profile.stations)
            if (st.face == static_cast<int>(k) && (!deepest || st.depth > deepest->depth)) deepest = &st;
        if (deepest)
            std::printf("    %-16s largest depth %.6g m at s = %.6g m (%.6g %.6g)\n", profile.faces[k].c_str(),
                        deepest->depth, deepest->s, deepest->x, deepest->y);
    }
}

} // namespace

int main(int argc, char** argv)
{
    po::options_description options("picForces options");
    options.add_options()
        ("file", po::value<std::string>(),
         "forces.dat to read (default postProcessing/forces/<latest>/forces.dat); with -wear, a wearProfile.dat")
        ("wear", "the wear profile of the toolWear function object at its last time (CSV, plot, deepest point)")
        ("source", po::value<std::string>()->default_value("forces"),
         "forces: the forces function object's file; grid: summed contactForce of each <time>/grid.vti")
        ("x", po::value<std::string>()->default_value("time"), "abscissa of forces.png: time or displacement")
        ("window", po::value<std::vector<double>>()->multitoken(), "t0 t1: print the time average over the window")
        ("CofR", po::value<std::string>(), "\"(x y)\": moment centre for -source grid (default (0 0))")
        ("surface", po::value<std::string>(),
         "\"(x0 y0) (x1 y1)\": stress along this face, material to its right (needs -time)")
        ("time", po::value<double>(), "time directory for -surface")
        ("band", po::value<double>()->default_value(0.0),
         "-surface: nodes up to this distance into the material [m] (default one cell)");
    return applicationMain(
        argc, argv, "picForces: forces on rigid bodies (CSV, plot, window mean) and stress along a tool face",
        options, [](const po::variables_map& vm) {
            const std::string caseDir = vm["case"].as<std::string>();
            // The forces function object's file reads alike in 3D; the rest is plane geometry.
            const std::string planeMode = vm.count("wear") ? "-wear" : vm.count("surface") ? "-surface"
                                          : vm["source"].as<std::string>() == "grid" ? "-source grid" : "";
            if (!planeMode.empty())
                refuseThreeD(caseDir, "picForces " + planeMode,
                             "picForces reads the forces function object's forces.dat of a 3D case (Fx Fy Fz per body)");
            const fs::path outDir = fs::path(caseDir) / "postProcessing" / "picForces";
            if (vm.count("wear")) return wearProfile(caseDir, outDir, vm);
            if (vm.count("surface")) return surfaceProfile(caseDir, outDir, vm);
            if (vm.count("time")) throw InputError("", 0, "-time selects the time directory for -surface");
            forceHistory(caseDir, outDir, vm);
        });
}
