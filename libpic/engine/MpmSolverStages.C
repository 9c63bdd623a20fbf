// What a run in stages changes in the engine between two steps: the set of particles (layers
// filled or dug away, bodies woken or put to sleep) and the openings of the sides (gates);
// and the grid of a state written between steps.
#include "engine/MpmSolver.H"

#include "core/error.H"

#include <algorithm>

namespace gpic {

template <int D>
void MpmSolver<D>::replaceParticles(Particles<D> particles)
{
    if (passesHoldIndices())
        throw RunError("the applied loads of constant/loads hold particle indices: a stage may not "
                       "add or remove particles in a case with loads");
    particles_ = std::move(particles);
    matchAffine();
    setUpParticles();  // as the constructor: a restart of this state steps bitwise alike
    setUpPassParticles();
}

template <int D>
void MpmSolver<D>::projectToGrid()
{
    // A failure here (a particle outside the grid) ends the run, hooks muted or not.
    hooks_.mute(true);
    computeWeights();
    particlesToGrid();
    computeForces();
    hooks_.mute(false);
}

template <int D>
void MpmSolver<D>::refreshOpenings()
{
    sides_.refresh(grid_);
}

template void MpmSolver<2>::replaceParticles(Particles<2>);
#if GPIC_WITH_3D
template void MpmSolver<3>::replaceParticles(Particles<3>);
#endif
template void MpmSolver<2>::projectToGrid();
#if GPIC_WITH_3D
template void MpmSolver<3>::projectToGrid();
#endif
template void MpmSolver<2>::refreshOpenings();
#if GPIC_WITH_3D
template void MpmSolver<3>::refreshOpenings();
#endif

} // namespace gpic
