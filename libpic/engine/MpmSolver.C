#include "engine/MpmSolver.H"

#include "schemes/AffineVelocity.H"
#include "schemes/XpicFilter.H"

#include <Eigen/LU>

#include "core/error.H"
#include "core/Threads.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace gpic {

namespace {
//- sigma : eps for plane-strain tensors (the shear pair counted twice).
inline double contract(const Space<2>::SymTensor& s, double eXX, double eYY, double eZZ, double eXY)
{
    return s[XX] * eXX + s[YY] * eYY + s[ZZ] * eZZ + 2.0 * s[XY] * eXY;
}
//- sigma : eps (each shear pair counted twice).
template <class Tensor> double contract(const Tensor& s, const Tensor& e)
{
    double work = s[XX] * e[XX] + s[YY] * e[YY] + s[ZZ] * e[ZZ] + 2.0 * s[XY] * e[XY];
    for (int c = Space<2>::nSym; c < s.size(); ++c) work += 2.0 * s[c] * e[c];
    return work;
}
//- sigma grad N, the force a particle's stress puts on a node per unit volume (eq. 2.3.8).
inline Space<2>::Vector stressOnNode(const Space<2>::SymTensor& s, const Space<2>::Vector& dN)
{
    return Space<2>::Vector(s[XX] * dN.x() + s[XY] * dN.y(), s[XY] * dN.x() + s[YY] * dN.y());
}
inline Space<3>::Vector stressOnNode(const Space<3>::SymTensor& s, const Space<3>::Vector& dN)
{
    return Space<3>::Vector(s[XX] * dN[0] + s[XY] * dN[1] + s[XZ] * dN[2], s[XY] * dN[0] + s[YY] * dN[1] + s[YZ] * dN[2],
                            s[XZ] * dN[0] + s[YZ] * dN[1] + s[ZZ] * dN[2]);
}
//- The mean normal stress the cell means replace (the in-plane one in a plane scene, where
//  sigma33 follows from the plane-strain condition).
template <class Tensor> double meanNormalStress(const Tensor& s)
{
    if constexpr (Tensor::RowsAtCompileTime == Space<2>::nSym)
        return 0.5 * (s[XX] + s[YY]);
    else
        return (s[XX] + s[YY] + s[ZZ]) / 3.0;
}
} // namespace

template <int D>
void MpmSolver<D>::useTransfer(std::unique_ptr<ParticleTransfer> transfer)
{
    transfer_ = std::move(transfer);
    matchAffine();
}

template <int D>
void MpmSolver<D>::matchAffine()
{
    if (transfer_->affine()) particles_.carry(FieldGroup::affine);  // C_p zero for particles that had none
    else particles_.drop(FieldGroup::affine);
}

template <int D>
MpmSolver<D>::MpmSolver(SolverInputs<D> in)
    : grid_(std::move(in.grid)), particles_(std::move(in.particles)), materials_(std::move(in.materials)),
      shape_(std::move(in.shape)), sides_(std::move(in.boundaries), grid_), strips_(grid_),
      transfer_(std::make_unique<FlipTransfer>(Dictionary::parse("transfer FLIP;", "the seed's FLIP")))
{
    ranks_ = in.ranks;
    setUpParticles();
    // The order matters: the rigid bodies' mass properties take gravity, the contact pass's
    // arrays the rigid bodies.
    gravity_ = in.gravity;
    damping_ = in.damping;
    setMassScaling(in.massScaling);
    if (in.transfer) useTransfer(std::move(in.transfer));
    // In an axisymmetric scene the hoop pass takes the cell means over the three normal
    // components (AxisymmetricHoop.H): the in-plane means alone would leave the hoop strain
    // constrained at every particle.
    if (in.cellMeanDilatation && !in.grid.axisymmetric()) cellMean_ = std::make_unique<CellMeanDilatation<D>>();
    time_ = in.time;
    removedMass_ = in.removedMass;
    if (!in.rigidBodies.empty()) attachRigidBodies(std::move(in.rigidBodies));
    coupleGrid(std::move(in.contact));
    // The passes last: the loads select particles in their final order.
    PassScene<D> scene{grid_, particles_, materials_, sides_, *shape_, *transfer_, in};
    for (auto& pass : assemblePasses(scene)) addPass(std::move(pass));
    affine_ = find<AffineVelocity<D>>();
    affineSkipsLightNodes_ = in.remapsVelocity;
    filter_ = find<XpicFilter<D>>();
    setUpPassParticles();
}

