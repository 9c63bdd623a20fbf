#include "schemes/UpdateScheme.H"

namespace gpic {

GPIC_REGISTER(UpdateScheme, USL, "USL")
GPIC_REGISTER(UpdateScheme, USF, "USF")
GPIC_REGISTER(UpdateScheme, MUSL, "MUSL")

void USL::advance(Engine& s, double dt) const
{
    s.computeWeights();      // initialisation phase (2.4.1)
    s.particlesToGrid();
    s.computeForces();       // Lagrangian phase (2.4.2-2.4.8)
    s.updateGrid(dt);
    s.updateStress(dt);
    s.gridToParticles(dt);   // convective phase: the grid is simply reset next step
}

void USF::advance(Engine& s, double dt) const
{
    s.computeWeights();
    s.particlesToGrid();
    s.updateStress(dt);
    s.computeForces();
    s.updateGrid(dt);
    s.gridToParticles(dt);
}

void MUSL::advance(Engine& s, double dt) const
{
    s.computeWeights();
    s.particlesToGrid();
    s.computeForces();
    s.updateGrid(dt);
    s.gridToParticles(dt);
    s.remapVelocity(dt);
    s.updateStress(dt);
}

} // namespace gpic
