#include "run/Simulation.H"

#include "case/CaseFiles.H"
#include "core/CaseLock.H"
#include "core/error.H"
#include "core/Info.H"
#include "core/StopSignals.H"
#include "core/Threads.H"
#include "dictionary/ExactNumber.H"
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "run/WriteBudget.H"

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

} // namespace

template <int D>
Simulation<D>::Simulation(const RunOptions& options, std::unique_ptr<Case<D>> c)
    : options_(options), case_(std::move(c)), solver_(*case_->solver), time_(case_->time), step_(case_->step),
      times_(options.caseDir, {case_->time, case_->step, case_->context.startTimeName},
             case_->timeControl->timePrecision(), case_->writeGrid, case_->timeControl->purgeWrite(),
             case_->controlDict)
{
    guard_ = std::make_unique<StabilityGuard<D>>(case_->stability, solver_, case_->context.bodyNames, case_->gravity,
                                              case_->hasLoads, snapshotFile());
    if (options_.tuneThreads && threadCount() > 1) tuner_ = std::make_unique<ThreadTuner>(threadCount());
    std::vector<bool> rigid(case_->context.bodyNames.size());
    for (std::size_t b = 0; b < rigid.size(); ++b) rigid[b] = solver_.rigidBody(static_cast<int>(b)) != nullptr;
    toolSurfaces_ = std::make_unique<ToolSurfaces<D>>(options_.caseDir, case_->context.bodyNames, rigid);
    times_.alsoIndex(toolSurfaces_->fileNames());
    if (std::find(rigid.begin(), rigid.end(), true) != rigid.end())
        toolWatch_ = std::make_unique<ToolForceWatch<D>>(
            case_->context.bodyNames, rigid,
            case_->volumetricStrainName == "cellMean"
                ? "measured at a wall's foot with volumetricStrain cellMean under FLIP, which damping does not "
                  "cure: use transfer APIC or volumetricStrain particle in system/mpmSchemes"
                : "damping 0.1 in system/controlDict calms a quasi-static push, but it drags on the soil "
                  "the tool moves: read the force from an undamped run where one runs through");
    if (options_.communicator) setUpParallel();
    // Every keyword has been read by now: what is left is a typo or a leftover.
    case_->warnUnused();

    log() << "Case " << case_->name << ": " << solver_.particles().size() << " particles, " << solver_.grid().nx();
    for (int a = 1; a < D; ++a) log() << " x " << solver_.grid().cells(a);
    log() << " cells, scheme " << case_->schemeName << ", shape functions " << case_->shapeName
          << ", volumetric strain " << case_->volumetricStrainName << ", starting at t = " << time_ << " (" << case_->context.startTimeName << ")\n";
    if (const ContactPass<D>* contact = solver_.contact())
        log() << "Contact pass: " << contact->nBodies() << " bodies with their own velocity fields, "
              << contact->summary() << "\n";
}

template <int D>
double Simulation<D>::parallelCriticalTimeStep()
{
    // MpmSolver::criticalTimeStep's terms over every rank: the shortest step length over the
    // fastest wave and particle, the passes' smallest step. Minima and maxima are exact, so
    // the step is the serial run's to the bit. With them the stop signal any rank has had:
    // every rank then stops at the end of the same step.
    // One exchange a step: the maxima as minima of the negated values.
    std::vector<double> terms{solver_.stepLength(), -solver_.maxWaveSpeed(), -solver_.maxParticleSpeed(),
                              solver_.passTimeStep(), -double(StopSignals::received())};
    parallel_->min(terms);
    stopSignal_ = static_cast<int>(-terms[4]);
    return std::min(terms[0] / (-terms[1] - terms[2]), terms[3]);
}

template <int D> Particles<D>* Simulation<D>::dormant()
{
    return case_->stages ? &case_->stages->pool().dormant() : nullptr;
}

