// picListTimes: lists the time directories of a case (like foamListTimes); with -rm removes
// all but the first, and drops them from the ParaView index, to rerun a case from its start;
// with -rebuild writes the ParaView index afresh from the time directories.
#include "applicationMain.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "case/CaseFiles.H"
#include "core/CaseLock.H"

#include <filesystem>
#include <iostream>
#include <optional>

namespace {

namespace fs = std::filesystem;

//- The index of every time directory with its particles, and the grid of every one where
//  all of them have one (ParaView takes the parts from the first time: they must agree).
void rebuildIndex(const std::string& dir)
{
    const auto times = gpic::listTimeDirectories(dir);
    bool everyGrid = !times.empty();
    for (const auto& [t, name] : times) everyGrid = everyGrid && fs::exists(fs::path(dir) / name / "grid.vti");
    const std::string pvdFile = gpic::pvdPath(dir);
    std::error_code ec;
    fs::remove(pvdFile, ec);  // nothing of the old index is kept
    gpic::PvdCollection pvd(pvdFile);
    std::size_t missing = 0;
    for (const auto& time : times) {
        if (!fs::exists(fs::path(dir) / time.second / "particles.vtp")) {
            ++missing;
            continue;
        }
        // uniform/time's exact value where picSolver wrote one (the name may be rounded).
        const auto stored = gpic::readStoredTime(dir, time.second);
        const double t = stored ? stored->value : time.first;
        pvd.add(t, time.second + "/particles.vtp", 0);
        if (everyGrid) pvd.add(t, time.second + "/grid.vti", 1);
    }
    pvd.write();
    std::cout << pvdFile << ": " << times.size() - missing << " times" << (everyGrid ? ", with the grid" : "");
    if (missing > 0) std::cout << " (" << missing << " time directories without particles.vtp left out)";
    std::cout << '\n';
}

} // namespace

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picListTimes options");
    options.add_options()("rm", "remove every time directory after the first")(
        "rebuild", "write the ParaView index afresh from the time directories");
    return gpic::applicationMain(
        argc, argv, "picListTimes: list (or remove) the time directories of a case", options,
        [](const po::variables_map& vm) {
            const std::string dir = vm["case"].as<std::string>();
            if (vm.count("rebuild") && vm.count("rm")) throw gpic::RunError("-rm and -rebuild: give one of them");
            // Removing or reindexing the times of a running case would pull them from under it.
            std::optional<gpic::CaseLock> lock;
            if (vm.count("rebuild") || vm.count("rm")) {
                gpic::listTimeDirectories(dir);  // a missing case is said as such first
                lock.emplace(dir, vm.count("rm") ? "picListTimes -rm" : "picListTimes -rebuild");
            }
            if (vm.count("rebuild")) {
                rebuildIndex(dir);
                return;
            }
            const auto times = gpic::listTimeDirectories(dir);
            if (!vm.count("rm")) {
                for (const auto& [t, name] : times) std::cout << name << '\n';
                return;
            }
            if (times.empty()) return;
            const std::string pvdFile = gpic::pvdPath(dir);
            const bool hasIndex = fs::exists(pvdFile);
            gpic::PvdCollection pvd(pvdFile);
            for (std::size_t k = 1; k < times.size(); ++k) {
                gpic::removeTimeDirectory(dir, times[k].second);
                pvd.removeTime(times[k].first);
                std::cout << "removed " << times[k].second << '\n';
            }
            if (hasIndex) pvd.write();
        });
}
