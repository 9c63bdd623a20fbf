#include "solver/MpmSolver.H"

#include "core/Threads.H"
#include "core/error.H"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace gpic {

namespace {
//- sigma : eps for plane-strain tensors (the shear pair counted twice).
inline double contract(const SymTensor& s, const SymTensor& e)
{
    return s[XX] * e[XX] + s[YY] * e[YY] + s[ZZ] * e[ZZ] + 2.0 * s[XY] * e[XY];
}
} // namespace

void MpmSolver::useTransfer(std::unique_ptr<ParticleTransfer> transfer)
{
    transfer_ = std::move(transfer);
    matchAffine();
    affineCentre_.clear();
    if (transfer_->affine())
        for (int n = 0; n < grid_.nNodes(); ++n) affineCentre_.push_back(shape_->affineCentre(grid_, n));
    filtered_.clear();
    filterScratch_.clear();
}

void MpmSolver::matchAffine()
{
    if (transfer_->affine()) particles_.carry(FieldGroup::affine);  // C_p zero for particles that had none
    else particles_.drop(FieldGroup::affine);
}

void MpmSolver::formAffine(std::size_t q, const std::vector<Vector2>& velocity, const Vector2& xp)
{
    Particles& p = particles_;
    const int stride = weights_.stride;
    const std::size_t k0 = q * stride;
    const bool fromGradient = shape_->affineFromGradient();
    Eigen::Matrix2d B = Eigen::Matrix2d::Zero(), D = Eigen::Matrix2d::Zero();
    for (int k = 0; k < stride; ++k) {
        const int n = weights_.node[k0 + k];
        if (n < 0) continue;
        const double N = weights_.N[k0 + k];
        const Vector2 r = affineCentre_[n] - xp;
        D.noalias() += (N * r) * r.transpose();  // D_p, h^2/4 I inside a B-spline grid
        // bilinear: B_p D_p^-1 is the velocity gradient (D_p singular on a grid line)
        if (fromGradient) B.noalias() += velocity[n] * weights_.dN[k0 + k].transpose();
        else B.noalias() += (N * velocity[n]) * r.transpose();  // B_p (Jiang et al. 2015)
    }
    Eigen::Matrix2d& C = p.affine[q];
    C = fromGradient ? B : Eigen::Matrix2d(B * D.inverse());
    p.affineEnergy[q] = 0.5 * p.m[q] * (C * D * C.transpose()).trace();
}

void MpmSolver::filterVelocity(double dt, int order)
{
    auto timer = timers_.time("transferFilter");
    const int nFields = contact_ ? contact_->nBodies() : 1;
    const auto nodes = static_cast<std::size_t>(grid_.nNodes());
    filtered_.resize(static_cast<std::size_t>(nFields));
    filterScratch_.resize(2 * static_cast<std::size_t>(nFields));
    const auto isRigidField = [&](int f) { return contact_ && !rigid_.empty() && rigid_[f]; };
    const auto massOf = [&](int f) -> const std::vector<double>& { return contact_ ? contact_->field(f).mass : grid_.mass; };
    for (int f = 0; f < nFields; ++f) {
        filtered_[f].resize(nodes);
        filterScratch_[2 * f].resize(nodes);
        filterScratch_[2 * f + 1].resize(nodes);
        if (isRigidField(f)) continue;  // a rigid body's particles follow their driver
        const std::vector<Vector2>& v = contact_ ? contact_->field(f).velocity : grid_.velocity;
        const std::vector<Vector2>& a = contact_ ? contact_->field(f).accel : grid_.accel;
        std::vector<Vector2>& w = filterScratch_[2 * f];
        grid_.forEachActiveNode([&](int n) {
            w[n] = v[n] - dt * a[n];  // v^t with its conditions: the velocity the update started from
            filtered_[f][n] = double(order) * w[n];
        });
    }
    const Particles& p = particles_;
    const int stride = weights_.stride;
    double binomial = order;  // C(m, k-1)
    for (int k = 2; k <= order; ++k) {
        binomial *= double(order - k + 1) / double(k);  // C(m, k)
        const double coefficient = (k % 2 == 0 ? -1.0 : 1.0) * binomial;
        for (int f = 0; f < nFields; ++f) {
            std::vector<Vector2>& next = filterScratch_[2 * f + 1];
            grid_.forEachActiveNode([&](int n) { next[n].setZero(); });
        }
        // One projection grid -> particles -> grid per field: S^T M_p S w, then / m_i.
        strips_.forEach([&](std::size_t q) {
            const int f = contact_ ? p.body[q] : 0;
            if (isRigidField(f)) return;
            const std::vector<Vector2>& w = filterScratch_[2 * f];
            std::vector<Vector2>& next = filterScratch_[2 * f + 1];
            const std::size_t k0 = q * stride;
            Vector2 vq = Vector2::Zero();
            for (int c = 0; c < stride; ++c) {
                const int n = weights_.node[k0 + c];
                if (n >= 0) vq += weights_.N[k0 + c] * w[n];
            }
            for (int c = 0; c < stride; ++c) {
                const int n = weights_.node[k0 + c];
                if (n >= 0) next[n] += (weights_.N[k0 + c] * p.m[q]) * vq;
            }
        });
        for (int f = 0; f < nFields; ++f) {
            if (isRigidField(f)) continue;
            const std::vector<double>& mass = massOf(f);
            const std::vector<Vector2>& v = contact_ ? contact_->field(f).velocity : grid_.velocity;
            const std::vector<Vector2>& a = contact_ ? contact_->field(f).accel : grid_.accel;
            std::vector<Vector2>& next = filterScratch_[2 * f + 1];
            grid_.forEachActiveNode([&](int n) {
                next[n] = mass[n] > 0.0 ? Vector2(next[n] / mass[n]) : Vector2::Zero();
            });
            applyBoundaries(next);
            // A node a rigid tool drives keeps the velocity the update started from.
            if (drivesRigidNodes())
                for (int n : grid_.active)
                    if (rigidNodes_.bodyAt(n) >= 0) next[n] = v[n] - dt * a[n];
            grid_.forEachActiveNode([&](int n) {
                filtered_[f][n] += coefficient * next[n];
            });
            filterScratch_[2 * f].swap(next);
        }
    }
}

