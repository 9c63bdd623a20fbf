#include "stages/Stage.H"

#include "bodies/RigidBodyDriver.H"
#include "dictionary/Dictionary.H"
#include "engine/MpmSolver.H"
#include "grid/Grid.H"
#include "planar/CosseratRotation.H"
#include "stages/ParticlePool.H"
#include "stages/StageTimeDriver.H"

#include <algorithm>
#include <ostream>

namespace gpic {

namespace {
std::string lastComponent(const std::string& name)
{
    const auto slash = name.rfind('/');
    return slash == std::string::npos ? name : name.substr(slash + 1);
}

std::string listOf(const std::vector<std::string>& names)
{
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}
} // namespace

template <int D>
Stage<D>::Stage(const Dictionary& dict, const StageSetup<D>& setup, double defaultDamping, int endBody)
    : name_(lastComponent(dict.name())),
      type_(dict.get<std::string>("type")),
      file_(dict.fileName()),
      line_(dict.startLine()),
      setup_(setup),
      until_(dict, setup.bodyNames, endBody)
{
    const std::size_t nBodies = setup.bodyNames.size();
    damping_ = dict.found("damping") ? dict.getChecked<double>(
                                           "damping", [](const double& a) { return a >= 0 && a < 1; },
                                           "0 <= damping < 1 (eq. 3.3.5)")
                                     : defaultDamping;
    gravityOn_ = dict.getOrDefault<bool>("gravity", true);
    massScaling_ = MassScaling::read(dict, setup.courant, setup.massScaling);
    if (dict.found("massScaling")) massScaling_.refuseLoads(dict, setup.hasLoads);

    active_.assign(nBodies, dict.found("bodies") ? 0 : 1);
    if (dict.found("bodies")) {
        const auto names = dict.get<std::vector<std::string>>("bodies");
        if (names.empty()) dict.fail("bodies", "a stage needs at least one body; valid choices: " + listOf(setup.bodyNames));
        for (const auto& n : names) active_[static_cast<std::size_t>(bodyId(dict, "bodies", n))] = 1;
    }

    // Drivers: constant/rigidBodies, then the stage's own. Built now, so that a bad driver
    // stops the run before its first step, not when the stage comes.
    drivers_.resize(nBodies);
    rotationFixed_.assign(nBodies, 1);
    const auto addDrivers = [&](const Dictionary& d) {
        for (const auto& key : d.keys()) {
            const int b = bodyId(d, key, key);
            if (!d.isDict(key)) d.fail(key, "'" + key + "' needs a driver sub-dictionary { type ...; }");
            const Dictionary& driver = d.subDict(key);
            drivers_[static_cast<std::size_t>(b)] = RigidBodyDriver<D>::New(driver);
            if (driver.found("rotation"))
                rotationFixed_[static_cast<std::size_t>(b)] = driver.getWord("rotation", {"fixed", "free"}) == "fixed";
        }
    };
    if (setup.rigidBodies) addDrivers(*setup.rigidBodies);
    if (const Dictionary* own = dict.subDictPtr("drivers")) addDrivers(*own);
    rigid_.assign(nBodies, 0);
    for (std::size_t b = 0; b < nBodies; ++b) rigid_[b] = drivers_[b] != nullptr;

    if (const Dictionary* open = dict.subDictPtr("openings"))
        for (const auto& side : open->keys())
            setOpening(*open, side, side, open->getWord(side, {"open", "closed"}) == "open" ? 1 : 0);
}

template <int D>
Stage<D>::~Stage() = default;

template <int D>
int Stage<D>::bodyId(const Dictionary& dict, const std::string& keyword, const std::string& name) const
{
    const auto& names = setup_.bodyNames;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
        dict.fail(keyword, "'" + name + "' is not a body of the particles; valid choices: " + listOf(names));
    return static_cast<int>(it - names.begin());
}

template <int D>
void Stage<D>::setOpening(const Dictionary& dict, const std::string& keyword, const std::string& side, int state)
{
    const auto& sides = gridSideNames();
    const auto it = std::find(sides.begin(), sides.begin() + Space<D>::nFaces, side);
    std::vector<std::string> withOpening;
    for (int s = 0; s < Space<D>::nFaces; ++s)
        if (setup_.sideHasOpening[s]) withOpening.push_back(sides[s]);
    if (it == sides.begin() + Space<D>::nFaces || !setup_.sideHasOpening[it - sides.begin()])
        dict.fail(keyword, "side '" + side + "' has no `opening` in constant/grid; valid choices: " +
                               (withOpening.empty() ? std::string("(none)") : listOf(withOpening)));
    openings_[static_cast<std::size_t>(it - sides.begin())] = state;
}

template <int D>
bool Stage<D>::changesParticles() const
{
    return std::find(active_.begin(), active_.end(), 0) != active_.end();
}

template <int D>
std::string Stage<D>::bodyList() const
{
    std::vector<std::string> names;
    for (std::size_t b = 0; b < active_.size(); ++b)
        if (active_[b]) names.push_back(setup_.bodyNames[b]);
    return listOf(names);
}

template <int D>
void Stage<D>::configure(MpmSolver<D>& solver, double t0)
{
    solver.setDamping(damping_);
    solver.setMassScaling(massScaling_);
    solver.setGravity(gravity());
    for (int s = 0; s < Space<D>::nFaces; ++s) {
        BoundaryCondition<D>& bc = solver.boundary(static_cast<GridSide>(s));
        if (bc.hasOpening()) bc.setOpen(openings_[s] != 0);
    }
    solver.refreshOpenings();
    std::vector<std::unique_ptr<RigidBodyDriver<D>>> drivers(drivers_.size());
    for (std::size_t b = 0; b < drivers_.size(); ++b)
        if (drivers_[b]) drivers[b] = std::make_unique<StageTimeDriver<D>>(std::move(drivers_[b]), t0);
    solver.setRigidBodies(std::move(drivers));
    if constexpr (D == 2)
        if (auto* rotation = solver.template find<CosseratRotation>()) rotation->setRigidFixed(rotationFixed_);
}

template <int D>
StageEvent Stage<D>::begin(MpmSolver<D>& solver, ParticlePool<D>& pool, double t, long step)
{
    pool.exchange(
        solver, [&](const Particles<D>& p, std::size_t q) { return !isActive(p.body[q]); },
        [&](const Particles<D>& p, std::size_t q) { return isActive(p.body[q]) && wakesAtBegin(p, q); });
    configure(solver, t);
    until_.start(solver, t, step);
    return started(solver, pool, t, step);
}

template <int D>
void Stage<D>::resume(MpmSolver<D>& solver, const Dictionary& progress, double stageStart)
{
    configure(solver, stageStart);
    until_.readProgress(progress.subDict("clock"));
    readOwnProgress(progress);
}

template <int D>
StageEvent Stage<D>::afterStep(MpmSolver<D>& solver, ParticlePool<D>&, double t, long step, double dt)
{
    std::string why;
    bool timedOut = false;
    if (!until_.reached(solver, t, step, dt, why, timedOut)) return StageEvent::none;
    return end(why, timedOut);
}

template <int D>
StageEvent Stage<D>::end(const std::string& reason, bool timedOut)
{
    reason_ = reason;
    timedOut_ = timedOut;
    return StageEvent::ended;
}

template <int D>
void Stage<D>::writeProgress(std::ostream& os) const
{
    os << "    clock\n    {\n";
    until_.writeProgress(os, "        ");
    os << "    }\n";
    writeOwnProgress(os);
}

template class Stage<2>;
#if GPIC_WITH_3D
template class Stage<3>;
#endif


} // namespace gpic
