#include "run/StabilityGuard.H"

#include "engine/MpmSolver.H"
#include "io/ParticlesVtk.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>

namespace gpic {

namespace {
template <class Vector> std::string str(const Vector& v)
{
    std::ostringstream os;
    os << "(" << v.x();
    for (int a = 1; a < Vector::SizeAtCompileTime; ++a) os << " " << v[a];
    os << ")";
    return os.str();
}

template <class Vector> bool finite(const Vector& v) { return v.allFinite(); }

//- Fewer particles (or nodes) than this are checked on one thread.
constexpr long long parallelFrom = 20000;
} // namespace

template <int D>
StabilityGuard<D>::StabilityGuard(const StabilitySettings& settings, const MpmSolver<D>& solver,
                               std::vector<std::string> bodyNames, const Vector& gravity, bool hasLoads,
                               std::string snapshotFile)
    : solver_(solver), bodyNames_(std::move(bodyNames)), gravity_(gravity), hasLoads_(hasLoads),
      snapshotInterval_(settings.snapshotInterval), maxEnergyGain_(settings.maxEnergyGain),
      adjustTimeStep_(settings.adjustTimeStep), courant_(settings.courant), fixedDeltaT_(settings.fixedDeltaT),
      snapshotFile_(std::move(snapshotFile))
{
    int bodies = static_cast<int>(bodyNames_.size());
    for (int b : solver_.particles().body) bodies = std::max(bodies, b + 1);
    rigid_.assign(static_cast<std::size_t>(bodies), 0);
    for (std::size_t b = 0; b < rigid_.size(); ++b) {
        rigid_[b] = solver_.rigidBody(static_cast<int>(b)) != nullptr;
        anyRigid_ = anyRigid_ || rigid_[b];
    }
}

template <int D>
bool StabilityGuard<D>::isRigid(std::size_t q) const
{
    const int b = solver_.particles().body[q];
    return anyRigid_ && b >= 0 && b < static_cast<int>(rigid_.size()) && rigid_[b];
}

template <int D>
typename StabilityGuard<D>::Survey StabilityGuard<D>::survey() const
{
    const Particles<D>& p = solver_.particles();
    const std::size_t n = p.size();
    const Vector lo = solver_.grid().origin(), hi = solver_.grid().upper();
    const Vector g = gravity_;
    // Rigid particles (driven) carry no energy of the material.
    const char* rigidBody = anyRigid_ ? rigid_.data() : nullptr;
    const int bodies = static_cast<int>(rigid_.size());
    std::size_t invalid = n, outside = n;
    double kinetic = 0, work = 0, gravity = 0, speed2 = 0;
    const bool affine = p.carries(FieldGroup::affine);
    // With mass scaling the energy of the scaled inertia: the account of the system stepped.
    const std::vector<double>& scale = solver_.massScales();
    const long long count = static_cast<long long>(n);
    // Threads only where they pay: a parallel region costs microseconds.
#pragma omp parallel for if (count > parallelFrom) schedule(static) reduction(min : invalid, outside) \
    reduction(+ : kinetic, work, gravity) reduction(max : speed2)
    for (long long i = 0; i < count; ++i) {
        const auto q = static_cast<std::size_t>(i);
        const Vector& x = p.x[q];
        const Vector& v = p.v[q];
        // One sum is finite only when every term is.
        const double all = x.sum() + v.sum() + p.sigma[q].sum() + p.V[q];
        if (!std::isfinite(all) || !(p.V[q] > 0.0)) invalid = std::min(invalid, q);
        // The test of Grid::contains, so that the guard fails where computeWeights would. The
        // solver has removed the particles that left through an outlet by now.
        if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) outside = std::min(outside, q);
        const double v2 = v.squaredNorm();
        speed2 = std::max(speed2, v2);
        if (!rigidBody || p.body[q] >= bodies || !rigidBody[p.body[q]]) {
            const double s = inertiaScale(scale, p, q, false);
            kinetic += 0.5 * s * p.m[q] * v2;
            if (affine) kinetic += s * p.affineEnergy[q];  // APIC: the part C_p carries
            work += p.work[q];
            gravity += p.m[q] * g.dot(x);  // differences only: the work of gravity
        }
    }
    Survey s;
    s.invalid = invalid;
    s.outside = outside;
    s.kinetic = kinetic;
    s.work = work;
    s.gravity = gravity;
    s.speed2 = speed2;
    s.count = static_cast<double>(n);
    if (solver_.ranks().parallel()) {  // every rank's: particles changing ranks carry no energy
        std::vector<double> sums{s.kinetic, s.work, s.gravity, s.count};
        solver_.sumOverRanks(sums);
        s.kinetic = sums[0], s.work = sums[1], s.gravity = sums[2], s.count = sums[3];
    }
    return s;
}