template <int D>
void MpmSolver<D>::coupleGrid(std::unique_ptr<ContactPass<D>> contact)
{
    CouplingParts<D> parts;
    parts.grid = &grid_;
    parts.contact = std::move(contact);
    parts.rigid = &rigid_;
    coupling_ = GridCoupling<D>::New(parts);
    coupling_->attach(grid_, rigid_);
}

template <int D>
const std::vector<typename Space<D>::Vector>& MpmSolver<D>::affineCentres() const
{
    static const std::vector<Vector> none;
    return affine_ ? affine_->centres() : none;
}

template <int D>
EngineView<D> MpmSolver<D>::view()
{
    return EngineView<D>{grid_,    particles_, weights_, strips_,       sides_,      rigid_,          *coupling_,
                      *transfer_, gravity_,  time_,    damping_,      minNodalMass_, massScale_, affineCentres(),
                      timers_,    rankSums_};
}

template <int D>
void MpmSolver<D>::addPass(std::unique_ptr<EnginePass<D>> pass)
{
    for (const StepPoint point : pass->points()) passAt_[static_cast<std::size_t>(point)].push_back(pass.get());
    passes_.push_back(std::move(pass));
}

template <int D>
bool MpmSolver<D>::passesHoldIndices() const
{
    return std::any_of(passes_.begin(), passes_.end(), [](const auto& pass) { return pass->holdsParticleIndices(); });
}

template <int D>
void MpmSolver<D>::renumberPasses(const std::vector<std::size_t>& newIndex)
{
    for (auto& pass : passes_) pass->renumber(newIndex, particles_.size());
}

template <int D>
void MpmSolver<D>::reach(StepPoint point, double dt)
{
    const auto& passes = passAt_[static_cast<std::size_t>(point)];
    if (!passes.empty()) {
        EngineView<D> engine = view();
        for (EnginePass<D>* pass : passes) pass->at(point, engine, dt);
    }
    hooks_.call(point, *this);
}

template <int D>
double MpmSolver<D>::passTimeStep() const
{
    double dt = 1e300;
    for (std::size_t m = 0; m < materials_.size(); ++m)
        if (materialDeforms_[m]) dt = std::min(dt, passTimeStep(m));
    return dt;
}

template <int D>
double MpmSolver<D>::passTimeStep(std::size_t m) const
{
    double dt = 1e300;
    for (const auto& pass : passes_)
        dt = std::min(dt, pass->maxDeltaT(m, grid_.minCellSize(), massScale_.empty() ? 1.0 : massScale_[m]));
    return dt;
}

template <int D>
std::string MpmSolver<D>::passTimeStepName() const
{
    for (const auto& pass : passes_)
        if (!pass->stepLimitName().empty()) return pass->stepLimitName();
    return "";
}

template <int D>
void MpmSolver<D>::setMassScaling(const MassScaling& scaling)
{
    massScaling_ = scaling;
    massScale_.clear();
    if (!scaling.active()) return;
    const double h = grid_.minCellSize();
    for (const auto& m : materials_) {
        const double c = m->waveSpeed();
        double stable = c > 0 ? h / c : 1e300;
        if (m->needsRotation()) stable = std::min(stable, m->polar()->rotationalTimeStep(h));
        massScale_.push_back(scaling.scaleFor(stable));
    }
}

template <int D>
void MpmSolver<D>::setUpParticles()
{
    // The arrays the materials declare; plastic strain only where a material writes it.
    bool plastic = false;
    for (const auto& m : materials_) {
        m->declareFields(particles_);
        for (FieldGroup g : m->particleFields()) plastic = plastic || g == FieldGroup::plasticStrain;
    }
    if (!plastic) particles_.drop(FieldGroup::plasticStrain);
    // The order a time directory of these particles gets in a restart too: a restart then
    // steps bitwise as the straight run.
    particles_.sortByMaterial();
    reindex();
    for (const auto& b : blocks_)
        if (b.material < 0 || b.material >= static_cast<int>(materials_.size()))
            throw RunError("particle material id " + std::to_string(b.material) +
                           " has no material in constant/materials");
    markDeformingMaterials();
    // The small-mass cut-off follows the lightest particle present. In a parallel run it is
    // a minimum over the ranks, taken at the start and where the run's particles change
    // (updateSmallMassCutoff, on every rank), not where particles only change hands.
    if (!ranks_.parallel() || !cutoffTaken_) updateSmallMassCutoff();
}

