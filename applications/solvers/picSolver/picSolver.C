// picSolver: explicit MPM/PIC for granular flow (plane strain, axisymmetric or 3D, as the
// case's constant/grid says). Runs a case from its latest (or chosen) time directory to
// endTime, writing ParaView time directories. With -parallel (under mpirun), each rank runs
// its subdomain of a case picDecompose split (doc/parallel.md).
#include "applicationMain.H"
#include "parallel/Communicator.H"
#include "run/Simulation.H"

#include <cstdlib>

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picSolver options");
    options.add_options()("time", po::value<double>(), "start from this time directory")(
        "quiet", "only warnings and errors (no selection, progress or timing lines)")(
        "parallel", "run the subdomains of a decomposed case, one per MPI rank (mpirun -np N picSolver -parallel)");
    return gpic::applicationMain(
        argc, argv, "picSolver: explicit material point (PIC) solver; run inside a case or with -case",
        options, [&argc, &argv](const po::variables_map& vm) {
            gpic::RunOptions run;
            std::unique_ptr<gpic::Communicator> comm;
            if (vm.count("parallel")) {
                if (!gpic::mpiAvailable())
                    throw gpic::InputError("", 0, "-parallel: this build has no MPI (install libopenmpi-dev and "
                                                  "build again with -DGPIC_WITH_MPI=ON)");
                comm = gpic::mpiCommunicator(&argc, &argv);
                run.communicator = comm.get();
            }
            run.caseDir = vm["case"].as<std::string>();
            if (vm.count("time")) run.startTime = vm["time"].as<double>();
            run.quiet = vm.count("quiet") > 0 || (comm && comm->rank() > 0);  // one rank reports
            // OMP_NUM_THREADS fixes the count; without it the run measures which count is faster.
            run.tuneThreads = std::getenv("OMP_NUM_THREADS") == nullptr;
            gpic::runCase(run);
        });
}
