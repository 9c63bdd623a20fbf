// picInit: fills the bodies of constant/bodies with particles and writes time directory 0/
// (and the ParaView index) for picSolver.
#include "applicationMain.H"
#include "case/CaseInitialiser.H"

#include <iostream>

int main(int argc, char** argv)
{
    boost::program_options::options_description options("picInit options");
    options.add_options()("overwrite", "remove the time directories of an earlier run first");
    return gpic::applicationMain(
        argc, argv, "picInit: create the particles of the start time directory from constant/bodies",
        options, [](const auto& vm) {
            const std::string dir = vm["case"].template as<std::string>();
            const auto summary = gpic::initialiseCase(dir, vm.count("overwrite") > 0);
            std::cout << "picInit: " << summary.particles << " particles in " << summary.bodies
                      << " bodies written to " << dir << "/" << summary.timeDirectory
                      << "/particles.vtp\n";
        });
}