template <int D>
void MpmSolver<D>::updateSmallMassCutoff()
{
    double lightest = 0;
    for (double m : particles_.m) lightest = lightest == 0 ? m : std::min(lightest, m);
    if (ranks_.parallel()) {  // every rank's lightest: the same cut-off as the serial run
        const double none = std::numeric_limits<double>::max();
        lightest = ranks_.smallest(lightest > 0 ? lightest : none);
        if (lightest == none) lightest = 0.0;
    }
    minNodalMass_ = 1e-9 * lightest;
    cutoffTaken_ = true;
}

template <int D>
void MpmSolver<D>::setUpPassParticles()
{
    bool polar = false;
    for (auto& pass : passes_) {
        pass->setUpParticles(particles_);
        polar = polar || pass->particleGroup() == FieldGroup::polar;
    }
    // A nonpolar scene drops any rotation arrays read.
    if (!polar) particles_.drop(FieldGroup::polar);
}

template <int D>
void MpmSolver<D>::reindex()
{
    blocks_ = particles_.blocks();
    // Pieces of a fixed size: the material update then balances over any thread count.
    constexpr std::size_t chunk = 512;
    chunks_.clear();
    for (const auto& b : blocks_)
        for (std::size_t begin = b.begin; begin < b.end; begin += chunk)
            chunks_.push_back({begin, std::min(b.end, begin + chunk), b.material});
    rigidParticles_.clear();
    for (std::size_t q = 0; q < particles_.size(); ++q)
        if (driverOf(q)) rigidParticles_.push_back(q);
}

template <int D>
void MpmSolver<D>::sortParticles()
{
    auto timer = timers_.time("sort");
    Particles<D>& p = particles_;
    const auto n = static_cast<long>(p.size());
    sortKey_.resize(p.size());
    const long nCells = grid_.nCells();
    parallelFor(n, [&](long q) {
        sortKey_[q] = grid_.contains(p.x[q]) ? p.material[q] * nCells + strips_.cellKey(grid_, p.x[q])
                                             : p.material[q] * nCells;  // reported by computeWeights
    });
    sortOrder_.resize(p.size());
    std::iota(sortOrder_.begin(), sortOrder_.end(), std::size_t(0));
    // Stable: equal keys keep their order, so the result depends on the state only.
    std::stable_sort(sortOrder_.begin(), sortOrder_.end(),
                     [&](std::size_t a, std::size_t b) { return sortKey_[a] < sortKey_[b]; });
    if (std::is_sorted(sortOrder_.begin(), sortOrder_.end())) return;
    p.reorder(sortOrder_);
    if (passesHoldIndices()) {
        std::vector<std::size_t> newIndex(p.size());
        for (std::size_t k = 0; k < sortOrder_.size(); ++k) newIndex[sortOrder_[k]] = k;
        renumberPasses(newIndex);
    }
    reindex();
}

template <int D>
void MpmSolver<D>::computeWeights()
{
    auto timer = timers_.time("shapeFunctions");
    const Particles<D>& p = particles_;
    const auto n = static_cast<long>(p.size());
    // The lowest-numbered particle outside the grid, for a stable message.
    const long first = parallelFirst(n, [&](long q) {
        return !grid_.contains(p.x[q]) || !p.x[q].allFinite();
    });
    if (first < n) {
        const auto q = static_cast<std::size_t>(first);
        std::ostringstream msg;
        msg << "particle " << p.id[q] << " (body " << p.body[q] << ", material "
            << materials_[p.material[q]]->name() << ") at (";
        for (int a = 0; a < D; ++a) msg << (a ? " " : "") << p.x[q][a];
        msg << ") is outside the grid [" << grid_.origin().transpose()
            << "] - [" << grid_.upper().transpose() << "]";
        throw RunError(msg.str());
    }
    shape_->evaluate(grid_, p, weights_);
    strips_.assign(grid_, p);
    if (cellMean_) cellMean_->assign(grid_, p, [&](std::size_t q) { return driverOf(q) != nullptr; });
}

template <int D>
void MpmSolver<D>::particlesToGrid()
{
    auto timer = timers_.time("particlesToGrid");
    EngineView<D> engine = view();
    coupling_->particlesToGrid(engine, time_);
    reach(StepPoint::afterParticlesToGrid, 0.0);
}

