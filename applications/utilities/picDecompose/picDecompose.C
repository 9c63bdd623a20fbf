// picDecompose: splits a case into subdomains for a parallel run, as OpenFOAM's decomposePar:
// reads system/decomposeParDict, gives every cell of the grid an owner (parallel/
// Decomposition.H) and writes each subdomain as a case of its own for its rank: processor<N>/
// with the case's system/ and constant/, constant/cellDecomposition, and the subdomain's
// particles of the chosen time, processor<N>/<time>/particles.vtp (and a run in stages'
// sleeping particles, dormant.vtp, by their cells likewise), with the rest of that
// time directory (uniform/, the tools' surfaces). Prints each subdomain's
// particles and cells and the imbalance. doc/parallel.md.
#include "applicationMain.H"
#include "TimeSelection.H"
#include "case/CaseFiles.H"
#include "core/CaseLock.H"
#include "dictionary/Dictionary.H"
#include "grid/Grid.H"
#include "io/ParticlesVtk.H"
#include "parallel/CellDecompositionFile.H"
#include "parallel/Decomposition.H"
#include "parallel/ProcessorDirectories.H"
#include "particles/Particles.H"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace {

namespace fs = std::filesystem;

template <int D> void decompose(const std::string& caseDir, const std::string& time, bool force)
{
    const gpic::Dictionary gridDict = gpic::readCaseFile(caseDir, "constant/grid");
    const gpic::Grid<D> grid(gridDict);
    const gpic::Dictionary parDict = gpic::readCaseFile(caseDir, "system/decomposeParDict");
    const gpic::DecompositionSettings settings = gpic::readDecomposeParDict(parDict, D);

    // The particles of the time and, in a run in stages, its sleeping ones: both by cell, both
    // weigh (the sleeping ones wake where they lie).
    const fs::path timeDir = fs::path(caseDir) / time;
    struct Set {
        std::string file;
        gpic::Particles<D> particles;
        double t = 0;
        std::vector<std::string> materials, bodies;
        std::vector<int> cellOf;
        std::vector<std::vector<std::size_t>> members;
    };
    std::vector<Set> sets;
    std::vector<int> perCell(static_cast<std::size_t>(grid.nCells()), 0);
    for (const char* file : {"particles.vtp", "dormant.vtp"}) {
        if (std::string(file) == "dormant.vtp" && !fs::exists(timeDir / file)) continue;
        Set& set = sets.emplace_back();
        set.file = file;
        const std::string path = (timeDir / file).string();
        gpic::readParticles(path, set.particles, set.t, &set.materials, &set.bodies);
        set.cellOf.resize(set.particles.size());
        for (std::size_t p = 0; p < set.particles.size(); ++p) {
            if (!grid.contains(set.particles.x[p]))
                throw gpic::InputError(path, 0, "particle " + std::to_string(set.particles.id[p]) + " lies outside the grid");
            set.cellOf[p] = gpic::cellNumber(grid, grid.cellOf(set.particles.x[p]));
            ++perCell[set.cellOf[p]];
        }
    }
    gpic::CellDecomposition decomposition{settings.subdomains, gpic::decomposeCells(grid, perCell, settings)};

    // Never over an earlier decomposition unless asked: its time directories may be a run's.
    const auto existing = gpic::processorDirectories(caseDir);
    if (!existing.empty() && !force)
        throw gpic::InputError("", 0, existing.front().string() + " exists: the case is decomposed already "
                                      "(picDecompose -force removes every processor<N> first)");
    for (const auto& dir : existing) fs::remove_all(dir);

    for (Set& set : sets) {
        set.members.resize(static_cast<std::size_t>(settings.subdomains));
        for (std::size_t p = 0; p < set.particles.size(); ++p) set.members[decomposition.owner[set.cellOf[p]]].push_back(p);
    }
    std::vector<int> cells(static_cast<std::size_t>(settings.subdomains), 0);
    for (int o : decomposition.owner) ++cells[o];
    for (int k = 0; k < settings.subdomains; ++k) {
        const fs::path proc = fs::path(caseDir) / ("processor" + std::to_string(k));
        // Each subdomain a case of its own for its rank (picSolver -parallel): the case's
        // dictionaries and surfaces, and the owners of the cells.
        fs::create_directories(proc);
        fs::copy(fs::path(caseDir) / "system", proc / "system", fs::copy_options::recursive);
        fs::copy(fs::path(caseDir) / "constant", proc / "constant", fs::copy_options::recursive);
        gpic::writeCellDecomposition((proc / "constant" / "cellDecomposition").string(), decomposition);
        // The time directory is built apart and renamed: a stopped decomposition leaves no
        // time that a run would start from.
        const fs::path tmp = proc / ("." + time + ".tmp");
        fs::create_directories(tmp);
        for (const auto& entry : fs::directory_iterator(timeDir)) {
            const std::string name = entry.path().filename().string();
            // the particles are split below; the grid's fields are each rank's own
            if (name == "particles.vtp" || name == "dormant.vtp" || name == "grid.vti") continue;
            fs::copy(entry.path(), tmp / name, fs::copy_options::recursive);
        }
        for (const Set& set : sets) {
            gpic::Particles<D> mine = set.particles;
            mine.reorder(set.members[k]);
            // A subdomain with no sleeping particle has no file of them, as a serial run writes.
            if (set.file == "dormant.vtp" && mine.size() == 0) continue;
            gpic::writeParticles((tmp / set.file).string(), mine, set.t, set.materials, set.bodies);
        }
        fs::rename(tmp, proc / time);
    }
    const auto& particles = sets.front().particles;
    const auto& members = sets.front().members;
    std::size_t most = 0;
    std::printf("%-10s %10s %8s\n", "subdomain", "particles", "cells");
    for (int k = 0; k < settings.subdomains; ++k) {
        std::printf("%-10d %10zu %8d\n", k, members[k].size(), cells[k]);
        most = std::max(most, members[k].size());
    }
    const double mean = static_cast<double>(particles.size()) / settings.subdomains;
    std::printf("%zu particles of time %s in %d subdomains, method %s; largest/mean %.3f\n", particles.size(),
                time.c_str(), settings.subdomains, parDict.get<std::string>("method").c_str(),
                mean > 0 ? static_cast<double>(most) / mean : 1.0);
    if (sets.size() > 1) std::printf("and %zu sleeping particles (dormant.vtp) by their cells\n", sets.back().particles.size());
}

} // namespace

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picDecompose options");
    options.add_options()("time", po::value<double>(), "this time directory (default: the latest)")(
        "force", "remove the processor<N> directories of an earlier decomposition first");
    return gpic::applicationMain(
        argc, argv, "picDecompose: split a case into subdomains (system/decomposeParDict) for a parallel run",
        options, [](const po::variables_map& vm) {
            const std::string dir = vm["case"].as<std::string>();
            const std::string time = vm.count("time") ? gpic::findTime(dir, vm["time"].as<double>()) : gpic::latestTime(dir);
            gpic::CaseLock lock(dir, "picDecompose");
            if (gpic::caseDimension(gpic::readCaseFile(dir, "constant/grid")) == 3) {
#if GPIC_WITH_3D
                decompose<3>(dir, time, vm.count("force") > 0);
#else
                gpic::refusePlaneBuild(gpic::readCaseFile(dir, "constant/grid"));
#endif
            } else {
                decompose<2>(dir, time, vm.count("force") > 0);
            }
        });
}
