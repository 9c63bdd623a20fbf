#include "case/CaseReader.H"

#include "case/CaseFiles.H"
#include "core/Info.H"
#include "core/Plugins.H"
#include "core/error.H"
#include "dictionary/ExactNumber.H"
#include "io/ParticlesVtk.H"
#include "io/TimeDirectories.H"
#include "parallel/Communicator.H"
#include "planar/CosseratRotation.H"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

namespace {
//- Map the material ids stored in a time directory onto the order of constant/materials.
template <int D> void remapMaterials(Particles<D>& p, const std::vector<std::string>& stored,
                    const std::vector<std::string>& current, const std::string& file)
{
    std::vector<int> map(stored.size(), -1);
    for (std::size_t s = 0; s < stored.size(); ++s) {
        for (std::size_t c = 0; c < current.size(); ++c)
            if (stored[s] == current[c]) map[s] = static_cast<int>(c);
        if (map[s] < 0) {
            std::string valid;
            for (const auto& c : current) valid += (valid.empty() ? "" : ", ") + c;
            throw InputError(file, 0, "material '" + stored[s] +
                                          "' of the particles is not in constant/materials; "
                                          "valid choices: " + valid);
        }
    }
    for (auto& m : p.material) {
        if (m < 0 || m >= static_cast<int>(map.size()))
            throw InputError(file, 0, "particle material id " + std::to_string(m) + " is unknown");
        m = map[m];
    }
}

//- The time directory the run starts from: -time, or controlDict's startFrom.
std::string startTimeName(const std::string& dir, const RunOptions& options, const TimeControl& timeControl)
{
    if (options.startTime) return findTime(dir, *options.startTime);
    if (timeControl.startFrom() == "latestTime") return latestTime(dir);
    if (timeControl.startFrom() == "firstTime") {
        const auto times = listTimeDirectories(dir);
        return times.empty() ? latestTime(dir) /* throws: no time directory */ : times.front().second;
    }
    return findTime(dir, timeControl.startTime());
}

bool hasFile(const std::string& dir, const char* relativePath) { return fs::exists(fs::path(dir) / relativePath); }

//- Could `name` be the directory name picSolver or picInit gives time t (timeName at some
//  number of digits), or does it read back as t?
bool namesTime(const std::string& name, double t)
{
    for (int digits = 1; digits <= 17; ++digits)
        if (timeName(t, digits) == name) return true;
    char* end = nullptr;
    const double named = std::strtod(name.c_str(), &end);
    return *end == '\0' && std::abs(named - t) <= 1e-12 * std::abs(t);
}

//- The start directory's three records of its time agree: the directory name, the particle
//  file's TimeValue (`particleTime`) and uniform/time (`stored`), which every directory but
//  picInit's holds. A state from another time or case, a renamed directory or an edited or
//  lost uniform/ is refused rather than continued from.
void checkStartTime(const std::string& dir, const std::string& startName, double particleTime,
                    const std::optional<StoredTime>& stored)
{
    const fs::path start = fs::path(dir) / startName;
    const std::string particles = (start / "particles.vtp").string();
    if (!stored) {
        // picInit writes the first time directory of a case, without uniform/; picSolver writes
        // uniform/ into every one: a later directory without it has lost it.
        const auto times = listTimeDirectories(dir);
        if (!times.empty() && times.front().second != startName)
            throw InputError((start / "uniform/time").string(), 0,
                             "missing: every time directory picSolver writes has it (the run's time, step and "
                             "state); restart from another time directory, or from the start");
    } else if (stored->value != particleTime) {
        throw InputError(particles, 0, "its time " + exactNumber(particleTime) + " s differs from " + startName +
                                           "/uniform/time's " + exactNumber(stored->value) +
                                           " s: one of them is from another time or case");
    }
    if (!namesTime(startName, particleTime))
        throw InputError(particles, 0, "its time " + exactNumber(particleTime) + " s is not that of its directory " +
                                           startName + ": a renamed or copied time directory");
}
} // namespace

