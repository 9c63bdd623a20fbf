#include "solver/Simulation.H"

#include "core/Plugins.H"
#include "core/Info.H"
#include "core/StopSignals.H"
#include "core/Threads.H"
#include "core/error.H"
#include "dictionary/ExactNumber.H"
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "solver/CaseFiles.H"

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

namespace {
//- Peak resident memory of the process (VmHWM) [MiB]; 0 where /proc is not there.
double peakMemoryMiB()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            double kB = 0;
            status >> kB;
            return kB / 1024.0;
        }
        status.ignore(1 << 20, '\n');
    }
    return 0.0;
}

//- Map the material ids stored in a time directory onto the order of constant/materials.
void remapMaterials(Particles& p, const std::vector<std::string>& stored,
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
} // namespace

Simulation::Simulation(const RunOptions& options)
    : options_(options),
      controlDict_(readCaseFile(options.caseDir, "system/controlDict"))
{
    setQuiet(options_.quiet);
    const std::string& dir = options_.caseDir;
    caseName_ = caseName(dir);
    Plugins::open(controlDict_, "libs");
    for (const auto& lib : options_.libs) Plugins::open(lib);

    timeControl_ = std::make_unique<TimeControl>(controlDict_);
    timeDigits_ = timeControl_->timePrecision();
    if (controlDict_.found("stages") && controlDict_.found("damping"))
        controlDict_.fail("damping", "a run in stages sets the damping per stage: move `damping` into the stages");
    const auto damping = controlDict_.getOrDefault<double>("damping", 0.0);
    if (damping < 0 || damping >= 1) controlDict_.fail("damping", "damping must lie in [0, 1)");
    writeGrid_ = controlDict_.getOrDefault<bool>("writeGrid", false);
    progressInterval_ = controlDict_.getOrDefault<double>("progressInterval", 5.0);

    // Start time directory.
    std::string startName;
    if (options_.startTime) startName = findTime(dir, *options_.startTime);
    else if (timeControl_->startFrom() == "latestTime") startName = latestTime(dir);
    else if (timeControl_->startFrom() == "firstTime") {
        const auto times = listTimeDirectories(dir);
        startName = times.empty() ? latestTime(dir) /* throws: no time directory */ : times.front().second;
    }
    else startName = findTime(dir, timeControl_->startTime());

    Dictionary gridDict = readCaseFile(dir, "constant/grid");
    Grid grid(gridDict);
    auto boundaries = readBoundaries(gridDict);
    Dictionary materialsDict = readCaseFile(dir, "constant/materials");
    auto materials = readMaterials(materialsDict);

    Dictionary schemes;
    if (fs::exists(fs::path(dir) / "system/mpmSchemes")) schemes = readCaseFile(dir, "system/mpmSchemes");
    // The defaults a new user gets run long granular flows to their end (doc/stability.md,
    // "Transfers"): MUSL, and FLIP with PIC blended in over flipRelaxationTime 0.02 s.
    const std::string schemeName = schemes.getOrDefault<std::string>("updateScheme", "MUSL");
    const std::string shapeName = schemes.getOrDefault<std::string>("shapeFunction", "bilinear");
    const std::string transferName = schemes.getOrDefault<std::string>("transfer", "FLIP");
    // A keyword of another transfer is a mistake, not a default to ignore.
    for (const char* k : {"flipFraction", "flipRelaxationTime"})
        if (schemes.found(k) && transferName != "FLIP")
            schemes.fail(k, std::string(k) + " belongs to transfer FLIP, not " + transferName);
    if (schemes.found("xpicOrder") && transferName != "XPIC")
        schemes.fail("xpicOrder", "xpicOrder belongs to transfer XPIC, not " + transferName);
    // particle: each particle's own dilatation (the seed); cellMean: CellMeanDilatation.H
    const std::string volumetricStrain = schemes.getWordOrDefault("volumetricStrain", {"particle", "cellMean"}, "particle");
    sortInterval_ = schemes.getOrDefault<long>("sortInterval", 100);
    if (sortInterval_ < 0) schemes.fail("sortInterval", "sortInterval must be >= 0 (0: never sort)");
    scheme_ = Registry<UpdateScheme>::select(schemeName, schemes, schemes, "updateScheme");
    auto shape = Registry<ShapeFunction>::select(shapeName, schemes, schemes, "shapeFunction");
    auto transfer = Registry<ParticleTransfer>::select(transferName, schemes, schemes, "transfer");

    Particles particles;
    std::vector<std::string> storedMaterials, bodyNames;
    const std::string particleFile = (fs::path(dir) / startName / "particles.vtp").string();
    readParticles(particleFile, particles, time_, &storedMaterials, &bodyNames);
    remapMaterials(particles, storedMaterials, materialNames(materials), startName + "/particles.vtp");
    double removedMass = 0;  // through the outlets before this run [kg/m]
    if (const auto stored = readStoredTime(dir, startName)) {
        time_ = stored->value;
        step_ = stored->index;
        removedMass = stored->removedMass;
    }

    // The particles a stage holds back (a restart inside a fill) belong to the scene as well.
    Particles dormant;
    const fs::path dormantFile = fs::path(dir) / startName / "dormant.vtp";
    const bool staged = controlDict_.subDictPtr("stages") != nullptr;
    if (staged && fs::exists(dormantFile)) {
        double t = 0;
        std::vector<std::string> stored;
        readParticles(dormantFile.string(), dormant, t, &stored);
        remapMaterials(dormant, stored, materialNames(materials), startName + "/dormant.vtp");
    }
    bool dormantPolar = false;
    for (int m : dormant.material) dormantPolar = dormantPolar || materials[static_cast<std::size_t>(m)]->needsRotation();

    const std::array<bool, 4> mirror = mirrorSides(boundaries);
    solver_ = std::make_unique<MpmSolver>(std::move(grid), std::move(particles), std::move(materials),
                                          std::move(shape), std::move(boundaries));
    if (dormantPolar) solver_->enableRotation();
    solver_->setGravity(readGravity(dir));
    solver_->setDamping(damping);
    solver_->setTransfer(std::move(transfer));
    solver_->setCellMeanDilatation(volumetricStrain == "cellMean");
    solver_->setTime(time_);
    solver_->setRemovedMass(removedMass);
    if (solver_->hasRotation()) solver_->setRotationSides(readRotationSides(gridDict, mirror));
    std::optional<Dictionary> rigidBodiesDict;  // kept for the stages' drivers
    if (fs::exists(fs::path(dir) / "constant/rigidBodies")) {
        rigidBodiesDict = readCaseFile(dir, "constant/rigidBodies");
        const Dictionary& rigidBodies = *rigidBodiesDict;
        if (solver_->hasRotation()) solver_->setRigidRotation(readRigidRotation(rigidBodies, bodyNames));
        solver_->setRigidBodies(readRigidBodies(rigidBodies, bodyNames));
    }
    hasLoads_ = fs::exists(fs::path(dir) / "constant/loads");
    if (hasLoads_) solver_->setLoads(readLoads(readCaseFile(dir, "constant/loads")), bodyNames);
    if (fs::exists(fs::path(dir) / "constant/contactProperties")) {
        const Dictionary contactDict = readCaseFile(dir, "constant/contactProperties");
        ContactScene scene{dir, bodyNames, {}};
        for (int b = 0; b < scene.nBodies(); ++b) scene.rigid.push_back(solver_->rigidBody(b) != nullptr);
        solver_->setContact(ContactPass::New(contactDict, scene, solver_->grid()));
        contactDict.warnUnused();
    }

    if (const Dictionary* stagesDict = controlDict_.subDictPtr("stages")) {
        StageSetup setup;
        setup.bodyNames = bodyNames;
        setup.gravity = readGravity(dir);
        setup.rigidBodies = rigidBodiesDict ? &*rigidBodiesDict : nullptr;
        for (int side = 0; side < 4; ++side)
            setup.sideHasOpening[side] = solver_->boundary(static_cast<GridSide>(side)).hasOpening();
        setup.cellHeight = solver_->grid().cellSize().y();
        setup.gridMin = solver_->grid().origin();
        setup.gridMax = solver_->grid().upper();
        stages_ = std::make_unique<StageSequence>(*stagesDict, std::move(setup), dir);
        if (hasLoads_ && stages_->changesParticles())
            controlDict_.fail("stages", "the loads of constant/loads hold particle indices: with loads no stage may "
                                        "wake, put to sleep, fill or dig particles (give every stage all bodies)");
        const fs::path stageFile = fs::path(dir) / startName / "uniform/stage";
        if (fs::exists(stageFile)) {
            const Dictionary f = Dictionary::readFile(stageFile.string(), startName + "/uniform/stage");
            stages_->restore(&f, std::move(dormant));
        } else {
            stages_->restore(nullptr, std::move(dormant));
        }
    }

    context_ = RunContext{dir, startName, bodyNames, materialNames(solver_->materials())};
    if (const Dictionary* fns = controlDict_.subDictPtr("functions"))
        for (const auto& key : fns->keys()) {
            functions_.push_back(FunctionObject::New(fns->subDict(key), context_));
            FunctionObject* f = functions_.back().get();
            for (const StepPoint point : f->stepPoints())
                solver_->addHook(point, [f, point](const MpmSolver& s) { f->at(point, s); });
        }
    // Their running state where picSolver wrote the start directory (not picInit's 0/).
    const fs::path functionState = fs::path(dir) / startName / "uniform/functionObjects";
    if (!functions_.empty() && fs::exists(functionState)) {
        const Dictionary state =
            Dictionary::readFile(functionState.string(), startName + "/uniform/functionObjects");
        for (auto& f : functions_)
            if (state.isDict(f->name())) f->restore(state.subDict(f->name()));
    }

    std::ostringstream why;
    why << "cell size " << solver_->grid().minCellSize() << " m / (wave speed " << solver_->maxWaveSpeed()
        << " m/s + particle speed " << solver_->maxParticleSpeed() << " m/s)";
    timeControl_->checkStable(solver_->criticalTimeStep(), why.str());
    guard_ = std::make_unique<StabilityGuard>(controlDict_, *solver_, bodyNames, readGravity(dir), hasLoads_);
    onDisk_ = {time_, step_, startName};

    // Every keyword has been read by now: what is left is a typo or a leftover.
    controlDict_.warnUnused();
    gridDict.warnUnused();
    materialsDict.warnUnused();
    schemes.warnUnused();

    log() << "Case " << caseName_ << ": " << solver_->particles().size() << " particles, "
          << solver_->grid().nx() << " x " << solver_->grid().ny() << " cells, scheme " << schemeName
          << ", shape functions " << shapeName << ", starting at t = " << time_ << " (" << startName
          << ")\n";
    if (const ContactPass* contact = solver_->contact())
        log() << "Contact pass: " << contact->nBodies() << " bodies with their own velocity fields, "
              << contact->summary() << "\n";
}

