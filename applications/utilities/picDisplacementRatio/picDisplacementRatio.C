// picDisplacementRatio: the particle displacement ratio PDR = |particle displacement| /
// |tool displacement| over a window between two time directories (seed 6.2.5, fig. 6.32:
// where the material moves with the blade, the shear band at its edge; the seed draws the
// band at PDR = 0.15). Particles are matched by id; the tool's displacement is the mean of
// its particles'. Writes postProcessing/picDisplacementRatio/<t0>-<t1>/pdr.csv (initial x1,
// x2 at t0, PDR) and pdr.png (colour bands 0-0.15-0.3-0.5-0.75-1), and prints how far in
// front of the tool the zone PDR >= threshold reaches.
//
//     picDisplacementRatio -from 1.5 -to 2.5 -tool blade
//     picDisplacementRatio -from 1.5 -to 2.5 -tool blade -threshold 0.2
#include "applicationMain.H"
#include "PlaneCaseOnly.H"

#include "Gnuplot.H"

#include "io/ParticlesVtk.H"
#include "io/TimeDirectories.H"
#include "particles/Particles.H"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unordered_map>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

} // namespace

int main(int argc, char** argv)
{
    po::options_description options("picDisplacementRatio options");
    options.add_options()("from", po::value<double>()->required(), "start of the window: a time directory")(
        "to", po::value<double>()->required(), "end of the window: a later time directory")(
        "tool", po::value<std::string>()->required(), "the moving body (a rigid tool), by name")(
        "threshold", po::value<double>()->default_value(0.15), "PDR of the shear band's edge (seed: 0.15)");
    return applicationMain(
        argc, argv, "Particle displacement ratio over a window: CSV and PNG.", options, [](const po::variables_map& vm) {
            const std::string caseDir = vm["case"].as<std::string>();
            refuseThreeD(caseDir, "picDisplacementRatio", "compare the displacement arrays of two time directories in ParaView");
            const std::string from = findTime(caseDir, vm["from"].as<double>());
            const std::string to = findTime(caseDir, vm["to"].as<double>());
            const double threshold = vm["threshold"].as<double>();
            if (!(threshold > 0)) throw InputError("", 0, "-threshold: expected a number > 0");
            Particles<2> a, b;
            double ta = 0, tb = 0;
            std::vector<std::string> bodyNames;
            readParticles((fs::path(caseDir) / from / "particles.vtp").string(), a, ta, nullptr, &bodyNames);
            readParticles((fs::path(caseDir) / to / "particles.vtp").string(), b, tb);
            if (!(tb > ta)) throw InputError("", 0, "-to: the window needs a time after -from (" + from + ")");
            const std::string toolName = vm["tool"].as<std::string>();
            const auto it = std::find(bodyNames.begin(), bodyNames.end(), toolName);
            if (it == bodyNames.end()) {
                std::string valid;
                for (const auto& n : bodyNames) valid += (valid.empty() ? "" : ", ") + n;
                throw InputError((fs::path(caseDir) / from / "particles.vtp").string(), 0,
                                 "-tool: body '" + toolName + "' does not exist; valid choices: " + valid);
            }
            const int tool = static_cast<int>(it - bodyNames.begin());

            std::unordered_map<int, std::size_t> atEnd;
            for (std::size_t q = 0; q < b.size(); ++q) atEnd[b.id[q]] = q;
            Vector2 toolMove = Vector2::Zero();
            int toolParticles = 0;
            for (std::size_t q = 0; q < a.size(); ++q)
                if (a.body[q] == tool)
                    if (auto e = atEnd.find(a.id[q]); e != atEnd.end()) {
                        toolMove += b.x[e->second] - a.x[q];
                        ++toolParticles;
                    }
            if (toolParticles == 0) throw InputError("", 0, "-tool: body '" + toolName + "' has no particles in both times");
            toolMove /= toolParticles;
            if (!(toolMove.norm() > 0))
                throw InputError("", 0, "-tool: body '" + toolName + "' did not move between " + from + " and " + to);

            const fs::path out = fs::path(caseDir) / "postProcessing" / "picDisplacementRatio" / (from + "-" + to);
            fs::create_directories(out);
            const fs::path csv = out / "pdr.csv";
            std::ofstream f(csv);
            if (!f) throw InputError(csv.string(), 0, "cannot open for writing");
            f.precision(10);
            f << "x1,x2,PDR\n";
            // How far ahead of the tool (in its direction of motion) the moving zone reaches.
            const Vector2 direction = toolMove.normalized();
            double toolFront = -1e300, reach = -1e300;
            for (std::size_t q = 0; q < a.size(); ++q)
                if (a.body[q] == tool) toolFront = std::max(toolFront, a.x[q].dot(direction));
            std::size_t matched = 0;
            for (std::size_t q = 0; q < a.size(); ++q) {
                if (a.body[q] == tool) continue;
                const auto e = atEnd.find(a.id[q]);
                if (e == atEnd.end()) continue;  // gone through an outlet
                const double pdr = (b.x[e->second] - a.x[q]).norm() / toolMove.norm();
                f << a.x[q].x() << ',' << a.x[q].y() << ',' << pdr << '\n';
                ++matched;
                if (pdr >= threshold) reach = std::max(reach, a.x[q].dot(direction) - toolFront);
            }
            f.close();
            // The seed's colour bands (fig. 6.32).
            const std::string script =
                "set terminal pngcairo size 1000,600\nset output " + gnuplotQuoted((out / "pdr.png").string()) +
                "\nset size ratio -1\nset datafile separator ','\nset key off\nset xlabel 'x1 [m]'\nset ylabel 'x2 [m]'\n"
                "set title " + gnuplotQuoted("PDR over " + from + " ... " + to + " s (tool " + toolName + ")") + " noenhanced\n"
                "set palette defined (0 'grey85', 0.15 'grey85', 0.15 'yellow', 0.3 'yellow', 0.3 'orange', 0.5 'orange', "
                "0.5 'red', 0.75 'red', 0.75 'dark-red', 1 'dark-red')\nset cbrange [0:1]\n"
                "plot " + gnuplotQuoted(csv.string()) + " every ::1 using 1:2:3 with points pt 5 ps 0.5 lc palette\n";
            runGnuplot(script, (out / "pdr.png").string(), csv.string());
            std::cout << "Tool " << toolName << " moved " << toolMove.norm() << " m between " << from << " and " << to
                      << "; " << matched << " particles; the zone PDR >= " << threshold << " reaches "
                      << (reach > -1e300 ? std::to_string(reach) + " m ahead of the tool" : std::string("nowhere"))
                      << "\nPDR: " << csv.string() << ", " << (out / "pdr.png").string() << '\n';
        });
}
