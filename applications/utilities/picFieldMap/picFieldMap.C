// picFieldMap: a map of one particle field over the particles' current positions, per time
// directory, as a PNG (gnuplot) and a CSV: micro-rotation (Cosserat runs), plastic shear
// strain and yield state (where the material flows; seed figs. 4.39-4.40), displacement,
// stress components. Writes postProcessing/picFieldMap/<time>/<field>.csv and .png and prints
// the field's range per time.
//
//     picFieldMap -field microRotation                   # the latest time
//     picFieldMap -field epsPs -time 0.4 -range 0 0.2
//     picFieldMap -field yieldState -allTimes
//     picFieldMap -field stress:xy                       # a component (xx xy ... zz, x y z, 0..n-1, mag)
//     picFieldMap -field initialPosition:y -bands 10     # coloured layers (seed figs. 6.9-6.11)
//     picFieldMap -field epsPs -slice x3 0.05            # 3D: the particles the plane x3 = 0.05 m
//                                                        # cuts (default: x3 through the middle)
#include "applicationMain.H"
#include "case/CaseFiles.H"
#include "dictionary/Dictionary.H"

#include "Gnuplot.H"
#include "ParticleField.H"
#include "TimeSelection.H"

#include "io/TimeDirectories.H"

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

//- The field name as a file name ("stress:xy" -> "stress_xy").
std::string fileStem(std::string field)
{
    std::replace(field.begin(), field.end(), ':', '_');
    return field;
}

void drawMap(const ParticleField& f, const fs::path& outDir, const po::variables_map& vm, const Slice* slice)
{
    // The map's axes: x1, x2, or in a slice of a 3D case its two in-plane axes.
    const std::string a1 = slice ? "x" + std::to_string(slice->first() + 1) : "x1",
                      a2 = slice ? "x" + std::to_string(slice->second() + 1) : "x2";
    fs::create_directories(outDir);
    const std::string stem = fileStem(f.name);
    const fs::path csv = outDir / (stem + ".csv");
    {
        std::ofstream out(csv);
        if (!out) throw InputError(csv.string(), 0, "cannot open for writing");
        out.precision(10);
        out << a1 << ',' << a2 << ',' << f.name << '\n';
        for (std::size_t q = 0; q < f.x.size(); ++q) out << f.x[q].x() << ',' << f.x[q].y() << ',' << f.value[q] << '\n';
    }
    const auto [lo, hi] = std::minmax_element(f.value.begin(), f.value.end());
    double mean = 0;
    for (double v : f.value) mean += v;
    mean /= std::max<std::size_t>(f.value.size(), 1);
    std::printf("time %-10g %-20s min %-12.5g max %-12.5g mean %-12.5g (%zu particles%s) -> %s\n", f.time,
                f.name.c_str(), f.value.empty() ? 0.0 : *lo, f.value.empty() ? 0.0 : *hi, mean, f.value.size(),
                slice ? (" in the slice x" + std::to_string(slice->axis + 1) + " = " + timeName(slice->position, 6)).c_str() : "",
                csv.c_str());

    // Particles as filled squares of their own size: the map reads like the seed's figures.
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300, h = 0;
    for (std::size_t q = 0; q < f.x.size(); ++q) {
        xmin = std::min(xmin, f.x[q].x()); xmax = std::max(xmax, f.x[q].x());
        ymin = std::min(ymin, f.x[q].y()); ymax = std::max(ymax, f.x[q].y());
        h = std::max(h, f.halfWidth[q]);
    }
    if (f.x.empty()) return;
    const double pad = 2 * h + 1e-12;
    const double width = xmax - xmin + 2 * pad, height = ymax - ymin + 2 * pad;
    const int pxWidth = 1000, pxHeight = std::clamp(static_cast<int>(pxWidth * height / width) + 80, 300, 1400);
    const fs::path png = outDir / (stem + ".png");
    std::string script = "set terminal pngcairo size " + std::to_string(pxWidth) + "," + std::to_string(pxHeight) +
                         "\nset output " + gnuplotQuoted(png.string()) + "\nset size ratio -1\n" +
                         "set xlabel '" + a1 + " [m]'\nset ylabel '" + a2 + " [m]'\nset title " +
                         gnuplotQuoted(f.name + " at t = " + timeName(f.time, 6) + " s" +
                                       (slice ? " in the slice x" + std::to_string(slice->axis + 1) + " = " +
                                                    timeName(slice->position, 6) + " m"
                                              : "")) +
                         " noenhanced\n" +
                         "set xrange [" + std::to_string(xmin - pad) + ":" + std::to_string(xmax + pad) + "]\n" +
                         "set yrange [" + std::to_string(ymin - pad) + ":" + std::to_string(ymax + pad) + "]\n" +
                         "set datafile separator ','\nset key off\n";
    if (f.name == "yieldState") {
        // The codes of YieldState: elastic 0, shear 1, tension 2, apex 3, edge 4.
        script += "set palette maxcolors 5\nset palette defined (0 'grey80', 1 'red', 2 'blue', 3 'black', 4 'orange')\n"
                  "set cbrange [-0.5:4.5]\nset cbtics ('elastic' 0, 'shear' 1, 'tension' 2, 'apex' 3, 'edge' 4)\n";
    } else {
        script += "set palette rgb 33,13,10\n";
        if (vm.count("bands")) {
            // Coloured layers (seed figs. 6.9-6.11): N bands of alternating colours, e.g. of
            // initialPosition:y, so that each initial layer keeps its colour as it deforms.
            const int bands = vm["bands"].as<int>();
            script += "set palette maxcolors " + std::to_string(bands) +
                      "\nset palette defined (0 '#1f77b4', 1 '#ff7f0e', 2 '#2ca02c', 3 '#d62728', 4 '#9467bd', 5 '#8c564b')\n";
            if (!vm.count("range")) {
                script += "set cbrange [" + std::to_string(*lo) + ":" + std::to_string(*hi + 1e-12 * std::abs(*hi) + 1e-300) + "]\n";
            }
        }
        if (vm.count("range")) {
            const auto r = vm["range"].as<std::vector<double>>();
            script += "set cbrange [" + std::to_string(r[0]) + ":" + std::to_string(r[1]) + "]\n";
        }
    }
    // Square markers scaled to the particle size in screen units.
    const double markerScale = 0.6 * (2 * h / width) * pxWidth / 6.0;
    script += "plot " + gnuplotQuoted(csv.string()) + " every ::1 using 1:2:3 with points pt 5 ps " +
              std::to_string(std::max(markerScale, 0.15)) + " lc palette\n";
    runGnuplot(script, png.string(), csv.string());
}

} // namespace

