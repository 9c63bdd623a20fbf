// picSolver: explicit MPM/PIC for granular flow (plane strain, axisymmetric or 3D, as the
// case's constant/grid says). Runs a case from its latest (or chosen) time directory to
// endTime, writing ParaView time directories.
#include "applicationMain.H"
#include "run/Simulation.H"

#include <cstdlib>

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picSolver options");
    options.add_options()("time", po::value<double>(), "start from this time directory")(
        "quiet", "only warnings and errors (no selection, progress or timing lines)");
    return gpic::applicationMain(
        argc, argv, "picSolver: explicit material point (PIC) solver; run inside a case or with -case",
        options, [](const po::variables_map& vm) {
            gpic::RunOptions run;
            run.caseDir = vm["case"].as<std::string>();
            if (vm.count("time")) run.startTime = vm["time"].as<double>();
            run.quiet = vm.count("quiet") > 0;
            // OMP_NUM_THREADS fixes the count; without it the run measures which count is faster.
            run.tuneThreads = std::getenv("OMP_NUM_THREADS") == nullptr;
            gpic::runCase(run);
        });
}