template <int D>
void Simulation<D>::setUpParallel()
{
    // Every part of the suite runs in parallel (doc/parallel.md): the passes complete their
    // scatters (XPIC's projections, the Cosserat rotation's fields), stages take their ends
    // and layers over the ranks, each rank keeps the sleeping particles of its cells, and a
    // cell's particles are all its owner's (volumetricStrain cellMean). A plugin's function
    // object that does not say it serves parallel runs is refused in one line, before any step.
    for (const auto& f : case_->functions)
        if (!f->servesParallelRuns())
            throw InputError("system/controlDict", 0,
                             "function object " + f->name() +
                                 ": its type does not say it serves parallel runs (FunctionObject::servesParallelRuns, "
                                 "doc/parallel.md); run it without -parallel");
    const Communicator& comm = *options_.communicator;
    // The layers of nodes beyond its cell a particle reaches: k nodes per axis, (k - 1) / 2.
    int perAxis = 1;
    while (std::pow(perAxis + 1, D) <= solver_.nodesPerParticle() + 0.5) ++perAxis;
    const Grid<D>& grid = solver_.grid();
    parallel_ = std::make_unique<ParallelRun<D>>(comm, grid, options_.caseDir, (perAxis - 1) / 2);
    parallel_->place(solver_, dormant());  // a start written before the last re-decomposition
    if (case_->hasLoads) parallel_->shareActiveNodesAlways();  // the guard's load work: owned nodes
    solver_.setRankSums(parallel_.get());
    log() << "Parallel run: rank " << comm.rank() << " of " << comm.size() << ", " << solver_.particles().size()
          << " particles here, " << parallel_->sharedValues() << " node values shared with the neighbours per exchange\n";
}

template <int D>
Simulation<D>::~Simulation()
{
    // The run's own last good state; a stopped run has written it as a time directory.
    std::error_code ec;
    fs::remove(snapshotFile(), ec);
}

template <int D>
std::string Simulation<D>::snapshotFile() const { return (fs::path(options_.caseDir) / ".lastGoodState.vtp").string(); }

template <int D>
std::ostream& Simulation<D>::log() const { return info(); }

template <int D>
void Simulation<D>::restartGuard()
{
    auto before = std::move(guard_);
    guard_ = std::make_unique<StabilityGuard<D>>(case_->stability, solver_, case_->context.bodyNames,
                                              case_->stages->gravity(), case_->hasLoads, snapshotFile());
    guard_->start(time_, step_);
    if (before) guard_->continueStatistics(*before);
    kineticRatioWarned_ = false;
    reportMassScaling();
}

template <int D>
void Simulation<D>::reportMassScaling() const
{
    const std::vector<double>& scale = solver_.massScales();
    if (scale.empty()) return;
    log() << "Mass scaling (" << solver_.massScaling().describe() << "): density of";
    const char* separator = " ";
    for (std::size_t m = 0; m < scale.size(); ++m)
        if (solver_.deforms(m)) {
            log() << separator << solver_.materials()[m]->name() << " x " << scale[m];
            separator = ", ";
        }
    log() << "; stable step " << solver_.criticalTimeStep() << " s; rigid bodies and gravity keep the true mass\n";
}

template <int D>
void Simulation<D>::watchKineticRatio()
{
    if (solver_.massScales().empty()) return;
    // The start of a stage sets the material moving before it has done much work: the
    // ratio means something once the stage is under way.
    constexpr long startSteps = 100;
    const double work = guard_->workDoneSinceStart();
    if (guard_->checksSinceStart() < startSteps || !(work > 0)) return;
    const double ratio = guard_->kineticEnergy() / work;
    largestKineticRatio_ = std::max(largestKineticRatio_, ratio);
    const double bound = solver_.massScaling().kineticRatio();
    if (ratio > bound && !kineticRatioWarned_) {
        kineticRatioWarned_ = true;
        std::cerr << "Warning: at t = " << time_ << " s (step " << step_ << ") the kinetic energy is " << 100 * ratio
                  << " % of the work done on the material in the stage (kineticRatio " << bound
                  << "): the mass scaling makes inertia count; use a smaller factor or timeStep\n";
    }
}