template <int D> void Case<D>::warnUnused() const
{
    controlDict.warnUnused();
    gridDict.warnUnused();
    materialsDict.warnUnused();
    schemes.warnUnused();
}

template <int D> std::unique_ptr<Case<D>> readCase(const RunOptions& options)
{
    auto run = std::make_unique<Case<D>>();
    Case<D>& c = *run;
    const std::string& dir = options.caseDir;
    c.controlDict = readCaseFile(dir, "system/controlDict");
    setQuiet(options.quiet);
    c.name = caseName(dir);
    Plugins::open(c.controlDict, "libs");
    for (const auto& lib : options.libs) Plugins::open(lib);

    Dictionary& controlDict = c.controlDict;
    c.timeControl = std::make_unique<TimeControl>(controlDict);
    c.stability = StabilitySettings::read(controlDict, *c.timeControl);
    if (controlDict.found("stages") && controlDict.found("damping"))
        controlDict.fail("damping", "a run in stages sets the damping per stage: move `damping` into the stages");
    const auto damping = controlDict.getOrDefault<double>("damping", 0.0);
    if (damping < 0 || damping >= 1) controlDict.fail("damping", "damping must lie in [0, 1)");
    c.writeGrid = controlDict.getOrDefault<bool>("writeGrid", false);
    c.progressInterval = controlDict.getOrDefault<double>("progressInterval", 5.0);
    const std::string startName = startTimeName(dir, options, *c.timeControl);

    c.gridDict = readCaseFile(dir, "constant/grid");
    if (const int dimension = caseDimension(c.gridDict); dimension != D)
        c.gridDict.fail("nCells", "constant/grid describes a " + std::to_string(dimension) +
                                      "D scene, read as " + std::to_string(D) + "D");
    SolverInputs<D> in{Grid<D>(c.gridDict)};
    in.boundaries = readBoundaries<D>(c.gridDict);
    c.materialsDict = readCaseFile(dir, "constant/materials");
    in.materials = readMaterials<D>(c.materialsDict);
    const std::vector<std::string> materials = materialNames(in.materials);

    if (hasFile(dir, "system/mpmSchemes")) c.schemes = readCaseFile(dir, "system/mpmSchemes");
    Dictionary& schemes = c.schemes;
    // The defaults a new user gets run long granular flows to their end (doc/stability.md,
    // "Transfers"): MUSL, and FLIP with PIC blended in over flipRelaxationTime 0.02 s.
    c.schemeName = schemes.getOrDefault<std::string>("updateScheme", "MUSL");
    c.shapeName = schemes.getOrDefault<std::string>("shapeFunction", "bilinear");
    const std::string transferName = schemes.getOrDefault<std::string>("transfer", "FLIP");
    // A keyword of another transfer is a mistake, not a default to ignore.
    for (const char* k : {"flipFraction", "flipRelaxationTime"})
        if (schemes.found(k) && transferName != "FLIP")
            schemes.fail(k, std::string(k) + " belongs to transfer FLIP, not " + transferName);
    if (schemes.found("xpicOrder") && transferName != "XPIC")
        schemes.fail("xpicOrder", "xpicOrder belongs to transfer XPIC, not " + transferName);
    // particle: each particle's own dilatation (the seed); cellMean: CellMeanDilatation.H
    in.cellMeanDilatation = schemes.getWordOrDefault("volumetricStrain", {"particle", "cellMean"}, "particle") == "cellMean";
    c.volumetricStrainName = in.cellMeanDilatation ? "cellMean" : "particle";
    c.sortInterval = schemes.getOrDefault<long>("sortInterval", 100);
    if (c.sortInterval < 0) schemes.fail("sortInterval", "sortInterval must be >= 0 (0: never sort)");
    c.scheme = Registry<UpdateScheme>::select(c.schemeName, schemes, schemes, "updateScheme");
    in.remapsVelocity = c.scheme->remapsVelocity();
    in.shape = Registry<ShapeFunction<D>>::select(c.shapeName, schemes, schemes, "shapeFunction");
    if (in.grid.axisymmetric()) {  // what the hoop terms are not yet written for
        if (!in.shape->servesAxisymmetric())
            schemes.fail("shapeFunction", "shapeFunction " + c.shapeName + " is not yet available with geometry "
                                          "axisymmetric (constant/grid); valid choices: bilinear, uGIMP");
    }
    in.transfer = Registry<ParticleTransfer>::select(transferName, schemes, schemes, "transfer");

    std::vector<std::string> storedMaterials, bodyNames;
    readParticles((fs::path(dir) / startName / "particles.vtp").string(), in.particles, c.time, &storedMaterials,
                  &bodyNames, true);
    remapMaterials(in.particles, storedMaterials, materials, startName + "/particles.vtp");
    const auto stored = readStoredTime(dir, startName);
    checkStartTime(dir, startName, c.time, stored);
    if (stored) {
        c.time = stored->value;
        c.step = stored->index;
        in.removedMass = stored->removedMass;
    }
    in.time = c.time;

    // The particles a stage holds back (a restart inside a fill) belong to the scene as well.
    Particles<D> dormant;
    const fs::path dormantFile = fs::path(dir) / startName / "dormant.vtp";
    const Dictionary* stagesDict = controlDict.subDictPtr("stages");
    if (stagesDict && fs::exists(dormantFile)) {
        double t = 0;
        std::vector<std::string> stored;
        readParticles(dormantFile.string(), dormant, t, &stored);
        remapMaterials(dormant, stored, materials, startName + "/dormant.vtp");
    }
    bool polar = false;
    if constexpr (D == 2) {
        in.carryRotation = CosseratRotation::polarScene(dormant, in.materials);
        polar = in.carryRotation || CosseratRotation::polarScene(in.particles, in.materials);
    }
    if (polar && in.grid.axisymmetric())
        for (const auto& m : in.materials)
            if (m->needsRotation())
                c.materialsDict.fail(m->name(), "material '" + m->name() + "' is polar (Cosserat), not yet "
                                                "available with geometry axisymmetric (constant/grid)");

    c.gravity = readGravity<D>(dir);
    in.gravity = c.gravity;
    in.damping = damping;
    in.massScaling = MassScaling::read(controlDict, c.timeControl->courant(), MassScaling());
    const MassScaling massScaling = in.massScaling;  // the stages' default
    if constexpr (D == 2)
        if (polar) in.rotationSides = readRotationSides(c.gridDict, mirrorSides(in.boundaries));
    std::optional<Dictionary> rigidBodiesDict;  // kept for the stages' drivers
    if (hasFile(dir, "constant/rigidBodies")) {
        rigidBodiesDict = readCaseFile(dir, "constant/rigidBodies");
        if constexpr (D == 2)
            if (polar) in.rigidRotation = readRigidRotation(*rigidBodiesDict, bodyNames);
        in.rigidBodies = readRigidBodies<D>(*rigidBodiesDict, bodyNames);
    }
    c.hasLoads = hasFile(dir, "constant/loads");
    if (c.hasLoads) in.loads = readLoads<D>(readCaseFile(dir, "constant/loads"));
    massScaling.refuseLoads(controlDict, c.hasLoads);
    in.bodyNames = bodyNames;
    if (const Communicator* comm = options.communicator) {  // a parallel run: its sums over the ranks
        in.ranks.sum = [comm](std::vector<double>& v) { comm->sumInRankOrder(v); };
        in.ranks.min = [comm](std::vector<double>& v) { comm->min(v); };
        in.ranks.gather = [comm](const std::vector<char>& mine) {
            std::vector<int> peers;
            for (int r = 0; r < comm->size(); ++r)
                if (r != comm->rank()) peers.push_back(r);
            const auto got = comm->exchange(peers, std::vector<std::vector<char>>(peers.size(), mine));
            std::vector<std::vector<char>> all(static_cast<std::size_t>(comm->size()));
            all[static_cast<std::size_t>(comm->rank())] = mine;
            for (std::size_t k = 0; k < peers.size(); ++k) all[static_cast<std::size_t>(peers[k])] = got[k];
            return all;
        };
    }
    if (hasFile(dir, "constant/contactProperties")) {
        const Dictionary contactDict = readCaseFile(dir, "constant/contactProperties");
        ContactScene scene{dir, bodyNames, {}, {}, {}};
        scene.ranks = in.ranks;
        for (int b = 0; b < scene.nBodies(); ++b)
            scene.rigid.push_back(static_cast<std::size_t>(b) < in.rigidBodies.size() && in.rigidBodies[b]);
        for (const auto& side : in.boundaries) scene.mirror.push_back(side->isMirror());
        in.contact = ContactPass<D>::New(contactDict, scene, in.grid);
        contactDict.warnUnused();
    }
    c.solver = std::make_unique<MpmSolver<D>>(std::move(in));
    MpmSolver<D>& solver = *c.solver;

    if (stagesDict) {
        StageSetup<D> setup;
        setup.bodyNames = bodyNames;
        setup.gravity = c.gravity;
        setup.rigidBodies = rigidBodiesDict ? &*rigidBodiesDict : nullptr;
        for (int side = 0; side < Space<D>::nFaces; ++side)
            setup.sideHasOpening[side] = solver.boundary(static_cast<GridSide>(side)).hasOpening();
        setup.cellHeight = solver.grid().cellSize()[D - 1];
        setup.gridMin = solver.grid().origin();
        setup.gridMax = solver.grid().upper();
        setup.massScaling = massScaling;
        setup.courant = c.timeControl->courant();
        setup.hasLoads = c.hasLoads;
        c.stages = std::make_unique<StageSequence<D>>(*stagesDict, std::move(setup), dir);
        if (c.hasLoads && c.stages->changesParticles())
            controlDict.fail("stages", "the loads of constant/loads hold particle indices: with loads no stage may "
                                       "wake, put to sleep, fill or dig particles (give every stage all bodies)");
        const fs::path stageFile = fs::path(dir) / startName / "uniform/stage";
        if (fs::exists(stageFile)) {
            const Dictionary f = Dictionary::readFile(stageFile.string(), startName + "/uniform/stage");
            c.stages->restore(&f, std::move(dormant));
        } else {
            c.stages->restore(nullptr, std::move(dormant));
        }
    }

    c.context = RunContext{dir, startName, bodyNames, materials};
    if (const Dictionary* fns = controlDict.subDictPtr("functions"))
        for (const auto& key : fns->keys()) {
            c.functions.push_back(FunctionObject<D>::New(fns->subDict(key), c.context));
            FunctionObject<D>* f = c.functions.back().get();
            for (const StepPoint point : f->stepPoints())
                solver.addHook(point, [f, point](const MpmSolver<D>& s) { f->at(point, s); });
        }
    // Their running state where picSolver wrote the start directory (not picInit's 0/).
    const fs::path functionState = fs::path(dir) / startName / "uniform/functionObjects";
    if (!c.functions.empty() && fs::exists(functionState)) {
        const Dictionary state = Dictionary::readFile(functionState.string(), startName + "/uniform/functionObjects");
        for (auto& f : c.functions)
            if (state.isDict(f->name())) f->restore(state.subDict(f->name()));
    }

    std::ostringstream why;
    why << "cell size " << solver.stepLength() << " m / (wave speed " << solver.maxWaveSpeed()
        << " m/s + particle speed " << solver.maxParticleSpeed() << " m/s)";
    if (solver.passTimeStep() < 1e300)
        why << ", or the " << solver.passTimeStepName() << "'s step " << solver.passTimeStep() << " s";
    c.timeControl->checkStable(solver.criticalTimeStep(), why.str());
    return run;
}

template struct Case<2>;
#if GPIC_WITH_3D
template struct Case<3>;
#endif
template std::unique_ptr<Case<2>> readCase<2>(const RunOptions&);
#if GPIC_WITH_3D
template std::unique_ptr<Case<3>> readCase<3>(const RunOptions&);
#endif

} // namespace gpic