Simulation::~Simulation() = default;

std::ostream& Simulation::log() const { return info(); }

void Simulation::restartGuard()
{
    auto before = std::move(guard_);
    guard_ = std::make_unique<StabilityGuard>(controlDict_, *solver_, context_.bodyNames, stages_->gravity(), hasLoads_);
    guard_->start(time_, step_);
    if (before) guard_->continueStatistics(*before);
}

void Simulation::writeState(const Particles& particles, double time, long step, double deltaT,
                            double removedMass, const std::string& name)
{
    // The grid and the function objects hold the current step's: written only with it.
    const bool current = &particles == &solver_->particles();
    const bool withGrid = writeGrid_ && current;
    writeTimeDirectoryAtomically(options_.caseDir, name, [&](const std::string& tmp) {
        writeParticles(tmp + "/particles.vtp", particles, time, context_.materialNames, context_.bodyNames);
        if (withGrid) writeGrid(tmp + "/grid.vti", solver_->grid(), time);
        fs::create_directories(tmp + "/uniform");
        std::ofstream t(tmp + "/uniform/time");
        t << "FoamFile { version 2.0; format ascii; class dictionary; object time; }\n"
          << "value   " << exactNumber(time) << ";\nname    \"" << name << "\";\nindex   " << step
          << ";\ndeltaT  " << exactNumber(deltaT) << ";\n";
        if (removedMass > 0) t << "removedMass " << exactNumber(removedMass) << ";  // [kg/m] through the outlets\n";
        if (!t.flush()) throw RunError("cannot write " + tmp + "/uniform/time: " + std::strerror(errno));
        if (current && !functions_.empty()) {
            std::ofstream f(tmp + "/uniform/functionObjects");
            f << "FoamFile { version 2.0; format ascii; class dictionary; object functionObjects; }\n";
            for (const auto& fn : functions_) {
                f << fn->name() << "\n{\n";
                fn->writeState(f);
                f << "}\n";
            }
            if (!f.flush()) throw RunError("cannot write " + tmp + "/uniform/functionObjects: " + std::strerror(errno));
        }
        if (stages_) {  // where the run is in its stages, and the sleeping particles
            stages_->writeStageFile(tmp, name);
            const Particles& dormant = stages_->pool().dormant();
            if (dormant.size() > 0)
                writeParticles(tmp + "/dormant.vtp", dormant, time, context_.materialNames, context_.bodyNames);
        }
    });
}