template <int D>
void Simulation<D>::writeState(const Particles<D>& particles, double time, long step, double deltaT,
                            double removedMass, const std::string& name)
{
    // The grid and the function objects hold the current step's: written only with it.
    const bool current = &particles == &solver_.particles();
    const bool withGrid = case_->writeGrid && current;
    writeTimeDirectoryAtomically(options_.caseDir, name, [&](const std::string& tmp) {
        writeParticles(tmp + "/particles.vtp", particles, time, case_->context.materialNames, case_->context.bodyNames);
        if (withGrid) writeGrid(tmp + "/grid.vti", solver_.grid(), time);
        toolSurfaces_->write(tmp, particles, time, solver_.ranks());
        fs::create_directories(tmp + "/uniform");
        std::ofstream t(tmp + "/uniform/time");
        t << fileHeader("time") << "value   " << exactNumber(time) << ";\nname    \"" << name << "\";\nindex   " << step
          << ";\ndeltaT  " << exactNumber(deltaT) << ";\n";
        if (removedMass > 0) t << "removedMass " << exactNumber(removedMass) << ";  // [kg/m] through the outlets\n";
        if (!t.flush()) throw RunError("cannot write " + tmp + "/uniform/time: " + std::strerror(errno));
        if (current && !case_->functions.empty()) {
            std::ofstream f(tmp + "/uniform/functionObjects");
            f << fileHeader("functionObjects");
            for (const auto& fn : case_->functions) {
                f << fn->name() << "\n{\n";
                fn->writeState(f);
                f << "}\n";
            }
            if (!f.flush()) throw RunError("cannot write " + tmp + "/uniform/functionObjects: " + std::strerror(errno));
        }
        if (case_->stages) {  // where the run is in its stages, and the sleeping particles
            case_->stages->writeStageFile(tmp, name);
            const Particles<D>& dormant = case_->stages->pool().dormant();
            if (dormant.size() > 0)
                writeParticles(tmp + "/dormant.vtp", dormant, time, case_->context.materialNames, case_->context.bodyNames);
        }
    });
}

template <int D>
void Simulation<D>::write()
{
    auto timer = solver_.timers().time("output");
    // The function objects' rows up to this state on disk first: a run killed later keeps them.
    for (auto& f : case_->functions) f->flushFiles();
    const std::string name = times_.nameFor(time_);
    writeState(solver_.particles(), time_, step_, deltaT_, solver_.removedMass(), name);
    guard_->stateWritten((fs::path(options_.caseDir) / name / "particles.vtp").string(), time_, step_, deltaT_);
    times_.written(time_, step_, name);
    indexProcessors();
}

template <int D> void Simulation<D>::indexProcessors() const
{
    // A parallel run: rank 0 lists every rank's files of each time in <case>/processors.pvd,
    // one part per rank and file, so that ParaView opens the whole decomposed run as one time
    // series. The ranks write the same time directories: rank 0's index names them all.
    if (!parallel_ || parallel_->communicator().rank() != 0) return;
    const PvdCollection mine(pvdPath(options_.caseDir));
    int parts = 1;
    for (const PvdEntry& e : mine.entries()) parts = std::max(parts, e.part + 1);
    const fs::path all = fs::path(options_.caseDir).parent_path() / "processors.pvd";
    fs::remove(all);  // written afresh from rank 0's index
    PvdCollection pvd(all.string());
    for (const PvdEntry& e : mine.entries())
        for (int r = 0; r < parallel_->communicator().size(); ++r)
            pvd.add(e.time, "processor" + std::to_string(r) + "/" + e.file, r * parts + e.part);
    pvd.write();
}

template <int D>
void Simulation<D>::stop(const std::optional<StabilityTrip>& trip, const std::string& solverMessage)
{
    std::ostringstream where;
    try {
        if (trip && trip->stateIsGood) {
            if (times_.newest().step != step_) write();
        } else if (const GoodState<D>& good = guard_->lastGood(); good.step > times_.newest().step) {
            const std::string name = times_.nameFor(good.time);
            Particles<D> particles = good.particles();  // read back once, for both files
            writeState(particles, good.time, good.step, good.deltaT, good.removedMass, name);
            if (case_->writeGrid && !parallel_)  // projecting would wait for the other ranks
                writeGoodStateGrid(std::move(particles), good.time,
                                   (fs::path(options_.caseDir) / name / "grid.vti").string());
            times_.writtenOutOfTurn(good.time, good.step, name);
            indexProcessors();
        }
        where << "; last good state: time " << times_.newest().time << " s (step " << times_.newest().step
              << ") in " << times_.newestPath();
    } catch (const std::exception& e) {
        where << "; the last good state could not be written: " << e.what();
    }
    throw RunError((trip ? trip->message : solverMessage) + where.str());
}