template <int D>
void MpmSolver<D>::setRigidBodies(std::vector<std::unique_ptr<RigidBodyDriver<D>>> drivers)
{
    attachRigidBodies(std::move(drivers));
    coupleGrid(coupling_->releaseContact());  // a rigid body may come or go: the strategy with it
}

template <int D>
void MpmSolver<D>::attachRigidBodies(std::vector<std::unique_ptr<RigidBodyDriver<D>>> drivers)
{
    // Keep the table only when some body is rigid: otherwise no rigid pass runs at all.
    const bool anyRigid = std::any_of(drivers.begin(), drivers.end(), [](const auto& d) { return d != nullptr; });
    rigid_ = anyRigid ? std::move(drivers) : std::vector<std::unique_ptr<RigidBodyDriver<D>>>{};
    if (anyRigid) {
        const auto info = RigidBodyInfo<D>::ofBodies(particles_, rigid_.size(), gravity_, ranks_);
        for (std::size_t b = 0; b < rigid_.size(); ++b)
            if (rigid_[b]) rigid_[b]->attach(info[b]);
    }
    markDeformingMaterials();
    reindex();
}

template <int D>
void MpmSolver<D>::markDeformingMaterials()
{
    materialDeforms_.assign(materials_.size(), 0);
    bool any = false;
    for (std::size_t q = 0; q < particles_.size(); ++q)
        if (!driverOf(q)) {
            const int m = particles_.material[q];
            if (m >= 0 && m < static_cast<int>(materials_.size())) materialDeforms_[m] = any = true;
        }
    // No deformable particle yet (a fill whose layers all sleep): every material counts, so
    // the time step stays finite and on the safe side. Not on one rank of a parallel run, whose
    // subdomain may hold a rigid body alone: the step's terms come from every rank's particles.
    if (!any && !ranks_.parallel()) materialDeforms_.assign(materials_.size(), 1);
}

template <int D>
void MpmSolver<D>::computeForces()
{
    auto timer = timers_.time("forces");
    const Particles<D>& p = particles_;
    const int stride = weights_.stride;
    if (cellMean_)
        cellMean_->average(p, [&](std::size_t q) { return meanNormalStress(p.sigma[q]); }, cellMeanValue_);
    // The arrays' pointers in locals: Eigen's SSE stores may alias anything, and the compiler
    // would otherwise reload every vector's data pointer after each addition into a node.
    const int* node = weights_.node.data();
    const double* N = weights_.N.data();
    const Vector* dNs = weights_.dN.data();
    Vector* fIntAt = grid_.fInt.data();
    Vector* fExtAt = grid_.fExt.data();
    const Vector g = gravity_;
    strips_.forEach([&, node, N, dNs, fIntAt, fExtAt, g, stride](std::size_t q) {
        // A rigid body carries no stress: its nodes are driven instead.
        SymTensor s = driverOf(q) ? SymTensor::Zero() : p.sigma[q];
        if (cellMean_) {  // the cell's mean pressure (in-plane in 2D) in place of the particle's own
            const double shift = cellMeanValue_[q] - meanNormalStress(s);
            for (int c = 0; c < D; ++c) s[c] += shift;
        }
        const std::size_t k0 = q * stride;
        BodyField<D>* body = coupling_->bodyField(p.body[q]);
        Vector* bodyForce = body ? body->force.data() : nullptr;  // in a local, as the others
        const double Vp = p.V[q], mp = p.m[q];
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const Vector dN = dNs[k0 + a];
            // eq. 2.3.8: F_int = -sum_p V_p B_p^T sigma_p
            const Vector fInt = -Vp * stressOnNode(s, dN);
            const Vector fExt = (N[k0 + a] * mp) * g;  // eq. 2.3.9; loads: AppliedLoads
            fIntAt[n] += fInt;
            fExtAt[n] += fExt;
            // With a contact pass the same terms go to the body's own field too.
            if (bodyForce) bodyForce[n] += fInt + fExt;
        }
    });
    reach(StepPoint::afterForces, 0.0);
}

template <int D>
void MpmSolver<D>::updateGrid(double dt)
{
    deltaT_ = dt;
    if (rankSums_) rankSums_->completeForces(grid_);  // a parallel run: the other ranks' parts
    reach(StepPoint::beforeGridUpdate, dt);
    EngineView<D> engine = view();
    coupling_->updateGrid(engine, time_ + dt, dt);
    reach(StepPoint::afterGridUpdate, dt);
}

