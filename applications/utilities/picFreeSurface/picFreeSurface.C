// picFreeSurface: the free surface of the material as a curve per time directory (seed figs.
// 6.9, 6.11, 6.30: the heap in front of a blade at 100-400 mm of travel). The particles of
// the chosen bodies are binned by x1 into columns of -width (default: the largest particle
// width); the surface of a column is the top of its highest particle (x2 + half its height).
// Columns without particles are left out. Writes postProcessing/picFreeSurface/surface.csv
// (one column pair per time) and surface.png (all times on one plot).
//
//     picFreeSurface -allTimes
//     picFreeSurface -times "0 4 8 12" -bodies corn
#include "applicationMain.H"
#include "PlaneCaseOnly.H"

#include "Gnuplot.H"
#include "ParticleField.H"
#include "TimeSelection.H"

#include "io/TimeDirectories.H"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

struct Surface {
    double time = 0;
    std::map<long, std::pair<double, double>> column;  //- bin -> (x1 centre, top x2)
};

Surface freeSurface(const std::string& vtp, const std::vector<int>& bodies, double width)
{
    const ParticleField body = readParticleField(vtp, "body");
    const ParticleField halfSize = readParticleField(vtp, "halfSize:y");
    Surface s;
    s.time = body.time;
    for (std::size_t q = 0; q < body.x.size(); ++q) {
        if (!bodies.empty() && std::find(bodies.begin(), bodies.end(), static_cast<int>(body.value[q])) == bodies.end())
            continue;
        const long bin = static_cast<long>(std::floor(body.x[q].x() / width));
        const double top = body.x[q].y() + halfSize.value[q];
        auto [it, fresh] = s.column.try_emplace(bin, (bin + 0.5) * width, top);
        if (!fresh) it->second.second = std::max(it->second.second, top);
    }
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    po::options_description options("picFreeSurface options");
    addTimeOptions(options);
    options.add_options()("bodies", po::value<std::vector<int>>()->multitoken(), "body ids to include (default: all)")(
        "width", po::value<double>(), "column width [m] (default: the largest particle width)");
    return applicationMain(
        argc, argv, "Free surface of the material per time directory: CSV and PNG.", options,
        [](const po::variables_map& vm) {
            const std::string caseDir = vm["case"].as<std::string>();
            refuseThreeD(caseDir, "picFreeSurface", "open its particles.vtp in ParaView and take a Slice through the surface");
            const std::vector<std::string> times = selectedTimes(vm, caseDir);
            const std::vector<int> bodies = vm.count("bodies") ? vm["bodies"].as<std::vector<int>>() : std::vector<int>{};
            double width = vm.count("width") ? vm["width"].as<double>() : 0.0;
            if (vm.count("width") && !(width > 0)) throw InputError("", 0, "-width: expected a length > 0");
            if (width == 0) {
                const ParticleField h = readParticleField((fs::path(caseDir) / times.front() / "particles.vtp").string(), "halfSize:x");
                for (double v : h.value) width = std::max(width, 2 * v);
                if (!(width > 0)) throw InputError("", 0, "the particles have no size: give -width");
            }
            std::vector<Surface> surfaces;
            for (const auto& name : times)
                surfaces.push_back(freeSurface((fs::path(caseDir) / name / "particles.vtp").string(), bodies, width));

            const fs::path out = fs::path(caseDir) / "postProcessing" / "picFreeSurface";
            fs::create_directories(out);
            const fs::path dat = out / "surface.dat";
            {
                std::ofstream f(dat);
                if (!f) throw InputError(dat.string(), 0, "cannot open for writing");
                f.precision(10);
                f << "# free surface: x1 [m], top x2 [m] per column of " << width << " m; one block per time\n";
                for (std::size_t k = 0; k < surfaces.size(); ++k) {
                    f << "# time " << times[k] << "\n";
                    for (const auto& [bin, xy] : surfaces[k].column) f << xy.first << ' ' << xy.second << '\n';
                    f << "\n\n";
                }
            }
            const fs::path csv = out / "surface.csv";
            {
                std::ofstream f(csv);
                f.precision(10);
                f << "time,x1,x2\n";
                for (std::size_t k = 0; k < surfaces.size(); ++k)
                    for (const auto& [bin, xy] : surfaces[k].column) f << surfaces[k].time << ',' << xy.first << ',' << xy.second << '\n';
            }
            std::string plot;
            for (std::size_t k = 0; k < surfaces.size(); ++k)
                plot += std::string(k ? ", " : "") + gnuplotQuoted(dat.string()) + " index " + std::to_string(k) +
                        " with lines lw 2 title " + gnuplotQuoted("t = " + times[k] + " s");
            // Free axis scales: a heap of a few cm on a surface metres long would not show at
            // equal scales.
            runGnuplot("set terminal pngcairo size 1000,500\nset output " + gnuplotQuoted((out / "surface.png").string()) +
                           "\nset xlabel 'x1 [m]'\nset ylabel 'x2 [m]'\nset grid\nset key outside right\n"
                           "plot " + plot + "\n",
                       (out / "surface.png").string(), dat.string());
            for (std::size_t k = 0; k < surfaces.size(); ++k) {
                double top = -1e300;
                for (const auto& [bin, xy] : surfaces[k].column) top = std::max(top, xy.second);
                std::cout << "time " << times[k] << ": " << surfaces[k].column.size() << " columns of " << width
                          << " m, highest point x2 = " << top << " m\n";
            }
            std::cout << "Free surface: " << csv.string() << ", " << (out / "surface.png").string() << '\n';
        });
}