template <int D>
void Simulation<D>::writeGoodStateGrid(Particles<D> particles, double time, const std::string& path)
{
    // The run ends here: the engine may take the good state's particles to project them.
    if (!solver_.passesHoldIndices()) {
        solver_.replaceParticles(std::move(particles));
        solver_.setTime(time);
        solver_.projectToGrid();
        writeGrid(path, solver_.grid(), time);
        return;
    }
    // Loads hold particle indices: the grid's place and size, with empty fields.
    Grid<D> empty = solver_.grid();
    empty.resetFields();
    writeGrid(path, empty, time);
}

template <int D>
long Simulation<D>::run()
{
    const auto wallStart = Clock::now();
    auto lastProgress = wallStart;
    const double tStart = time_;
    const long firstStep = step_;
    checkWriteBudget(*case_->timeControl, case_->controlDict, time_,
                     case_->timeControl->plainDeltaT(solver_.criticalTimeStep()), options_.caseDir,
                     case_->context.startTimeName);
    indexStart();
    startParts();
    bool writtenLast = true;
    const StopSignals stopSignals;  // SIGINT, SIGTERM: finish the step, write it, stop
    double particleUpdates = 0;     // the particles each step moves: a silo empties as it runs
    while (!finished()) {
        const double tPrevious = time_;
        const auto stepStart = Clock::now();
        particleUpdates += static_cast<double>(solver_.particles().size());
        takeStep();
        checkStep();
        if (tuner_) tuner_->stepTook(std::chrono::duration<double>(Clock::now() - stepStart).count());
        const StageEvent stage = afterStep();
        // The end of every stage is written: a restart from it begins the next stage.
        writtenLast = case_->timeControl->isWriteTime(tPrevious, time_, step_) || stage == StageEvent::ended;
        if (writtenLast) write();
        if (!finished()) {  // the last step is written in any case
            auto timer = solver_.timers().time("stabilityGuard");
            guard_->keepIfDue(time_, step_, deltaT_);
        }
        if (stage == StageEvent::ended) {
            case_->stages->beginNext(solver_, time_, step_);
            if (parallel_) solver_.updateSmallMassCutoff();  // the stage's particles, on every rank
            restartGuard();
        }
        honourStopSignal(writtenLast, wallStart);
        reportProgress(wallStart, lastProgress, tStart);
    }
    if (!writtenLast) write();
    const long steps = step_ - firstStep;
    reportEnd(std::chrono::duration<double>(Clock::now() - wallStart).count(), steps, particleUpdates);
    return steps;
}

template <int D>
void Simulation<D>::indexStart()
{
    const std::string& start = case_->context.startTimeName;
    PvdCollection pvd(pvdPath(options_.caseDir));
    pvd.removeAfter(time_);
    // Every time of the index has the same parts: the start its grid and tool surfaces too.
    const fs::path startDir = fs::path(options_.caseDir) / start;
    if (case_->writeGrid && !fs::exists(startDir / "grid.vti")) {
        solver_.projectToGrid();
        writeGrid((startDir / "grid.vti").string(), solver_.grid(), time_);
    }
    const auto surfaces = toolSurfaces_->fileNames();
    // Missing on any rank of a parallel run: every rank writes (the pose is a sum over them).
    std::vector<double> missing{
        std::any_of(surfaces.begin(), surfaces.end(), [&](const std::string& f) { return !fs::exists(startDir / f); }) ? -1.0 : 0.0};
    solver_.ranks().minOver(missing);
    if (missing[0] < 0.0)
        toolSurfaces_->write(startDir.string(), solver_.particles(), time_, solver_.ranks());
    times_.index(pvd, time_, start);
    pvd.write();
    indexProcessors();
}