bool MpmSolver::needsRotation(const Particles& particles, const std::vector<std::unique_ptr<Material>>& materials)
{
    // A polar material that constant/materials lists but no body uses costs nothing.
    for (int m : particles.material)
        if (m >= 0 && m < static_cast<int>(materials.size()) && materials[m]->needsRotation()) return true;
    return false;
}

MpmSolver::MpmSolver(SolverInputs in)
    : grid_(std::move(in.grid)), particles_(std::move(in.particles)), materials_(std::move(in.materials)),
      shape_(std::move(in.shape)), boundaries_(std::move(in.boundaries)), strips_(grid_),
      transfer_(std::make_unique<FlipTransfer>(Dictionary::parse("transfer FLIP;", "the seed's FLIP")))
{
    refreshOpenings();  // the constrained side nodes
    if (needsRotation(particles_, materials_)) addRotation();  // polar scenes only
    setUpParticles();
    if (in.carryRotation) enableRotation();
    // The order matters: the rigid bodies' mass properties take gravity, the contact pass's
    // arrays the rigid bodies.
    gravity_ = in.gravity;
    damping_ = in.damping;
    if (in.transfer) useTransfer(std::move(in.transfer));
    if (in.cellMeanDilatation) cellMean_ = std::make_unique<CellMeanDilatation>();
    time_ = in.time;
    removedMass_ = in.removedMass;
    if (rotation_ && in.rotationSides) rotation_->setSideFixed(*in.rotationSides);
    if (rotation_ && !in.rigidRotation.empty()) rotation_->setRigidFixed(std::move(in.rigidRotation));
    if (!in.rigidBodies.empty()) setRigidBodies(std::move(in.rigidBodies));
    if (!in.loads.empty()) useLoads(std::move(in.loads), in.bodyNames);
    useContact(std::move(in.contact));
}

void MpmSolver::enableRotation()
{
    if (rotation_) return;
    addRotation();
    rotation_->setUpParticles(particles_);
}

void MpmSolver::addRotation()
{
    auto pass = std::make_unique<CosseratRotation>(materials_, boundaries_, grid_.nNodes());
    rotation_ = pass.get();
    addPass(std::move(pass));
}

void MpmSolver::addPass(std::unique_ptr<EnginePass> pass)
{
    for (const StepPoint point : pass->points()) passAt_[static_cast<std::size_t>(point)].push_back(pass.get());
    passes_.push_back(std::move(pass));
}

void MpmSolver::reach(StepPoint point, double dt)
{
    const auto& passes = passAt_[static_cast<std::size_t>(point)];
    if (!passes.empty()) {
        EngineView engine{grid_,    particles_,   weights_,
                          strips_,  sideNodes_,   rigid_,
                          drivesRigidNodes() ? &rigidNodes_ : nullptr,
                          contact_.get(), *transfer_, damping_, timers_};
        for (EnginePass* pass : passes) pass->at(point, engine, dt);
    }
    hooks_.call(point, *this);
}

