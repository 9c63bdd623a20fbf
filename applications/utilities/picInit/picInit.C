// picInit: fills the bodies of constant/bodies with particles and writes time directory 0/
// (and the ParaView index) for picSolver.
#include "applicationMain.H"
#include "bodies/BodyFiller.H"
#include "core/Plugins.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "solver/CaseFiles.H"

#include <filesystem>
#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    namespace fs = std::filesystem;
    po::options_description options("picInit options");
    return gpic::applicationMain(
        argc, argv, "picInit: create the particles of time directory 0 from constant/bodies", options,
        [](const po::variables_map& vm) {
            using namespace gpic;
            const std::string dir = vm["case"].as<std::string>();
            Dictionary control = readCaseFile(dir, "system/controlDict");
            Plugins::open(control, "libs");
            Dictionary gridDict = readCaseFile(dir, "constant/grid");
            const Grid grid(gridDict);
            Dictionary materialsDict = readCaseFile(dir, "constant/materials");
            const auto materials = readMaterials(materialsDict);
            Dictionary bodiesDict = readCaseFile(dir, "constant/bodies");
            const auto filled = fillBodies(bodiesDict, grid, materials, readGravity(dir));
            bodiesDict.warnUnused();

            const double t0 = control.getOrDefault<double>("startTime", 0.0);
            const std::string start = timeName(t0);
            writeTimeDirectoryAtomically(dir, start, [&](const std::string& tmp) {
                writeParticles(tmp + "/particles.vtp", filled.particles, t0, materialNames(materials),
                               filled.bodyNames);
            });
            const std::string caseName = fs::absolute(dir).lexically_normal().filename().string();
            PvdCollection pvd((fs::path(dir) / (caseName + ".pvd")).string());
            pvd.removeAfter(-1.0);
            pvd.add(t0, start + "/particles.vtp", 0);
            pvd.write();
            std::cout << "picInit: " << filled.particles.size() << " particles in "
                      << filled.bodyNames.size() << " bodies written to " << dir << "/" << start
                      << "/particles.vtp\n";
        });
}
