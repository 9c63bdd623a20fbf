// picListTimes: lists the time directories of a case (like foamListTimes); with -rm removes
// all but the first, and drops them from the ParaView index, to rerun a case from its start.
#include "applicationMain.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "solver/CaseFiles.H"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picListTimes options");
    options.add_options()("rm", "remove every time directory after the first");
    return gpic::applicationMain(
        argc, argv, "picListTimes: list (or remove) the time directories of a case", options,
        [](const po::variables_map& vm) {
            const std::string dir = vm["case"].as<std::string>();
            const auto times = gpic::listTimeDirectories(dir);
            if (!vm.count("rm")) {
                for (const auto& [t, name] : times) std::cout << name << '\n';
                return;
            }
            if (times.empty()) return;
            const std::string pvdFile = gpic::pvdPath(dir);
            const bool hasIndex = std::filesystem::exists(pvdFile);
            gpic::PvdCollection pvd(pvdFile);
            for (std::size_t k = 1; k < times.size(); ++k) {
                gpic::removeTimeDirectory(dir, times[k].second);
                pvd.removeTime(times[k].first);
                std::cout << "removed " << times[k].second << '\n';
            }
            if (hasIndex) pvd.write();
        });
}