template <int D>
double StabilityGuard<D>::loadWork(double dt) const
{
    if (!hasLoads_) return 0.0;
    // The loads are the external nodal force less the weight m_i g; their power on the nodal
    // velocity at mid-step, v_i^{t+1} - dt a_i / 2.
    const Grid<D>& grid = solver_.grid();
    const Vector g = gravity_;
    const long long count = static_cast<long long>(grid.active.size());
    double w = 0;
#pragma omp parallel for if (count > parallelFrom) schedule(static) reduction(+ : w)
    for (long long k = 0; k < count; ++k) {
        const auto n = static_cast<std::size_t>(grid.active[static_cast<std::size_t>(k)]);
        if (!solver_.countsNode(static_cast<int>(n))) continue;  // a parallel run: each node once
        const Vector load = grid.fExt[n] - grid.mass[n] * g;
        w += load.dot(grid.velocity[n] - 0.5 * dt * grid.accel[n]);
    }
    return dt * solver_.ranks().total(w);
}

template <int D>
double StabilityGuard<D>::rigidWork(double t, double dt) const
{
    if (!anyRigid_) return 0.0;
    const auto& loads = solver_.rigidBodyLoads();
    double w = 0;
    const double tMid = t - 0.5 * dt;
    for (std::size_t b = 0; b < rigid_.size() && b < loads.size(); ++b) {
        const RigidBodyDriver<D>* driver = solver_.rigidBody(static_cast<int>(b));
        if (rigid_[b] && driver) w += powerOnMaterial(*driver, loads[b], tMid);
    }
    return dt * w;
}

template <int D>
void StabilityGuard<D>::start(double t, long step, const std::string& onDisk)
{
    const Survey s = survey();
    kinetic0_ = lastKinetic_ = s.kinetic;
    work0_ = s.work;
    workDone_ = 0;
    checks_ = 0;
    gravity0_ = gravityPrevious_ = s.gravity;
    externalWork_ = 0;
    createdBefore_ = created_ = 0;
    particleCount_ = s.count;
    // Elastic energy held at the start (an initial or restarted stress): sum V |sigma|^2 /
    // (2 rho c^2), rho c^2 the P-wave modulus; a scale, not an exact value.
    const Particles<D>& p = solver_.particles();
    std::vector<double> compliance;
    for (const auto& m : solver_.materials()) {
        const double c = m->waveSpeed();
        compliance.push_back(c > 0 && m->rho() > 0 ? 1.0 / (2.0 * m->rho() * c * c) : 0.0);
    }
    const double cMax = solver_.ranks().largest(solver_.maxWaveSpeed());  // a parallel run: over every rank
    double elastic = 0, mass = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (isRigid(q)) continue;
        const SymTensor& s2 = p.sigma[q];
        const double norm2 = s2[XX] * s2[XX] + s2[YY] * s2[YY] + s2[ZZ] * s2[ZZ] + 2 * s2[XY] * s2[XY];
        if (std::isfinite(norm2)) elastic += p.V[q] * norm2 * compliance[static_cast<std::size_t>(p.material[q])];
        mass += p.m[q];
    }
    // A floor for a scene that starts at rest, unstressed and weightless: motion of a
    // millionth of the wave speed.
    if (solver_.ranks().parallel()) {
        std::vector<double> sums{elastic, mass};
        solver_.sumOverRanks(sums);
        elastic = sums[0], mass = sums[1];
    }
    const double floor = 0.5 * mass * (1e-6 * cMax) * (1e-6 * cMax);
    budget_ = s.kinetic + elastic + floor;
    // Rigid bodies alone: no material energy to account, only round-off in the bodies' loads.
    energyChecked_ = mass > 0;
    if (onDisk.empty())
        keep(t, step, 0.0);
    else
        stateWritten(onDisk, t, step, 0.0);
}