void MpmSolver::setRigidRotation(std::vector<char> fixed)
{
    if (rotation_) rotation_->setRigidFixed(std::move(fixed));
}

const CosseratField& MpmSolver::rotationField() const
{
    static const CosseratField none;
    return rotation_ ? rotation_->field() : none;
}

double MpmSolver::rotationalTimeStep() const
{
    return rotation_ ? rotation_->timeStep(materials_, materialDeforms_, grid_.minCellSize()) : 1e300;
}

void MpmSolver::setUpParticles()
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
    // The small-mass cut-off follows the lightest particle present.
    double lightest = 0;
    for (double m : particles_.m) lightest = lightest == 0 ? m : std::min(lightest, m);
    minNodalMass_ = 1e-9 * lightest;
    // A nonpolar scene drops any rotation arrays read.
    if (rotation_) rotation_->setUpParticles(particles_);
    else particles_.drop(FieldGroup::polar);
}

void MpmSolver::applyBoundaries(std::vector<Vector2>& field) const
{
    for (int s = 0; s < 4; ++s) boundaries_[s]->constrain(field, sideNodes_[s]);
}

void MpmSolver::reindex()
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

void MpmSolver::sortParticles()
{
    auto timer = timers_.time("sort");
    Particles& p = particles_;
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
    if (!particleForce_.empty()) {
        std::vector<std::size_t> newIndex(p.size());
        for (std::size_t k = 0; k < sortOrder_.size(); ++k) newIndex[sortOrder_[k]] = k;
        for (auto& load : loads_) load->renumber(newIndex);
    }
    reindex();
}

void MpmSolver::computeWeights()
{
    auto timer = timers_.time("shapeFunctions");
    const Particles& p = particles_;
    const auto n = static_cast<long>(p.size());
    // The lowest-numbered particle outside the grid, for a stable message.
    const long first = parallelFirst(n, [&](long q) {
        return !grid_.contains(p.x[q]) || !std::isfinite(p.x[q].x()) || !std::isfinite(p.x[q].y());
    });
    if (first < n) {
        const auto q = static_cast<std::size_t>(first);
        std::ostringstream msg;
        msg << "particle " << p.id[q] << " (body " << p.body[q] << ", material "
            << materials_[p.material[q]]->name() << ") at (" << p.x[q].x() << " "
            << p.x[q].y() << ") is outside the grid [" << grid_.origin().transpose()
            << "] - [" << grid_.upper().transpose() << "]";
        throw RunError(msg.str());
    }
    shape_->evaluate(grid_, p, weights_);
    strips_.assign(grid_, p);
    if (cellMean_) cellMean_->assign(grid_, p, [&](std::size_t q) { return driverOf(q) != nullptr; });
}

void MpmSolver::particlesToGrid()
{
    auto timer = timers_.time("particlesToGrid");
    const bool driven = drivesRigidNodes();
    if (driven) rigidNodes_.reset(grid_.active);
    if (contact_) contact_->reset(grid_.active);
    grid_.resetFields();
    const Particles& p = particles_;
    const int stride = weights_.stride;
    strips_.forEach([&](std::size_t q) {
        const std::size_t k0 = q * stride;
        BodyField* body = contact_ ? &contact_->field(p.body[q]) : nullptr;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            const double N = weights_.N[k0 + a];
            if (n < 0) continue;
            grid_.markActive(n);  // also at N = 0: its gradient may still carry force
            const Vector2 v = carriedVelocity(q, n, p.x[q]);  // APIC: v_p + C_p (x_i - x_p)
            if (body) {  // the body's own field, from its particles only (seed G.4 step 1)
                body->mass[n] += N * p.m[q];
                body->momentum[n] += (N * p.m[q]) * v;
                continue;
            }
            if (driven && rigid_[p.body[q]]) rigidNodes_.add(n, p.body[q], N, N * p.m[q], v);
            grid_.mass[n] += N * p.m[q];             // lumped mass, row sums of eq. 2.3.7
            grid_.momentum[n] += (N * p.m[q]) * v;  // eq. 2.4.1
        }
    });
    grid_.collectActive();
    if (contact_)  // the system (centre-of-mass) field is the sum of the bodies' (F.8.6)
        grid_.forEachActiveNode([&](int n) {
            for (int b = 0; b < contact_->nBodies(); ++b) {
                const BodyField& f = contact_->field(b);
                grid_.mass[n] += f.mass[n];
                grid_.momentum[n] += f.momentum[n];
            }
        });
    // No small-mass cut-off: p_i/m_i is a weighted mean of particle velocities, exact for
    // any m_i > 0; zeroing light nodes would put spurious strain into a rigid translation.
    grid_.forEachActiveNode([&](int n) {
        grid_.velocity[n] = grid_.mass[n] > 0.0 ? Vector2(grid_.momentum[n] / grid_.mass[n]) : Vector2::Zero();
    });
    if (driven) rigidNodes_.constrain(grid_, rigid_, time_);
    applyBoundaries(grid_.velocity);
    if (contact_) bodyVelocities(time_);
    reach(StepPoint::afterParticlesToGrid, 0.0);
}