template <int D>
void MpmSolver<D>::updateStress(double dt)
{
    Particles<D>& p = particles_;
    const auto nParticles = static_cast<long>(p.size());
    {
        auto timer = timers_.time("strain");
        const int stride = weights_.stride;
        const int* node = weights_.node.data();  // in locals, as in gridToParticles
        const Vector* dNw = weights_.dN.data();
        // Velocity gradient L_ab = sum_i v_i,a dN_i/dx_b (B v of eq. 2.4.5, plus spin).
        const auto velocityGradient = [&, node, dNw, stride](std::size_t q) {
            Gradient L = Gradient::Zero();
            if (driverOf(q)) return L;  // rigid: no strain, no spin, no volume change
            const std::size_t k0 = q * stride;
            // With a contact pass each body deforms with its own velocity field.
            const Vector* velocity = coupling_->velocity(grid_, coupling_->fieldOf(p.body[q])).data();
            for (int a = 0; a < stride; ++a) {
                const int n = node[k0 + a];
                if (n < 0) continue;
                L.noalias() += velocity[n] * dNw[k0 + a].transpose();
            }
            return L;
        };
        const auto strainIncrement = [&](std::size_t q, const Gradient& L) {
            if constexpr (D == 3) {
                SymTensor& de = p.dEps[q];
                de << dt * L(0, 0), dt * L(1, 1), dt * L(2, 2), 0.5 * dt * (L(0, 1) + L(1, 0)),
                    0.5 * dt * (L(1, 2) + L(2, 1)), 0.5 * dt * (L(0, 2) + L(2, 0));
                // The spin's components in the order of the shears (W12, W23, W13), JaumannRate.H.
                p.dOmega[q] = typename Space<D>::Spin(0.5 * dt * (L(0, 1) - L(1, 0)), 0.5 * dt * (L(1, 2) - L(2, 1)),
                                                      0.5 * dt * (L(0, 2) - L(2, 0)));
                p.eps[q] += de;
                p.V[q] *= (Gradient::Identity() + dt * L).determinant();  // V_{t+1} = det(I + dt L) V_t
                p.work[q] += 0.5 * p.V[q] * contract(p.sigma[q], de);
            } else {
                // Kept as scalars: reading freshly stored components back as a pair stalls on
                // store forwarding (a third of this pass).
                const double dXX = dt * L(0, 0), dYY = dt * L(1, 1), dZZ = 0.0 /* plane strain */,
                             dXY = 0.5 * dt * (L(0, 1) + L(1, 0));
                SymTensor& de = p.dEps[q];
                de[XX] = dXX;
                de[YY] = dYY;
                de[ZZ] = dZZ;
                de[XY] = dXY;
                p.dOmega[q] = 0.5 * dt * (L(0, 1) - L(1, 0));
                SymTensor& eps = p.eps[q];
                eps[XX] += dXX;
                eps[YY] += dYY;
                eps[ZZ] += dZZ;
                eps[XY] += dXY;
                // Volume follows the deformation: V_{t+1} = det(I + dt L) V_t.
                p.V[q] *= (1.0 + dt * L(0, 0)) * (1.0 + dt * L(1, 1)) - dt * dt * L(0, 1) * L(1, 0);
                // Stress work by the trapezoidal rule (first half): an energy measure valid for every material.
                p.work[q] += 0.5 * p.V[q] * contract(p.sigma[q], dXX, dYY, dZZ, dXY);
            }
        };
        if (!cellMean_) {
            parallelFor(nParticles, [&](long q) { strainIncrement(q, velocityGradient(q)); });
        }
        else {
            velocityGradient_.resize(p.size());
            parallelFor(nParticles, [&](long q) { velocityGradient_[q] = velocityGradient(q); });
            cellMean_->average(p, [&](std::size_t q) { return velocityGradient_[q].trace(); }, cellMeanValue_);
            parallelFor(nParticles, [&](long q) {
                // The cell's mean dilatation rate in place of the particle's own; shear and spin kept.
                Gradient& L = velocityGradient_[q];
                L.diagonal().array() += (1.0 / D) * (cellMeanValue_[q] - L.trace());
                strainIncrement(q, L);
            });
        }
    }
    reach(StepPoint::afterStrain, dt);
    auto timer = timers_.time("material");
    const auto nChunks = static_cast<long>(chunks_.size());
    parallelForDynamic(nChunks, nParticles >= minParallelWork(), [&](long c) {
        const ParticleBlock& chunk = chunks_[c];
        materials_[chunk.material]->updateStress(p, chunk, dt);
        for (std::size_t q = chunk.begin; q < chunk.end; ++q) p.work[q] += 0.5 * p.V[q] * contract(p.sigma[q], p.dEps[q]);
    });
    if (cellMean_) cellMean_->holdCellPressure(p, cellMeanValue_);
    reach(StepPoint::afterStressUpdate, dt);
}

