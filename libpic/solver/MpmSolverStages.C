// What a run in stages changes in the engine between two steps: the set of particles (layers
// filled or dug away, bodies woken or put to sleep) and the openings of the sides (gates).
#include "solver/MpmSolver.H"

#include "core/error.H"

#include <algorithm>

namespace gpic {

void MpmSolver::replaceParticles(Particles particles)
{
    if (!loads_.empty())
        throw RunError("the applied loads of constant/loads hold particle indices: a stage may not "
                       "add or remove particles in a case with loads");
    particles_ = std::move(particles);
    matchAffine();
    for (const auto& m : materials_)
        for (const auto& h : m->historyNames()) particles_.declareHistory(h);
    // The same order as the constructor makes of a time directory holding these particles:
    // a restart then steps bitwise as the straight run.
    particles_.sortByMaterial();
    reindex();
    for (const auto& b : blocks_)
        if (b.material < 0 || b.material >= static_cast<int>(materials_.size()))
            throw RunError("particle material id " + std::to_string(b.material) +
                           " has no material in constant/materials");
    markDeformingMaterials();
    // As the constructor: the small-mass cut-off follows the lightest particle present.
    double lightest = 0;
    for (double m : particles_.m) lightest = lightest == 0 ? m : std::min(lightest, m);
    minNodalMass_ = 1e-9 * lightest;
    if (hasRotation_) {  // as setupRotation: particles new to the scene, and the inertia cut-off
        if (!particles_.polar.enabled()) {
            particles_.polar.enable(particles_.size());
            for (std::size_t q = 0; q < particles_.size(); ++q) particles_.polar.sigma21[q] = particles_.sigma[q][XY];
        }
        double lightestJ = 0;
        for (std::size_t q = 0; q < particles_.size(); ++q) {
            const double mJ = particles_.m[q] * rotation_.materialJ[static_cast<std::size_t>(particles_.material[q])];
            if (mJ > 0) lightestJ = lightestJ == 0 ? mJ : std::min(lightestJ, mJ);
        }
        rotation_.minInertia = 1e-9 * lightestJ;
    }
}

void MpmSolver::refreshOpenings()
{
    // As the constructor: an open stretch's nodes are left free, a closed one is a wall.
    hasOutlet_ = false;
    for (int s = 0; s < 4; ++s) {
        const BoundaryCondition& bc = *boundaries_[s];
        sideNodes_[s].clear();
        for (int n : grid_.sideNodes(static_cast<GridSide>(s)))
            if (bc.isOpen(bc.along(grid_.nodePosition(n)))) hasOutlet_ = true;
            else sideNodes_[s].push_back(n);
        hasOutlet_ = hasOutlet_ || bc.letsOut();
    }
}

} // namespace gpic