std::string Simulation::timeDirectoryName(double t)
{
    // A time this run wrote already keeps its name (the same state written again).
    const auto sameTime = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };
    for (const auto& w : written_)
        if (sameTime(w.first, t)) return w.second;
    // A name fits when no other directory of this run has it and it reads back nearer t than
    // the previous write (or the start): 0.15 is not written as "0.2" before 0.2 comes.
    const double previous = written_.empty() ? std::stod(context_.startTimeName) : written_.back().first;
    const auto free = [&](const std::string& n) {
        if (n == context_.startTimeName) return false;
        for (const auto& w : written_)
            if (w.second == n) return false;
        return true;
    };
    // Name n reads back as time `of`, nearer it than half the spacing to `other`.
    const auto readsBack = [](const std::string& n, double of, double other) {
        return std::abs(std::stod(n) - of) <= 0.5 * std::abs(of - other);
    };
    const auto fits = [&](const std::string& n) { return free(n) && readsBack(n, t, previous); };
    std::string name = timeName(t, timeDigits_);
    if (fits(name)) return name;
    const std::string unfit = name;
    if (!written_.empty() && written_.back().second == unfit && readsBack(unfit, t, previous)) {
        // t's name is the rounded name of the previous write just before it (a last write at
        // endTime after a write at nearly the same time): that one takes the digits that tell
        // it from t, so that each directory holds the state its name says.
        auto& last = written_.back();
        std::string moved;
        for (int d = timeDigits_ + 1; d <= 17 && moved.empty(); ++d) {
            const std::string n = timeName(last.first, d);
            if (n != unfit && free(n) && readsBack(n, last.first, t)) moved = n;
        }
        if (moved.empty()) throw RunError("time " + timeName(t, 17) + " s: no directory name of up to 17 digits is free");
        fs::rename(fs::path(options_.caseDir) / last.second, fs::path(options_.caseDir) / moved);
        PvdCollection pvd(pvdPath(options_.caseDir));
        pvd.removeTime(last.first);
        pvd.add(last.first, moved + "/particles.vtp", 0);
        if (writeGrid_) pvd.add(last.first, moved + "/grid.vti", 1);
        pvd.write();
        if (onDisk_.name == last.second) onDisk_.name = moved;
        log() << "Time directory " << last.second << " (time " << std::setprecision(12) << last.first
              << " s) renamed " << moved << ": time " << t << " s is written as " << unfit << "\n";
        last.second = moved;
        return unfit;
    }
    int digits = timeDigits_;
    while (!fits(name) && digits < 17) name = timeName(t, ++digits);
    if (!fits(name)) throw RunError("time " + timeName(t, 17) + " s: no directory name of up to 17 digits is free");
    std::ostringstream os;
    os << "keyword 'timePrecision': " << timeDigits_ << " digits would name time " << std::setprecision(12) << t
       << " s '" << unfit << "' (another time's name, or nearer another time); time directories get " << digits
       << " digits from now on (raise timePrecision to keep their names alike)";
    warning(controlDict_.fileName(), controlDict_.lineOf("timePrecision"), os.str());
    timeDigits_ = digits;
    return name;
}