void MpmSolver::bodyVelocities(double t)
{
    for (int b = 0; b < contact_->nBodies(); ++b) {
        BodyField& f = contact_->field(b);
        const RigidBodyDriver* driver = rigid_.empty() ? nullptr : rigid_[b].get();
        if (driver) {  // drivers cache their motion: serial
            for (int n : grid_.active)
                if (f.mass[n] > 0.0) f.velocity[n] = driver->velocity(t, grid_.nodePosition(n));
            continue;
        }
        grid_.forEachActiveNode([&](int n) {
            if (f.mass[n] > 0.0) f.velocity[n] = f.momentum[n] / f.mass[n];
        });
        applyBoundaries(f.velocity);
    }
}

void MpmSolver::useContact(std::unique_ptr<ContactPass> pass)
{
    // Without a pass (one body, noSlip) no per-body array exists.
    if (!pass) return;
    contact_ = std::move(pass);
    allocateExchange();
}

void MpmSolver::allocateExchange()
{
    const auto nodes = static_cast<std::size_t>(grid_.nNodes());
    rigidNodes_.allocate(drivesRigidNodes() ? nodes : 0);
    grid_.fContact.assign(!rigid_.empty() || contact_ ? nodes : 0, Vector2::Zero());
    rigidLoads_.assign(contact_ ? static_cast<std::size_t>(contact_->nBodies()) : rigid_.size(), RigidBodyLoad{});
}

void MpmSolver::setRigidBodies(std::vector<std::unique_ptr<RigidBodyDriver>> drivers)
{
    // Keep the table only when some body is rigid: otherwise no rigid pass runs at all.
    const bool anyRigid = std::any_of(drivers.begin(), drivers.end(), [](const auto& d) { return d != nullptr; });
    rigid_ = anyRigid ? std::move(drivers) : std::vector<std::unique_ptr<RigidBodyDriver>>{};
    allocateExchange();
    if (anyRigid) {
        // Mass properties per body (particle domains as rectangles for the inertia).
        std::vector<RigidBodyInfo> info(rigid_.size());
        for (std::size_t q = 0; q < particles_.size(); ++q) {
            auto& b = info[particles_.body[q]];
            b.mass += particles_.m[q];
            b.centroid += particles_.m[q] * particles_.x[q];
            b.velocity += particles_.m[q] * particles_.v[q];
        }
        for (auto& b : info) {
            if (b.mass > 0) b.centroid /= b.mass;
            if (b.mass > 0) b.velocity /= b.mass;
            b.gravity = gravity_;
        }
        for (std::size_t q = 0; q < particles_.size(); ++q) {
            auto& b = info[particles_.body[q]];
            const Vector2& a = particles_.halfSize[q];
            b.inertia += particles_.m[q] * ((particles_.x[q] - b.centroid).squaredNorm() + a.squaredNorm() / 3.0);
        }
        for (std::size_t b = 0; b < rigid_.size(); ++b)
            if (rigid_[b]) rigid_[b]->attach(info[b]);
    }
    markDeformingMaterials();
    reindex();
}

void MpmSolver::markDeformingMaterials()
{
    materialDeforms_.assign(materials_.size(), 0);
    bool any = false;
    for (std::size_t q = 0; q < particles_.size(); ++q)
        if (!driverOf(q)) {
            const int m = particles_.material[q];
            if (m >= 0 && m < static_cast<int>(materials_.size())) materialDeforms_[m] = any = true;
        }
    // No deformable particle yet (a fill whose layers all sleep): every material counts, so
    // the time step stays finite and on the safe side.
    if (!any) materialDeforms_.assign(materials_.size(), 1);
}

void MpmSolver::useLoads(std::vector<std::unique_ptr<ParticleLoad>> loads,
                         const std::vector<std::string>& bodyNames)
{
    loads_ = std::move(loads);
    for (auto& load : loads_) load->initialise(particles_, grid_, bodyNames);
    particleForce_.assign(loads_.empty() ? 0 : particles_.size(), Vector2::Zero());
}