int main(int argc, char** argv)
{
    po::options_description options("picFieldMap options");
    addTimeOptions(options);
    options.add_options()("field", po::value<std::string>()->required(),
                          "particle array, or array:component (xx xy yx yy zz, x y z, 0..n-1, mag)")(
        "range", po::value<std::vector<double>>()->multitoken(), "colour range: min max")(
        "bands", po::value<int>(), "colour in N bands (coloured layers: -field initialPosition:y -bands 10)")(
        "slice", po::value<std::vector<std::string>>()->multitoken(),
        "3D: the plane AXIS POSITION (x1, x2 or x3 and metres) whose particles are mapped; default x3 through the "
        "middle of the particles");
    return applicationMain(
        argc, argv, "Map of a particle field at its positions: CSV and PNG per time directory.", options,
        [](const po::variables_map& vm) {
            const std::string caseDir = vm["case"].as<std::string>();
            const bool threeD = fs::exists(fs::path(caseDir) / "constant/grid") &&
                                caseDimension(readCaseFile(caseDir, "constant/grid")) == 3;
            std::optional<Slice> slice;
            if (vm.count("slice")) {
                const auto words = vm["slice"].as<std::vector<std::string>>();
                if (!threeD) throw InputError("", 0, "-slice: a plane case is mapped whole; -slice is for a 3D case");
                Slice s;
                const std::vector<std::string> axes = {"x1", "x2", "x3"};
                const auto axis = words.empty() ? axes.end() : std::find(axes.begin(), axes.end(), words[0]);
                std::size_t used = 0;
                try {
                    if (words.size() == 2) s.position = std::stod(words[1], &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (words.size() != 2 || axis == axes.end() || used != words[1].size() || !std::isfinite(s.position))
                    throw InputError("", 0, "-slice: expected an axis and a position, e.g. -slice x3 0.05; valid axes: x1, x2, x3");
                s.axis = static_cast<int>(axis - axes.begin());
                slice = s;
            }
            if (vm.count("bands") && vm["bands"].as<int>() < 2)
                throw InputError("", 0, "-bands: expected a number of bands >= 2");
            if (vm.count("range")) {
                const auto r = vm["range"].as<std::vector<double>>();
                if (r.size() != 2 || !(r[1] > r[0]))
                    throw InputError("", 0, "-range: expected two numbers min max with max > min");
            }
            const std::vector<std::string> times = selectedTimes(vm, caseDir);
            const fs::path out = fs::path(caseDir) / "postProcessing" / "picFieldMap";
            for (const auto& name : times) {
                const std::string vtp = (fs::path(caseDir) / name / "particles.vtp").string();
                std::optional<Slice> at = slice;
                if (threeD && !at) at = Slice{2, middleAlong(vtp, 2)};  // x3 through the particles' middle
                const ParticleField f = readParticleField(vtp, vm["field"].as<std::string>(), at ? &*at : nullptr);
                drawMap(f, out / name, vm, at ? &*at : nullptr);
            }
        });
}
