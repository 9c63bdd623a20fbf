// picReconstruct: merges the time directories of a decomposed case back into the case, as
// OpenFOAM's reconstructPar: the particles of every processor<N>/<time>/particles.vtp in one
// <time>/particles.vtp, ordered by particle id (and a run in stages' sleeping particles,
// dormant.vtp, likewise), with the rest of processor0's time directory
// (uniform/, the tools' surfaces), and the times added to <case>.pvd; the function objects'
// files, which rank 0 writes, into postProcessing/. A time or a file the case holds already is
// left as it is (said so). doc/parallel.md.
#include "applicationMain.H"
#include "case/CaseFiles.H"
#include "core/CaseLock.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "parallel/ProcessorDirectories.H"
#include "particles/Particles.H"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <numeric>

namespace {

namespace fs = std::filesystem;

//- One file's particles from every subdomain, ordered by particle id (each id once).
template <int D> struct Merged {
    gpic::Particles<D> particles;
    double t = 0;
    std::vector<std::string> materials, bodies;
    int pieces = 0;  //- the subdomains that hold the file
};

template <int D>
Merged<D> merge(const std::vector<fs::path>& procs, const std::string& time, const std::string& file, bool everyOne)
{
    Merged<D> all;
    for (std::size_t k = 0; k < procs.size(); ++k) {
        const std::string path = (procs[k] / time / file).string();
        if (!fs::exists(path)) {
            if (everyOne) throw gpic::InputError(path, 0, "missing: every processor<N> must hold time " + time);
            continue;  // a subdomain with no sleeping particle
        }
        gpic::Particles<D> piece;
        double tk = 0;
        std::vector<std::string> m, b;
        gpic::readParticles(path, piece, tk, &m, &b);
        if (all.pieces++ == 0) {
            all.t = tk, all.materials = m, all.bodies = b;
            all.particles = std::move(piece);
            continue;
        }
        if (m != all.materials || b != all.bodies || tk != all.t)
            throw gpic::InputError(path, 0, "its time, materials or bodies differ from the other subdomains' " + file);
        all.particles.append(piece);
    }
    // One order whatever the decomposition: by particle id, each id once.
    gpic::Particles<D>& p = all.particles;
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
    for (std::size_t k = 1; k < order.size(); ++k)
        if (p.id[order[k]] == p.id[order[k - 1]])
            throw gpic::InputError((procs[0] / time).string(), 0,
                                   "particle " + std::to_string(p.id[order[k]]) + " is in two subdomains (" + file + ")");
    p.reorder(order);
    return all;
}

template <int D>
void reconstruct(const std::string& caseDir, const std::vector<fs::path>& procs, const std::string& time)
{
    const Merged<D> all = merge<D>(procs, time, "particles.vtp", true);
    const Merged<D> dormant = merge<D>(procs, time, "dormant.vtp", false);  // a run in stages
    const double t = all.t;
    gpic::writeTimeDirectoryAtomically(caseDir, time, [&](const std::string& tmp) {
        for (const auto& entry : fs::directory_iterator(procs[0] / time)) {
            const std::string name = entry.path().filename().string();
            if (name == "particles.vtp" || name == "dormant.vtp" || name == "grid.vti") continue;
            fs::copy(entry.path(), fs::path(tmp) / name, fs::copy_options::recursive);
        }
        gpic::writeParticles((fs::path(tmp) / "particles.vtp").string(), all.particles, t, all.materials, all.bodies);
        if (dormant.pieces > 0)
            gpic::writeParticles((fs::path(tmp) / "dormant.vtp").string(), dormant.particles, dormant.t,
                                 dormant.materials, dormant.bodies);
    });
    gpic::PvdCollection pvd(gpic::pvdPath(caseDir));
    const auto stored = gpic::readStoredTime(caseDir, time);
    pvd.add(stored ? stored->value : t, time + "/particles.vtp", 0);
    pvd.write();
    std::cout << time << ": " << all.particles.size() << " particles"
              << (dormant.pieces > 0 ? " and " + std::to_string(dormant.particles.size()) + " sleeping" : std::string())
              << " from " << procs.size() << " subdomains\n";
}

//- The function objects' files of a parallel run (rank 0 writes them, with every rank's
//  sums) into the case's postProcessing/, where the case has no file of that name.
void reconstructPostProcessing(const std::string& caseDir, const fs::path& processor0)
{
    const fs::path from = processor0 / "postProcessing";
    if (!fs::is_directory(from)) return;
    int copied = 0, kept = 0;
    for (const auto& entry : fs::recursive_directory_iterator(from)) {
        if (!entry.is_regular_file()) continue;
        const fs::path to = fs::path(caseDir) / "postProcessing" / fs::relative(entry.path(), from);
        if (fs::exists(to)) {
            ++kept;
            continue;
        }
        fs::create_directories(to.parent_path());
        fs::copy_file(entry.path(), to);
        ++copied;
    }
    std::cout << "postProcessing: " << copied << " files of the parallel run copied";
    if (kept > 0) std::cout << ", " << kept << " the case holds already left as they are";
    std::cout << '\n';
}

} // namespace

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picReconstruct options");
    options.add_options()("time", po::value<double>(), "this time only (default: every time of processor0)")(
        "latestTime", "the latest time of processor0 only");
    return gpic::applicationMain(
        argc, argv, "picReconstruct: merge the processor<N> time directories of a parallel run into the case",
        options, [](const po::variables_map& vm) {
            const std::string dir = vm["case"].as<std::string>();
            const auto procs = gpic::processorDirectories(dir);
            if (procs.empty()) throw gpic::InputError("", 0, dir + " holds no processor0: nothing to reconstruct "
                                                              "(picDecompose splits a case)");
            std::vector<std::string> times;
            if (vm.count("time"))
                times.push_back(gpic::findTime(procs[0].string(), vm["time"].as<double>()));
            else if (vm.count("latestTime"))
                times.push_back(gpic::latestTime(procs[0].string()));
            else
                for (const auto& [t, name] : gpic::listTimeDirectories(procs[0].string())) times.push_back(name);
            gpic::CaseLock lock(dir, "picReconstruct");
            const int dimension = gpic::caseDimension(gpic::readCaseFile(dir, "constant/grid"));
            for (const auto& time : times) {
                if (fs::exists(fs::path(dir) / time)) {
                    std::cout << time << ": the case holds it already, left as it is\n";
                    continue;
                }
                if (dimension == 3) {
#if GPIC_WITH_3D
                    reconstruct<3>(dir, procs, time);
#else
                    gpic::refusePlaneBuild(gpic::readCaseFile(dir, "constant/grid"));
#endif
                } else {
                    reconstruct<2>(dir, procs, time);
                }
            }
            reconstructPostProcessing(dir, procs[0]);
        });
}