void MpmSolver::computeForces()
{
    auto timer = timers_.time("forces");
    const Particles& p = particles_;
    const int stride = weights_.stride;
    if (!loads_.empty()) {
        std::fill(particleForce_.begin(), particleForce_.end(), Vector2::Zero());
        for (const auto& load : loads_) load->addForces(time_, p, particleForce_);
    }
    if (cellMean_)
        cellMean_->average(p, [&](std::size_t q) { return 0.5 * (p.sigma[q][XX] + p.sigma[q][YY]); }, cellMeanValue_);
    strips_.forEach([&](std::size_t q) {
        // A rigid body carries no stress: its nodes are driven instead.
        SymTensor s = driverOf(q) ? SymTensor::Zero() : p.sigma[q];
        if (cellMean_) {  // the cell's mean in-plane pressure in place of the particle's own
            const double shift = cellMeanValue_[q] - 0.5 * (s[XX] + s[YY]);
            s[XX] += shift;
            s[YY] += shift;
        }
        const std::size_t k0 = q * stride;
        BodyField* body = contact_ ? &contact_->field(p.body[q]) : nullptr;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n < 0) continue;
            const Vector2& dN = weights_.dN[k0 + a];
            // eq. 2.3.8: F_int = -sum_p V_p B_p^T sigma_p
            const Vector2 fInt = -p.V[q] * Vector2(s[XX] * dN.x() + s[XY] * dN.y(), s[XY] * dN.x() + s[YY] * dN.y());
            Vector2 fExt = (weights_.N[k0 + a] * p.m[q]) * gravity_;  // eq. 2.3.9
            if (!loads_.empty()) fExt += weights_.N[k0 + a] * particleForce_[q];  // traction term
            grid_.fInt[n] += fInt;
            grid_.fExt[n] += fExt;
            // With a contact pass the same terms go to the body's own field too.
            if (body) body->force[n] += fInt + fExt;
        }
    });
    reach(StepPoint::afterForces, 0.0);
}

void MpmSolver::updateGrid(double dt)
{
    reach(StepPoint::beforeGridUpdate, dt);
    if (contact_) updateBodyFields(dt);
    else updateSingleField(dt);
    reach(StepPoint::afterGridUpdate, dt);
}

void MpmSolver::updateSingleField(double dt)
{
    auto timer = timers_.time("gridUpdate");
    grid_.forEachActiveNode([&](int n) {
        Vector2 F = grid_.fInt[n] + grid_.fExt[n];
        if (damping_ > 0) {
            // eq. 3.3.5: F_damp = -alpha |F_ext + F_int| sign(v_n), per component.
            for (int d = 0; d < 2; ++d) {
                const double v = grid_.velocity[n][d];
                const double sign = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
                F[d] -= damping_ * std::abs(F[d]) * sign;
            }
        }
        // Nodes far lighter than any particle (a particle just touching the cell) would
        // get a huge F/m: USL then feeds it into the strain (the small-mass instability).
        grid_.accel[n] = grid_.mass[n] > minNodalMass_ ? Vector2(F / grid_.mass[n])
                                                       : Vector2::Zero();  // eq. 2.4.2
    });
    // Rigid nodes: the acceleration that brings them to the body's velocity.
    if (!rigid_.empty()) rigidNodes_.update(grid_, rigid_, time_ + dt, dt, gravity_, minNodalMass_, rigidLoads_);
    grid_.forEachActiveNode([&](int n) {
        grid_.velocity[n] += dt * grid_.accel[n];  // eq. 2.4.3
    });
    for (int s = 0; s < 4; ++s) boundaries_[s]->constrainUpdate(grid_.velocity, grid_.accel, dt, sideNodes_[s]);
}