template <int D>
void MpmSolver<D>::gridToParticles(double dt)
{
    reach(StepPoint::beforeGridToParticles, dt);
    auto timer = timers_.time("gridToParticles");
    Particles<D>& p = particles_;
    const int stride = weights_.stride;
    const auto nParticles = static_cast<long>(p.size());
    const double flip = transfer_->flipShare(dt);
    // Pointers in locals: Eigen's SSE stores may alias anything, and what the loop reads
    // through memory is reloaded after each of them (doc/threading.md).
    const int* node = weights_.node.data();
    const double* Nw = weights_.N.data();
    // Inlined into the threaded loop, as before the engine was a template: GCC then kept the
    // body as a call per particle.
    const LoopReport report = parallelForChecked(nParticles, [&, node, Nw, stride](long q) __attribute__((always_inline)) {
        if (driverOf(q)) return LoopMark::none;  // moved below
        Vector vNew = Vector::Zero(), a = Vector::Zero(), vStar = Vector::Zero();
        const std::size_t k0 = q * stride;
        // With a contact pass each body moves with its own corrected field (seed G.4 steps 3-4).
        const int f = coupling_->fieldOf(p.body[q]);
        const std::vector<Vector>& velocityField = coupling_->velocity(grid_, f);
        const Vector* velocity = velocityField.data();
        const Vector* accel = coupling_->accel(grid_, f).data();
        const bool xpic = filter_ != nullptr;
        const Vector* star = xpic ? filter_->field(f).data() : nullptr;
        for (int k = 0; k < stride; ++k) {
            const int n = node[k0 + k];
            if (n < 0) continue;
            const double N = Nw[k0 + k];
            vNew += N * velocity[n];
            a += N * accel[n];
            if (xpic) vStar += N * star[n];
        }
        if (affine_)
            affine_->form(p, weights_, static_cast<std::size_t>(q), velocityField, p.x[q],
                          affineSkipsLightNodes_ ? grid_.mass.data() : nullptr, vNew);
        p.x[q] += dt * vNew;  // eq. 2.4.7
        if (xpic) p.v[q] = vStar + dt * a;  // XPIC: the filtered v^t plus the increment
        // eq. 2.4.8 (FLIP), blended with PIC when the FLIP share is below 1: a particle's own
        // velocity beyond what its nodes carry (the FLIP null space, e.g. at a wall that stops
        // its nodes) then decays instead of persisting. PIC and APIC: share 0.
        else p.v[q] = flip * (p.v[q] + dt * a) + (1.0 - flip) * vNew;
        // A NaN or an infinity in any component. Summed from scalar reads: a packed read of
        // the velocity just stored as two halves waits for the stores (a quarter of this pass).
        double speedSum = p.v[q][0];
        for (int a = 1; a < D; ++a) speedSum += p.v[q][a];
        const bool failed = !std::isfinite(speedSum);
        const bool returned = !grid_.contains(p.x[q]) && sides_.keepInsideWalls(grid_, p.x[q], p.v[q]);
        return failed ? LoopMark::failure : (returned ? LoopMark::noted : LoopMark::none);
    });
    wallReturns_ += static_cast<std::size_t>(report.notes);
    const long firstBad = report.firstFailure;
    for (std::size_t q : rigidParticles_) {  // drivers cache their motion: serial
        const RigidBodyDriver<D>* body = driverOf(q);
        p.x[q] = body->move(time_, dt, p.x[q]);
        p.v[q] = body->velocity(time_ + dt, p.x[q]);
    }
    if (firstBad < nParticles) {
        const auto q = static_cast<std::size_t>(firstBad);
        throw RunError("particle " + std::to_string(p.id[q]) + " (material " + materials_[p.material[q]]->name() +
                       ") has a non-finite velocity: the step is unstable");
    }
    reach(StepPoint::afterGridToParticles, dt);
}