template <int D>
void StabilityGuard<D>::restartEnergyAccount() { restartPending_ = true; }

template <int D>
Particles<D> GoodState<D>::particles() const
{
    Particles<D> p;
    double t = 0;
    readParticles(file, p, t);
    return p;
}

template <int D>
void StabilityGuard<D>::keep(double t, long step, double dt)
{
    const auto begin = std::chrono::steady_clock::now();
    std::vector<std::string> materialNames;
    for (const auto& m : solver_.materials()) materialNames.push_back(m->name());
    writeParticles(snapshotFile_, solver_.particles(), t, materialNames, bodyNames_);  // atomic: tmp + rename
    lastGood_ = {snapshotFile_, t, step, dt, solver_.removedMass()};
    ++snapshots_;
    snapshotSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

template <int D>
void StabilityGuard<D>::keepIfDue(double t, long step, double dt)
{
    if (step - lastGood_.step >= snapshotInterval_) keep(t, step, dt);
}

template <int D>
void StabilityGuard<D>::stateWritten(const std::string& file, double t, long step, double dt)
{
    lastGood_ = {file, t, step, dt, solver_.removedMass()};
    ++snapshots_;
}

template <int D>
std::optional<StabilityTrip> StabilityGuard<D>::check(double t, long step, double dt)
{
    const Survey s = survey();
    lastKinetic_ = s.kinetic;
    ++checks_;
    const std::size_t n = solver_.particles().size();
    // The limit the next step would meet: exactly MpmSolver::criticalTimeStep().
    const double h = solver_.stepLength(), c = solver_.maxWaveSpeed(), vMax = std::sqrt(s.speed2);
    const double limit = h / (c + vMax);
    const bool aboveLimit = !adjustTimeStep_ && fixedDeltaT_ > limit;
    const auto limitText = [&] {
        std::ostringstream os;
        os << "the fixed deltaT " << fixedDeltaT_ << " s is above the stability limit " << limit << " s = cell " << h
           << " m / (wave speed " << c << " + speed " << vMax << ") m/s; use deltaT <= " << limit
           << " s or adjustTimeStep yes";
        return os.str();
    };
    // A state that fails on its own is named first; a step above the limit is worth a note.
    const auto note = [&] { return aboveLimit ? "; also, " + limitText() : std::string(); };
    if (s.invalid < n) return StabilityTrip{describeInvalid(s.invalid, t, step, dt) + note(), false};
    if (s.outside < n) return StabilityTrip{describeOutside(s.outside, t, step, dt) + note(), false};

    // Energy account.
    if (s.count != particleCount_ || restartPending_) {
        // Particles left or came (outflow, inflow): their energy is no work done. Start the
        // account again from here, keeping what the steps created so far and the budget.
        createdBefore_ = created_;
        kinetic0_ = s.kinetic;
        work0_ = s.work;
        gravity0_ = gravityPrevious_ = s.gravity;
        externalWork_ = 0;
        particleCount_ = s.count;
        restartPending_ = false;
    } else {
        const double external = loadWork(dt) + rigidWork(t, dt);
        externalWork_ += external;
        const double done = std::abs(s.gravity - gravityPrevious_) + std::abs(external);
        budget_ += done;
        workDone_ += done;
        gravityPrevious_ = s.gravity;
    }
    const double created = createdBefore_ + (s.kinetic - kinetic0_) + (s.work - work0_) - (s.gravity - gravity0_) -
                           externalWork_;
    created_ = created;
    const double gain = created / budget_;
    if (energyChecked_) largestGain_ = std::max(largestGain_, gain);
    if (energyChecked_ && !(gain <= maxEnergyGain_)) {
        // Blame the particle with the most kinetic energy.
        const Particles<D>& p = solver_.particles();
        std::size_t worst = 0;
        double most = -1;
        for (std::size_t q = 0; q < n; ++q) {
            const double k = isRigid(q) ? -1.0 : solver_.massScaleOf(q) * p.m[q] * p.v[q].squaredNorm();
            if (k > most) most = k, worst = q;
        }
        std::ostringstream what;
        what << "energy created by the steps: " << created << " J/m, " << gain
             << " times the energy budget " << budget_ << " J/m (maxEnergyGain " << maxEnergyGain_
             << "; kinetic energy " << s.kinetic << " J/m, was " << kinetic0_
             << "), the time step is unstable";
        // A step inside the estimate that still grows energy: either a mode the estimate
        // misses or a growth that is not the step's (doc/stability.md).
        // Within 1 %: the particle's speed, and with it the limit, has moved since the step began.
        const Vector& v = p.v[worst];
        std::string within = finite(v) && dt <= 1.01 * neededStep(worst, v)
                                 ? "; the step met that estimate: run again with a smaller maxCourant (or "
                                   "deltaT); a growth that comes at the same time is not the step's"
                                 : std::string();
        // Under FLIP such a growth can live in a particle's carried velocity alone, which the
        // grid does not show (the polar bucket, doc/stability.md): APIC sets it from the grid.
        if (!within.empty() && solver_.transfer().flipShare(dt) > 0.5)
            within += "; under FLIP it can be a particle's own velocity running away from its grid's: "
                      "try transfer APIC (doc/stability.md)";
        return StabilityTrip{describe(what.str(), worst, t, step, dt) + within + note(), false};
    }

    if (aboveLimit) {
        // Blame the fastest particle: its speed set the limit.
        const Particles<D>& p = solver_.particles();
        std::size_t fastest = 0;
        for (std::size_t q = 0; q < n; ++q)
            if (p.v[q].squaredNorm() == s.speed2) {
                fastest = q;
                break;
            }
        return StabilityTrip{describe(limitText(), fastest, t, step, dt), true};
    }

    return std::nullopt;
}

template <int D>
std::optional<StabilityTrip> StabilityGuard<D>::diagnose(double t, long step, double dt) const
{
    const Survey s = survey();
    const std::size_t n = solver_.particles().size();
    if (s.invalid < n) return StabilityTrip{describeInvalid(s.invalid, t, step, dt), false};
    if (s.outside < n) return StabilityTrip{describeOutside(s.outside, t, step, dt), false};
    return std::nullopt;
}

template <int D>
double StabilityGuard<D>::neededStep(std::size_t q, const Vector& v) const
{
    const Particles<D>& p = solver_.particles();
    const double c = isRigid(q) ? 0.0 : solver_.waveSpeed(static_cast<std::size_t>(p.material[q]));
    return std::min(courant_ * solver_.stepLength() / (c + v.norm()), courant_ * rotationStep(q));
}

template <int D>
double StabilityGuard<D>::rotationStep(std::size_t q) const
{
    return isRigid(q) ? 1e300 : solver_.passTimeStep(static_cast<std::size_t>(solver_.particles().material[q]));
}

template <int D>
std::string StabilityGuard<D>::describe(const std::string& what, std::size_t q, double t, long step, double dt) const
{
    const Particles<D>& p = solver_.particles();
    const int b = p.body[q];
    const std::string body = b >= 0 && b < static_cast<int>(bodyNames_.size()) ? bodyNames_[b] : std::to_string(b);
    const auto& material = *solver_.materials()[static_cast<std::size_t>(p.material[q])];
    // A non-finite velocity says nothing of the speed: use the particle's last good one.
    Vector v = p.v[q];
    std::string speedNote;
    if (!finite(v)) try {
        const Particles<D> good = lastGood_.particles();
        const auto at = std::find(good.id.begin(), good.id.end(), p.id[q]);
        if (at != good.id.end()) {
            v = good.v[static_cast<std::size_t>(at - good.id.begin())];
            speedNote = " at its last good speed";
        }
    } catch (const std::exception&) {
        // The last good state is gone (a time directory renamed since): the diagnosis goes without it.
    }
    const double c = isRigid(q) ? 0.0 : solver_.waveSpeed(static_cast<std::size_t>(p.material[q]));
    std::ostringstream os;
    os << what << " at time " << t << " s (step " << step << "): particle " << p.id[q] << " of body '" << body
       << "' (material '" << material.name() << "') at " << str(p.x[q]) << " m, velocity " << str(p.v[q])
       << " m/s; it would need deltaT <= " << neededStep(q, v) << " s" << speedNote << " (";
    const double rotation = rotationStep(q);
    if (rotation < 1e300) os << "the smaller of ";
    os << "Courant " << courant_ << " x cell " << solver_.stepLength() << " m / (wave speed " << c << " + speed "
       << v.norm() << ") m/s";
    if (rotation < 1e300)
        os << " and the " << solver_.passTimeStepName() << "'s Courant " << courant_ << " x " << rotation << " s";
    os << "), the step was " << dt << " s";
    return os.str();
}

template <int D>
std::string StabilityGuard<D>::describeInvalid(std::size_t first, double t, long step, double dt) const
{
    // Blame the source: a non-finite stress spreads to the velocities and positions of its
    // neighbours within a step, so look for the first of each kind in that order.
    const Particles<D>& p = solver_.particles();
    const std::pair<const char*, std::function<bool(std::size_t)>> kinds[] = {
        {"non-finite stress", [&](std::size_t q) { return !p.sigma[q].allFinite(); }},
        {"non-finite volume", [&](std::size_t q) { return !std::isfinite(p.V[q]); }},
        {"non-finite velocity", [&](std::size_t q) { return !finite(p.v[q]); }},
        {"non-finite position", [&](std::size_t q) { return !finite(p.x[q]); }},
    };
    for (const auto& [what, is] : kinds)
        for (std::size_t q = 0; q < p.size(); ++q)
            if (is(q)) return describe(what, q, t, step, dt);
    std::ostringstream what;
    what << "volume " << p.V[first] << " m^2 <= 0 (the particle turned inside out)";
    return describe(what.str(), first, t, step, dt);
}

template <int D>
std::string StabilityGuard<D>::describeOutside(std::size_t q, double t, long step, double dt) const
{
    const Grid<D>& grid = solver_.grid();
    const Vector& x = solver_.particles().x[q];
    std::string sides;
    const auto add = [&](bool beyond, GridSide side) {
        if (beyond) sides += (sides.empty() ? "" : " and ") + gridSideNames()[static_cast<int>(side)];
    };
    for (int a = 0; a < D; ++a) {
        add(x[a] < grid.origin()[a], static_cast<GridSide>(2 * a));
        add(x[a] > grid.upper()[a], static_cast<GridSide>(2 * a + 1));
    }
    std::ostringstream what;
    what << "particle outside the grid " << str(grid.origin()) << " - " << str(grid.upper()) << ", beyond its "
         << sides << " side, where no outflow removes it";
    return describe(what.str(), q, t, step, dt);
}

template class StabilityGuard<2>;
#if GPIC_WITH_3D
template class StabilityGuard<3>;
#endif
template struct GoodState<2>;
#if GPIC_WITH_3D
template struct GoodState<3>;
#endif

} // namespace gpic