void MpmSolver::updateBodyFields(double dt)
{
    const int nBodies = contact_->nBodies();
    const auto isRigid = [&](int b) { return !rigid_.empty() && rigid_[b] != nullptr; };
    const auto constrainBodies = [&] {
        for (int b = 0; b < nBodies; ++b)
            if (!isRigid(b))
                for (int s = 0; s < 4; ++s)
                    boundaries_[s]->constrainUpdate(contact_->field(b).velocity, contact_->field(b).accel, dt,
                                                    sideNodes_[s]);
    };
    {
        auto timer = timers_.time("gridUpdate");
        for (int b = 0; b < nBodies; ++b) {
            BodyField& f = contact_->field(b);
            if (isRigid(b)) {  // a rigid body's field is its driver's velocity (seed A14)
                for (int n : grid_.active) {  // drivers cache their motion: serial
                    if (!(f.mass[n] > 0.0)) continue;
                    const Vector2 vNew = rigid_[b]->velocity(time_ + dt, grid_.nodePosition(n));
                    f.accel[n] = (vNew - f.velocity[n]) / dt;
                    f.velocity[n] = vNew;
                }
                continue;
            }
            grid_.forEachActiveNode([&](int n) {
                if (!(f.mass[n] > 0.0)) return;
                Vector2 F = f.force[n];
                // eq. 3.3.5 on the body's own field. Not at a node shared with another body:
                // there the contact takes the unbalanced force, and a damping force would only
                // come back as a false contact load.
                if (damping_ > 0 && !contact_->shared(n)) {
                    for (int d = 0; d < 2; ++d) {
                        const double v = f.velocity[n][d];
                        F[d] -= damping_ * std::abs(F[d]) * (v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0));
                    }
                }
                f.accel[n] = f.mass[n] > minNodalMass_ ? Vector2(F / f.mass[n]) : Vector2::Zero();  // eq. 2.4.2
                f.velocity[n] += dt * f.accel[n];                                                // eq. 2.4.3
            });
        }
        constrainBodies();
    }
    {
        auto timer = timers_.time("contact");  // seed G.4 steps 2 and 4
        contactNodes_ = contact_->correct(grid_, particles_, rigid_, time_ + dt, dt, rigidLoads_);
    }
    auto timer = timers_.time("gridUpdate");
    constrainBodies();
    // The centre-of-mass field, for the grid output and function objects.
    grid_.forEachActiveNode([&](int n) {
        if (!(grid_.mass[n] > 0.0)) return;
        Vector2 momentum = Vector2::Zero(), rate = Vector2::Zero();
        for (int b = 0; b < nBodies; ++b) {
            const BodyField& f = contact_->field(b);
            momentum += f.mass[n] * f.velocity[n];
            rate += f.mass[n] * f.accel[n];
        }
        grid_.velocity[n] = momentum / grid_.mass[n];
        grid_.accel[n] = rate / grid_.mass[n];
    });
}