template <int D>
void Simulation<D>::startParts()
{
    // What an earlier run wrote after the start (a killed run's rows past its last time
    // directory, a torn row) goes before the first row is written.
    for (auto& f : case_->functions)
        if (const std::size_t dropped = f->keepRowsUpTo(time_))
            log() << "Function object " << f->name() << ": " << dropped << " rows after t = " << time_
                  << " s of an earlier run dropped\n";
    if (case_->stages) case_->stages->start(solver_, time_, step_);  // begins a stage, or carries one on
    if (case_->stages && parallel_) solver_.updateSmallMassCutoff();
    for (auto& f : case_->functions) f->start(solver_, time_);
    if (case_->stages) {
        restartGuard();
    } else {  // the state read from the start directory, unchanged
        guard_->start(time_, step_,
                      (fs::path(options_.caseDir) / case_->context.startTimeName / "particles.vtp").string());
        reportMassScaling();
    }
}

template <int D>
bool Simulation<D>::finished() const
{
    return case_->timeControl->finished(time_) || (case_->stages && case_->stages->done());
}

template <int D>
void Simulation<D>::takeStep()
{
    try {
        solver_.setTime(time_);
        const double noStage = std::numeric_limits<double>::infinity();
        const double critical = parallel_ ? parallelCriticalTimeStep() : solver_.criticalTimeStep();
        deltaT_ = case_->timeControl->deltaT(time_, critical, case_->stages ? case_->stages->landOn() : noStage);
        // At fixed step indices, so that a restart sorts exactly as the straight run.
        if (case_->sortInterval > 0 && step_ % case_->sortInterval == 0) solver_.sortParticles();
        case_->scheme->advance(solver_, deltaT_);
        solver_.endStep(deltaT_);
        if (parallel_) {  // the guard's account is over every rank: moves carry no energy
            parallel_->migrate(solver_);
            const std::string rebalanced = parallel_->rebalance(solver_, step_ + 1, dormant());
            if (!rebalanced.empty()) log() << "Parallel run: " << rebalanced << "\n";
        }
    } catch (const RunError& e) {
        // The particle to blame, where the guard finds one in what the solver left.
        stop(guard_->diagnose(time_, step_ + 1, deltaT_),
             std::string(e.what()) + " (step " + std::to_string(step_ + 1) + " from t = " + exactNumber(time_) + " s)");
    }
    time_ += deltaT_;
    ++step_;
}

template <int D>
void Simulation<D>::checkStep()
{
    std::optional<StabilityTrip> trip;
    {
        auto timer = solver_.timers().time("stabilityGuard");
        trip = guard_->check(time_, step_, deltaT_);
    }
    if (trip) stop(trip, "");
    watchKineticRatio();
    watchTools();
}

template <int D>
void Simulation<D>::watchTools()
{
    if (!toolWatch_) return;
    for (const std::string& line : toolWatch_->add(time_, solver_.rigidBodyLoads()))
        std::cerr << "Warning: at t = " << time_ << " s (step " << step_ << ") " << line << "\n";
}

template <int D>
StageEvent Simulation<D>::afterStep()
{
    {
        auto timer = solver_.timers().time("functionObjects");
        for (auto& f : case_->functions) f->execute(solver_, time_, step_);
    }
    if (!case_->stages) return StageEvent::none;
    const StageEvent stage = case_->stages->afterStep(solver_, time_, step_, deltaT_);
    if (stage == StageEvent::particlesChanged && parallel_) solver_.updateSmallMassCutoff();
    if (stage == StageEvent::particlesChanged) guard_->start(time_, step_);
    return stage;
}

template <int D>
void Simulation<D>::honourStopSignal(bool writtenLast, Clock::time_point wallStart)
{
    // A parallel run: the signal the ranks agreed on when the step began.
    const int signal = parallel_ ? stopSignal_ : StopSignals::received();
    if (!signal) return;
    if (!writtenLast) write();
    // The wall time too: a run made in segments adds them up (gpicdat.run_in_segments).
    std::ostringstream wall;
    wall << std::fixed << std::setprecision(1) << std::chrono::duration<double>(Clock::now() - wallStart).count();
    throw StopRequest(signal, StopSignals::name(signal) + " at t = " + exactNumber(time_) + " s (step " +
                                  std::to_string(step_) + ", wall " + wall.str() + " s): the state is written to " +
                                  times_.newestPath());
}

