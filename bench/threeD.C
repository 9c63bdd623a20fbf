// The 3D engine's throughput and memory per particle, on scenes set up in memory (so that
// it measures the engine alone, without the reader and the writers): the engine's step loop, as picSolver
// runs it (USL, bilinear cells, FLIP, the particles sorted by cell every 100 steps), timed
// from the first step to the last. Threads: OMP_NUM_THREADS.
//
//     benchThreeD [-scene column|block] [-steps n]
//
// column: a Mohr-Coulomb sand column (the 2D bench's column material: rho 2650, E 0.84 MPa,
//         nu 0.3, phi 19.8, psi 0, c 0) 0.2 x 0.125 x 0.125 m of 5 mm cells, 2 x 2 x 2
//         particles per cell (200 000), at the left wall of a 0.6 x 0.15 x 0.125 m grid,
//         slip walls, fixed base, gravity: it collapses;
// block:  a linear elastic block (E 10 MPa, nu 0.3, rho 1000) 30 x 30 x 30 cells of 10 mm,
//         8 particles per cell (216 000), on a fixed floor under gravity.
// Prints one line: particles, steps, wall, particle-updates/s, solver bytes per particle;
// then the time per pass (as picSolver's log).
#include "core/Info.H"
#include "dictionary/Dictionary.H"
#include "engine/MpmSolver.H"
#include "schemes/UpdateScheme.H"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

using namespace gpic;
using Vector = Space<3>::Vector;

namespace {

struct Scene {
    std::string material;
    Grid<3>::Index cells, filled;
    double h, dt;
    std::array<std::string, 6> sides;
};

std::unique_ptr<MpmSolver<3>> build(const Scene& scene)
{
    SolverInputs<3> in(Grid<3>(Vector::Zero(), Vector::Constant(scene.h), scene.cells));
    const Dictionary material = Dictionary::parse(scene.material, "constant/materials/solid");
    in.materials.push_back(Material<3>::New(material));
    const double rho = in.materials.front()->rho();
    const Vector half = Vector::Constant(0.25 * scene.h);
    const double volume = std::pow(0.5 * scene.h, 3);
    for (int k = 0; k < 2 * scene.filled[2]; ++k)
        for (int j = 0; j < 2 * scene.filled[1]; ++j)
            for (int i = 0; i < 2 * scene.filled[0]; ++i)
                in.particles.add(0.5 * scene.h * Vector(i + 0.5, j + 0.5, k + 0.5), rho * volume, volume, half, 0, 0);
    const Dictionary none;
    in.shape = Registry<ShapeFunction<3>>::select("bilinear", none, none, "shapeFunction");
    for (int s = 0; s < 6; ++s) {
        const Dictionary side = Dictionary::parse("type " + scene.sides[s] + ";", "constant/grid");
        in.boundaries[s] = Registry<BoundaryCondition<3>>::select(side, side, static_cast<GridSide>(s));
    }
    in.gravity = Vector(0, -9.81, 0);
    const Dictionary flip = Dictionary::parse("transfer FLIP;", "system/mpmSchemes");
    in.transfer = Registry<ParticleTransfer>::select("FLIP", flip, flip, "transfer");
    return std::make_unique<MpmSolver<3>>(std::move(in));
}

} // namespace

int main(int argc, char* argv[])
{
    std::string name = "column";
    long steps = 300;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-scene" && i + 1 < argc) name = argv[++i];
        else if (arg == "-steps" && i + 1 < argc) steps = std::max(1L, std::atol(argv[++i]));
        else {
            std::fprintf(stderr, "usage: benchThreeD [-scene column|block] [-steps n]\n");
            return arg == "-help" || arg == "--help" || arg == "-h" ? 0 : 2;
        }
    }
    Scene scene;
    if (name == "column") {
        scene = {"type mohrCoulomb; rho 2650; E 0.84e6; nu 0.3; phi 19.8; psi 0; c 0;",
                 {120, 30, 25}, {40, 25, 25}, 0.005, 1e-5, {"slip", "slip", "fixed", "free", "slip", "slip"}};
    } else if (name == "block") {
        scene = {"type linearElastic; rho 1000; E 10e6; nu 0.3;",
                 {32, 34, 32}, {30, 30, 30}, 0.01, 5e-5, {"slip", "slip", "fixed", "free", "slip", "slip"}};
    } else {
        std::fprintf(stderr, "benchThreeD: unknown scene '%s'; valid choices: column, block\n", name.c_str());
        return 2;
    }
    setQuiet(true);
    auto solver = build(scene);
    const Dictionary none;
    const auto usl = Registry<UpdateScheme>::select("USL", none, none, "updateScheme");
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) {
        if (k % 100 == 0) solver->sortParticles();
        usl->advance(*solver, scene.dt);
        solver->setTime(solver->time() + scene.dt);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double n = double(solver->particles().size());
    std::printf("%s: %.0f particles, %ld steps, %d threads, %.3f s, %.3g particle-updates/s, %.0f solver bytes/particle\n",
                name.c_str(), n, steps, omp_get_max_threads(), wall, n * double(steps) / wall,
                solver->bytesPerParticle());
    solver->timers().print(std::cout);
    return 0;
}