void Simulation::write()
{
    auto timer = solver_->timers().time("output");
    const std::string name = timeDirectoryName(time_);
    const std::string& dir = options_.caseDir;
    writeState(solver_->particles(), time_, step_, deltaT_, solver_->removedMass(), name);
    onDisk_ = {time_, step_, name};
    PvdCollection pvd(pvdPath(dir));
    pvd.add(time_, name + "/particles.vtp", 0);
    if (writeGrid_) pvd.add(time_, name + "/grid.vti", 1);
    // purgeWrite: like OpenFOAM, only directories this run wrote are removed, never the start.
    written_.push_back({time_, name});
    while (timeControl_->purgeWrite() > 0 &&
           static_cast<int>(written_.size()) > timeControl_->purgeWrite()) {
        pvd.removeTime(written_.front().first);
        removeTimeDirectory(dir, written_.front().second);
        written_.pop_front();
    }
    pvd.write();
}

void Simulation::stop(const std::optional<StabilityTrip>& trip, const std::string& solverMessage)
{
    std::ostringstream where;
    try {
        if (trip && trip->stateIsGood) {
            if (onDisk_.step != step_) write();
        } else if (const GoodState& good = guard_->lastGood(); good.step > onDisk_.step) {
            const std::string name = timeDirectoryName(good.time);
            writeState(good.particles, good.time, good.step, good.deltaT, good.removedMass, name);
            PvdCollection pvd(pvdPath(options_.caseDir));
            pvd.add(good.time, name + "/particles.vtp", 0);
            if (writeGrid_) {
                writeGoodStateGrid(good, (fs::path(options_.caseDir) / name / "grid.vti").string());
                pvd.add(good.time, name + "/grid.vti", 1);
            }
            pvd.write();
            onDisk_ = {good.time, good.step, name};
        }
        where << "; last good state: time " << onDisk_.time << " s (step " << onDisk_.step << ") in "
              << (fs::path(options_.caseDir) / onDisk_.name).string();
    } catch (const std::exception& e) {
        where << "; the last good state could not be written: " << e.what();
    }
    throw RunError((trip ? trip->message : solverMessage) + where.str());
}