void MpmSolver::updateStress(double dt)
{
    Particles& p = particles_;
    const auto nParticles = static_cast<long>(p.size());
    {
        auto timer = timers_.time("strain");
        const int stride = weights_.stride;
        // Velocity gradient L_ab = sum_i v_i,a dN_i/dx_b (B v of eq. 2.4.5, plus spin).
        const auto velocityGradient = [&](std::size_t q) {
            Eigen::Matrix2d L = Eigen::Matrix2d::Zero();
            if (driverOf(q)) return L;  // rigid: no strain, no spin, no volume change
            const std::size_t k0 = q * stride;
            // With a contact pass each body deforms with its own velocity field.
            const std::vector<Vector2>& velocity = contact_ ? contact_->field(p.body[q]).velocity : grid_.velocity;
            for (int a = 0; a < stride; ++a) {
                const int n = weights_.node[k0 + a];
                if (n < 0) continue;
                L.noalias() += velocity[n] * weights_.dN[k0 + a].transpose();
            }
            return L;
        };
        const auto strainIncrement = [&](std::size_t q, const Eigen::Matrix2d& L) {
            SymTensor& de = p.dEps[q];
            de[XX] = dt * L(0, 0);
            de[YY] = dt * L(1, 1);
            de[ZZ] = 0.0;  // plane strain
            de[XY] = 0.5 * dt * (L(0, 1) + L(1, 0));
            p.dOmega[q] = 0.5 * dt * (L(0, 1) - L(1, 0));
            p.eps[q] += de;
            // Volume follows the deformation: V_{t+1} = det(I + dt L) V_t.
            p.V[q] *= (1.0 + dt * L(0, 0)) * (1.0 + dt * L(1, 1)) - dt * dt * L(0, 1) * L(1, 0);
            // Stress work by the trapezoidal rule (first half): an energy measure valid for every material.
            p.work[q] += 0.5 * p.V[q] * contract(p.sigma[q], de);
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
                Eigen::Matrix2d& L = velocityGradient_[q];
                L.diagonal().array() += 0.5 * (cellMeanValue_[q] - L.trace());
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
    reach(StepPoint::afterStressUpdate, dt);
}

void MpmSolver::gridToParticles(double dt)
{
    const int order = transfer_->filterOrder();
    if (order >= 1) filterVelocity(dt, order);
    auto timer = timers_.time("gridToParticles");
    Particles& p = particles_;
    const int stride = weights_.stride;
    const auto nParticles = static_cast<long>(p.size());
    const double flip = transfer_->flipShare(dt);
    const bool affine = p.carries(FieldGroup::affine);
    const LoopReport report = parallelForChecked(nParticles, [&](long q) {
        if (driverOf(q)) return LoopMark::none;  // moved below
        Vector2 vNew = Vector2::Zero(), a = Vector2::Zero(), vStar = Vector2::Zero();
        const std::size_t k0 = q * stride;
        // With a contact pass each body moves with its own corrected field (seed G.4 steps 3-4).
        const BodyField* body = contact_ ? &contact_->field(p.body[q]) : nullptr;
        const std::vector<Vector2>& velocity = body ? body->velocity : grid_.velocity;
        const std::vector<Vector2>& accel = body ? body->accel : grid_.accel;
        const std::vector<Vector2>* star = order >= 1 ? &filtered_[body ? p.body[q] : 0] : nullptr;
        for (int k = 0; k < stride; ++k) {
            const int n = weights_.node[k0 + k];
            if (n < 0) continue;
            const double N = weights_.N[k0 + k];
            vNew += N * velocity[n];
            a += N * accel[n];
            if (star) vStar += N * (*star)[n];
        }
        if (affine) formAffine(static_cast<std::size_t>(q), velocity, p.x[q]);
        p.x[q] += dt * vNew;  // eq. 2.4.7
        if (star) p.v[q] = vStar + dt * a;  // XPIC: the filtered v^t plus the increment
        // eq. 2.4.8 (FLIP), blended with PIC when the FLIP share is below 1: a particle's own
        // velocity beyond what its nodes carry (the FLIP null space, e.g. at a wall that stops
        // its nodes) then decays instead of persisting. PIC and APIC: share 0.
        else p.v[q] = flip * (p.v[q] + dt * a) + (1.0 - flip) * vNew;
        const bool failed = !std::isfinite(p.v[q].x() + p.v[q].y());
        const bool returned = !grid_.contains(p.x[q]) && keepInsideWalls(static_cast<std::size_t>(q));
        return failed ? LoopMark::failure : (returned ? LoopMark::noted : LoopMark::none);
    });
    wallReturns_ += static_cast<std::size_t>(report.notes);
    const long firstBad = report.firstFailure;
    for (std::size_t q : rigidParticles_) {  // drivers cache their motion: serial
        const RigidBodyDriver* body = driverOf(q);
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

void MpmSolver::advanceRigidBodies(double dt)
{
    for (std::size_t b = 0; b < rigid_.size(); ++b)
        if (rigid_[b]) rigid_[b]->advance(time_, dt, rigidLoads_[b]);
}

void MpmSolver::remapVelocity(double dt)
{
    auto timer = timers_.time("particlesToGrid");
    const Particles& p = particles_;
    const int stride = weights_.stride;
    grid_.forEachActiveNode([&](int n) {
        grid_.momentum[n].setZero();
        if (contact_)
            for (int b = 0; b < contact_->nBodies(); ++b) contact_->field(b).momentum[n].setZero();
    });
    strips_.forEach([&](std::size_t q) {
        const std::size_t k0 = q * stride;
        BodyField* body = contact_ ? &contact_->field(p.body[q]) : nullptr;
        // APIC: C_p about the position the weights were taken at (x_p^t = x_p^{t+1} - dt v_p,
        // v_p being the nodal velocity the particle moved with).
        const Vector2 xp = p.carries(FieldGroup::affine) ? Vector2(p.x[q] - dt * p.v[q]) : p.x[q];
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n < 0) continue;
            const Vector2 momentum = (weights_.N[k0 + a] * p.m[q]) * carriedVelocity(q, n, xp);
            grid_.momentum[n] += momentum;
            if (body) body->momentum[n] += momentum;
        }
    });
    grid_.forEachActiveNode([&](int n) {
        grid_.velocity[n] = grid_.mass[n] > 0.0 ? Vector2(grid_.momentum[n] / grid_.mass[n]) : Vector2::Zero();
    });
    if (drivesRigidNodes()) rigidNodes_.constrain(grid_, rigid_, time_ + dt);
    applyBoundaries(grid_.velocity);
    if (contact_) {
        bodyVelocities(time_ + dt);
        contact_->correctRemapped(grid_, rigid_, time_ + dt);
    }
    if (p.carries(FieldGroup::affine)) {
        // APIC: C_p again, from the remapped nodal velocity: a mass-weighted mean of the
        // particles' motion, where v^{t+1} of a node that a particle barely touches holds
        // dt F/m of a tiny mass (the small-mass instability, Sulsky et al. 1995).
        const auto nParticles = static_cast<long>(p.size());
        parallelFor(nParticles, [&](long q) {
            if (driverOf(q)) return;
            const std::vector<Vector2>& velocity = contact_ ? contact_->field(p.body[q]).velocity : grid_.velocity;
            formAffine(static_cast<std::size_t>(q), velocity, p.x[q] - dt * p.v[q]);
        });
    }
    reach(StepPoint::afterRemap, dt);
}

double MpmSolver::maxParticleSpeed() const
{
    return parallelMax(static_cast<long>(particles_.size()), [&](long q) { return particles_.v[q].norm(); });
}

double MpmSolver::criticalTimeStep() const
{
    const double dt = grid_.minCellSize() / (maxWaveSpeed() + maxParticleSpeed());
    return rotation_ ? std::min(dt, rotationalTimeStep()) : dt;
}

double MpmSolver::maxWaveSpeed() const
{
    double c = 0;
    for (std::size_t m = 0; m < materials_.size(); ++m)
        if (materialDeforms_[m]) c = std::max(c, materials_[m]->waveSpeed());
    return c;
}

double MpmSolver::bytesPerParticle() const
{
    if (particles_.size() == 0) return 0.0;
    const std::size_t weights = weights_.node.capacity() * sizeof(int) + weights_.N.capacity() * sizeof(double) +
                                weights_.dN.capacity() * sizeof(Vector2);
    const std::size_t loads = particleForce_.capacity() * sizeof(Vector2);
    const std::size_t cellMeans = cellMean_ ? cellMean_->particleBytes() + cellMeanValue_.capacity() * sizeof(double) +
                                                  velocityGradient_.capacity() * sizeof(Eigen::Matrix2d)
                                            : 0;
    return double(particles_.bytes() + weights + loads + cellMeans) / double(particles_.size());
}

bool MpmSolver::leftThroughOpening(const Vector2& x) const
{
    const Vector2 low = grid_.origin(), high = grid_.upper();
    // The cell a particle leaves through moves freely where one of its nodes on the side is
    // open: the stretch of the opening widens by a cell on each side.
    const auto open = [&](GridSide side) {
        const BoundaryCondition& bc = *boundaries_[static_cast<int>(side)];
        const double s = bc.along(x);
        const double h = side == GridSide::left || side == GridSide::right ? grid_.cellSize().y() : grid_.cellSize().x();
        return bc.isOpen(s) || bc.isOpen(s - h) || bc.isOpen(s + h);
    };
    return (x.x() < low.x() && open(GridSide::left)) || (x.x() > high.x() && open(GridSide::right)) ||
           (x.y() < low.y() && open(GridSide::bottom)) || (x.y() > high.y() && open(GridSide::top));
}

bool MpmSolver::keepInsideWalls(std::size_t q)
{
    Particles& p = particles_;
    Vector2& x = p.x[q];
    if (!std::isfinite(x.x()) || !std::isfinite(x.y())) return false;
    if (hasOutlet_ && leftThroughOpening(x)) return false;  // removeOutflow takes it
    const Vector2 low = grid_.origin(), high = grid_.upper(), h = grid_.cellSize();
    bool moved = false;
    for (int s = 0; s < 4; ++s) {
        const BoundaryCondition& bc = *boundaries_[s];
        const int axis = s == static_cast<int>(GridSide::left) || s == static_cast<int>(GridSide::right) ? 0 : 1;
        const bool lowSide = s == static_cast<int>(GridSide::left) || s == static_cast<int>(GridSide::bottom);
        const double side = lowSide ? low[axis] : high[axis];
        const double past = lowSide ? side - x[axis] : x[axis] - side;
        // Only a small overshoot through a closed wall: anything larger is left for the
        // stability guard to report, and an open stretch lets the particle go.
        if (!(past > 0.0) || past > 0.5 * h[axis] || !bc.isWall()) continue;
        x[axis] = side;
        if (lowSide ? p.v[q][axis] < 0.0 : p.v[q][axis] > 0.0) p.v[q][axis] = 0.0;
        moved = true;
    }
    return moved;
}

std::size_t MpmSolver::removeOutflow()
{
    if (!hasOutlet_) return 0;
    Particles& p = particles_;
    const auto n = static_cast<long>(p.size());
    const auto leaves = [&](std::size_t q) { return !grid_.contains(p.x[q]) && !driverOf(q) && leftThroughOpening(p.x[q]); };
    const long leaving = parallelCount(n, [&](long q) { return leaves(static_cast<std::size_t>(q)); });
    if (leaving == 0) return 0;
    // Keep the others in their order (blocks stay contiguous); tell the loads.
    std::vector<std::size_t> kept, newIndex(p.size(), ParticleLoad::removedParticle);
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
    for (auto& load : loads_) load->renumber(newIndex);
    if (!particleForce_.empty()) particleForce_.resize(p.size());
    reindex();
    return static_cast<std::size_t>(leaving);
}

} // namespace gpic