template <int D>
void MpmSolver<D>::endStep(double dt)
{
    advanceRigidBodies(dt);
    removeOutflow();  // particles gone through an opening (silo outlet)
    reach(StepPoint::endOfStep, dt);
}

template <int D>
void MpmSolver<D>::advanceRigidBodies(double dt)
{
    for (std::size_t b = 0; b < rigid_.size(); ++b)
        if (rigid_[b]) rigid_[b]->advance(time_, dt, coupling_->loads()[b]);
}

template <int D>
void MpmSolver<D>::remapVelocity(double dt)
{
    auto timer = timers_.time("particlesToGrid");
    EngineView<D> engine = view();
    coupling_->remapVelocity(engine, time_ + dt, dt);
    reach(StepPoint::afterRemap, dt);  // APIC: C_p from the remapped velocity (AffineVelocity)
}

template <int D>
double MpmSolver<D>::maxParticleSpeed() const
{
    // One square root, of the largest |v|^2: the same value (the root is monotone and
    // correctly rounded), without a root per particle and step.
    return std::sqrt(parallelMax(static_cast<long>(particles_.size()), [&](long q) { return particles_.v[q].squaredNorm(); }));
}

template <int D>
double MpmSolver<D>::stepLength() const
{
    double length = grid_.minCellSize();
    const DeformingParticles<D> deforms{materialDeforms_, rigid_};
    for (const auto& pass : passes_) length = std::min(length, pass->stepLength(grid_, particles_, deforms));
    return length;
}

template <int D>
double MpmSolver<D>::criticalTimeStep() const
{
    const double dt = stepLength() / (maxWaveSpeed() + maxParticleSpeed());
    return std::min(dt, passTimeStep());
}

template <int D>
double MpmSolver<D>::maxWaveSpeed() const
{
    double c = 0;
    for (std::size_t m = 0; m < materials_.size(); ++m)
        if (materialDeforms_[m]) c = std::max(c, waveSpeed(m));
    return c;
}

template <int D>
double MpmSolver<D>::waveSpeed(std::size_t m) const
{
    const double c = materials_[m]->waveSpeed();
    return massScale_.empty() ? c : c / std::sqrt(massScale_[m]);  // c = sqrt(M / (s rho))
}

template <int D>
double MpmSolver<D>::bytesPerParticle() const
{
    if (particles_.size() == 0) return 0.0;
    const std::size_t weights = weights_.node.capacity() * sizeof(int) + weights_.N.capacity() * sizeof(double) +
                                weights_.dN.capacity() * sizeof(Vector);
    std::size_t passes = 0;
    for (const auto& pass : passes_) passes += pass->particleBytes();
    const std::size_t cellMeans = cellMean_ ? cellMean_->particleBytes() + cellMeanValue_.capacity() * sizeof(double) +
                                                  velocityGradient_.capacity() * sizeof(Gradient)
                                            : 0;
    return double(particles_.bytes() + weights + passes + cellMeans) / double(particles_.size());
}

template <int D>
std::size_t MpmSolver<D>::removeOutflow()
{
    if (!sides_.hasOutlet()) return 0;
    Particles<D>& p = particles_;
    const auto n = static_cast<long>(p.size());
    const auto leaves = [&](std::size_t q) { return !grid_.contains(p.x[q]) && !driverOf(q) && sides_.leftThroughOpening(grid_, p.x[q]); };
    const long leaving = parallelCount(n, [&](long q) { return leaves(static_cast<std::size_t>(q)); });
    if (leaving == 0) return 0;
    // Keep the others in their order (blocks stay contiguous); tell the loads.
    std::vector<std::size_t> kept, newIndex(p.size(), ParticleLoad<D>::removedParticle);
    kept.reserve(p.size() - static_cast<std::size_t>(leaving));
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (leaves(q)) {
            removedMass_ += p.m[q];
            continue;
        }
        newIndex[q] = kept.size();
        kept.push_back(q);
    }
    p.reorder(kept);
    renumberPasses(newIndex);
    reindex();
    return static_cast<std::size_t>(leaving);
}

template class MpmSolver<2>;
#if GPIC_WITH_3D
template class MpmSolver<3>;
#endif

} // namespace gpic