void Simulation::writeGoodStateGrid(const GoodState& good, const std::string& path)
{
    // The run ends here: the engine may take the good state's particles to project them.
    if (!solver_->hasLoads()) {
        solver_->replaceParticles(good.particles);
        solver_->setTime(good.time);
        solver_->projectToGrid();
        writeGrid(path, solver_->grid(), good.time);
        return;
    }
    // Loads hold particle indices: the grid's place and size, with empty fields.
    Grid empty = solver_->grid();
    empty.resetFields();
    writeGrid(path, empty, good.time);
}

long Simulation::run()
{
    using clock = std::chrono::steady_clock;
    const auto wallStart = clock::now();
    auto lastProgress = wallStart;
    const double tStart = time_;
    const long firstStep = step_;
    {
        // A restart drops the later entries of the ParaView index (they will be rewritten).
        PvdCollection pvd(pvdPath(options_.caseDir));
        pvd.removeAfter(time_);
        pvd.add(time_, context_.startTimeName + "/particles.vtp", 0);
        if (writeGrid_) {  // every time of the index has the same parts: the start its grid too
            const fs::path startGrid = fs::path(options_.caseDir) / context_.startTimeName / "grid.vti";
            if (!fs::exists(startGrid)) {
                solver_->projectToGrid();
                writeGrid(startGrid.string(), solver_->grid(), time_);
            }
            pvd.add(time_, context_.startTimeName + "/grid.vti", 1);
        }
        pvd.write();
    }
    if (stages_) stages_->start(*solver_, time_, step_);  // begins a stage, or carries one on
    for (auto& f : functions_) f->start(*solver_, time_);
    if (stages_) restartGuard();
    else guard_->start(time_, step_);
    bool writtenLast = true;
    const double noStage = std::numeric_limits<double>::infinity();
    const StopSignals stopSignals;  // SIGINT, SIGTERM: finish the step, write it, stop
    while (!timeControl_->finished(time_) && !(stages_ && stages_->done())) {
        try {
            solver_->setTime(time_);
            deltaT_ = timeControl_->deltaT(time_, solver_->criticalTimeStep(), stages_ ? stages_->landOn() : noStage);
            // At fixed step indices, so that a restart sorts exactly as the straight run.
            if (sortInterval_ > 0 && step_ % sortInterval_ == 0) solver_->sortParticles();
            scheme_->advance(*solver_, deltaT_);
            solver_->advanceRigidBodies(deltaT_);
            solver_->removeOutflow();  // particles gone through an opening (silo outlet)
        } catch (const RunError& e) {
            // The particle to blame, where the guard finds one in what the solver left.
            stop(guard_->diagnose(time_, step_ + 1, deltaT_),
                 std::string(e.what()) + " (step " + std::to_string(step_ + 1) + " from t = " + exactNumber(time_) + " s)");
        }
        const double tPrevious = time_;
        time_ += deltaT_;
        ++step_;
        {
            std::optional<StabilityTrip> trip;
            {
                auto timer = solver_->timers().time("stabilityGuard");
                trip = guard_->check(time_, step_, deltaT_);
            }
            if (trip) stop(trip, "");
        }
        {
            auto timer = solver_->timers().time("functionObjects");
            for (auto& f : functions_) f->execute(*solver_, time_, step_);
        }
        StageEvent stage = StageEvent::none;
        if (stages_) {
            stage = stages_->afterStep(*solver_, time_, step_, deltaT_);
            if (stage == StageEvent::particlesChanged) guard_->start(time_, step_);
        }
        // The end of every stage is written: a restart from it begins the next stage.
        writtenLast = timeControl_->isWriteTime(tPrevious, time_, step_) || stage == StageEvent::ended;
        if (writtenLast) write();
        if (stage == StageEvent::ended) {
            stages_->beginNext(*solver_, time_, step_);
            restartGuard();
        }
        if (const int signal = StopSignals::received()) {
            if (!writtenLast) write();
            throw StopRequest(signal, StopSignals::name(signal) + " at t = " + exactNumber(time_) + " s (step " +
                                          std::to_string(step_) + "): the state is written to " +
                                          (fs::path(options_.caseDir) / onDisk_.name).string());
        }
        const auto now = clock::now();
        if (std::chrono::duration<double>(now - lastProgress).count() >= progressInterval_) {
            lastProgress = now;
            const double wall = std::chrono::duration<double>(now - wallStart).count();
            char line[160];
            if (timeControl_->hasEndTime()) {
                const double left = wall * (timeControl_->endTime() - time_) / std::max(time_ - tStart, 1e-300);
                std::snprintf(line, sizeof line, "t = %-12.6g step %-9ld dt %-10.3g wall %8.1f s   left ~%8.1f s",
                              time_, step_, deltaT_, wall, left);
            } else {  // a run in stages without endTime: its end is not known in advance
                std::snprintf(line, sizeof line, "t = %-12.6g step %-9ld dt %-10.3g wall %8.1f s   |v|max %.3g m/s",
                              time_, step_, deltaT_, wall, solver_->maxParticleSpeed());
            }
            log() << line;
            if (const Stage* s = stages_ ? stages_->current() : nullptr) log() << "   stage " << s->name();
            log() << std::endl;
        }
    }
    if (!writtenLast) write();
    const double wall = std::chrono::duration<double>(clock::now() - wallStart).count();
    const long steps = step_ - firstStep;
    log() << "End: t = " << time_ << ", " << steps << " steps, " << solver_->particles().size()
          << " particles, wall " << wall << " s, "
          << (wall > 0 ? double(steps) * solver_->particles().size() / wall : 0.0)
          << " particle-updates/s, threads " << threadCount() << ", peak memory " << peakMemoryMiB()
          << " MiB, " << solver_->bytesPerParticle() << " B/particle\n";
    log() << "Stability guard: ";
    if (guard_->energyChecked())
        log() << "created energy at most " << 100 * guard_->largestEnergyGain() << " % of the budget (stops at "
              << 100 * guard_->maxEnergyGain() << " %), ";
    log() << guard_->snapshots() << " copies of the last good state, "
          << (guard_->snapshots() > 0 ? 1e3 * guard_->snapshotSeconds() / guard_->snapshots() : 0.0)
          << " ms each\n";
    if (solver_->wallReturns() > 0)
        log() << "Walls: " << solver_->wallReturns()
              << " particle positions put back on a wall side they had passed by less than half a cell\n";
    solver_->timers().print(log());
    return steps;
}

} // namespace gpic