template <int D>
void Simulation<D>::reportProgress(Clock::time_point wallStart, Clock::time_point& lastProgress, double tStart)
{
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - lastProgress).count() < case_->progressInterval) return;
    lastProgress = now;
    const double wall = std::chrono::duration<double>(now - wallStart).count();
    const TimeControl& control = *case_->timeControl;
    char line[160];
    if (control.hasEndTime()) {
        const double left = wall * (control.endTime() - time_) / std::max(time_ - tStart, 1e-300);
        std::snprintf(line, sizeof line, "t = %-12.6g step %-9ld dt %-10.3g wall %8.1f s   left ~%8.1f s", time_,
                      step_, deltaT_, wall, left);
    } else {  // a run in stages without endTime: its end is not known in advance
        std::snprintf(line, sizeof line, "t = %-12.6g step %-9ld dt %-10.3g wall %8.1f s   |v|max %.3g m/s", time_,
                      step_, deltaT_, wall, solver_.maxParticleSpeed());
    }
    log() << line;
    if (const Stage<D>* s = case_->stages ? case_->stages->current() : nullptr) log() << "   stage " << s->name();
    log() << std::endl;
}

template <int D>
void Simulation<D>::reportEnd(double wall, long steps, double particleUpdates)
{
    log() << "End: t = " << time_ << ", " << steps << " steps, " << solver_.particles().size()
          << " particles, wall " << wall << " s, " << (wall > 0 ? particleUpdates / wall : 0.0)
          << " particle-updates/s, threads "
          << (tuner_ ? std::to_string(tuner_->mostUsed()) + " (chosen by measuring: " + tuner_->summary() + ")"
                     : std::to_string(threadCount()))
          << ", peak memory " << peakMemoryMiB()
          << " MiB, " << solver_.bytesPerParticle() << " B/particle\n";
    log() << "Stability guard: ";
    if (guard_->energyChecked())
        log() << "created energy at most " << 100 * guard_->largestEnergyGain() << " % of the budget (stops at "
              << 100 * guard_->maxEnergyGain() << " %), ";
    log() << guard_->snapshots() << " last good states kept (" << guard_->snapshotSeconds()
          << " s writing those not in a time directory)\n";
    if (!solver_.massScales().empty() || largestKineticRatio_ > 0)
        log() << "Mass scaling: kinetic energy at most " << 100 * largestKineticRatio_
              << " % of the work done on the material in its stage (past each stage's first steps)\n";
    if (solver_.wallReturns() > 0)
        log() << "Walls: " << solver_.wallReturns()
              << " particle positions put back on a wall side they had passed by less than half a cell\n";
    if (parallel_)
        log() << "Parallel run: rank " << parallel_->communicator().rank() << " handed " << parallel_->particlesSent()
              << " particles to its neighbours and took " << parallel_->particlesReceived() << "; "
              << parallel_->sharedValues() << " node values shared, "
              << (steps > 0 ? parallel_->nodalBytesSent() / static_cast<double>(steps) : 0.0) << " bytes sent per step in "
              << (steps > 0 ? static_cast<double>(parallel_->nodalExchanges()) / static_cast<double>(steps) : 0.0)
              << " exchanges\n";
    solver_.timers().print(log());
}

template class Simulation<2>;
#if GPIC_WITH_3D
template class Simulation<3>;
#endif

long runCase(const RunOptions& given)
{
    RunOptions options = given;
    if (options.communicator)  // each rank runs its subdomain, as picDecompose wrote it
        options.caseDir = (fs::path(given.caseDir) / ("processor" + std::to_string(options.communicator->rank()))).string();
    const Dictionary grid = readCaseFile(options.caseDir, "constant/grid");
    const CaseLock lock(options.caseDir, "picSolver");  // one run writes a case at a time
    if (caseDimension(grid) == 3) {
#if GPIC_WITH_3D
        return Simulation<3>(options).run();
#else
        refusePlaneBuild(grid);
#endif
    }
    return Simulation<2>(options).run();
}

} // namespace gpic
