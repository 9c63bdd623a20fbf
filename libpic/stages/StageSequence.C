#include "stages/StageSequence.H"

#include "core/error.H"
#include "core/Info.H"
#include "dictionary/Dictionary.H"
#include "dictionary/ExactNumber.H"
#include "engine/MpmSolver.H"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

namespace {
const char* const header = "# index startTime endTime startStep endStep stage type reason";
} // namespace

template <int D>
StageSequence<D>::StageSequence(const Dictionary& stagesDict, StageSetup<D> setup, std::string caseDir)
    : setup_(std::move(setup)), caseDir_(std::move(caseDir))
{
    for (const auto& key : stagesDict.keys()) {
        if (!stagesDict.isDict(key))
            stagesDict.fail(key, "'" + key + "' is not a stage sub-dictionary { type ...; until { ... } }");
        stages_.push_back(Stage<D>::New(stagesDict.subDict(key), setup_));
    }
    if (stages_.empty()) stagesDict.fail("", "stages holds no stage; valid types: " + Registry<Stage<D>>::validChoices());
    setup_.rigidBodies = nullptr;  // read by the stages' constructors only; the caller's to keep
}

template <int D>
bool StageSequence<D>::changesParticles() const
{
    for (const auto& s : stages_)
        if (s->changesParticles()) return true;
    return false;
}

template <int D>
void StageSequence<D>::restore(const Dictionary* stageFile, Particles<D> dormant)
{
    pool_.dormant() = std::move(dormant);
    fresh_ = stageFile == nullptr;
    if (fresh_) return;
    const Dictionary& f = *stageFile;
    const long index = f.getChecked<long>("index", [&](const long& i) { return i >= 0 && i <= static_cast<long>(stages_.size()); },
                                          "0 <= index <= " + std::to_string(stages_.size()) + " (the stages of system/controlDict)");
    index_ = static_cast<std::size_t>(index);
    const std::string name = f.get<std::string>("stage");
    const std::string expected = done() ? "none" : stages_[index_]->name();
    if (name != expected)
        f.fail("stage", "the time directory was written in stage '" + name + "' (number " + std::to_string(index + 1) +
                            "), but stage number " + std::to_string(index + 1) + " of system/controlDict is '" +
                            expected + "'");
    begun_ = f.get<bool>("begun");
    startTime_ = f.get<double>("startTime");
    startStep_ = f.get<long>("startStep");
    if (begun_ && done()) f.fail("begun", "no stage is left to carry on");
    progress_ = f.subDictPtr("progress") ? *f.subDictPtr("progress") : Dictionary();
}

template <int D>
void StageSequence<D>::logBegin(double t, long step) const
{
    const Stage<D>& s = *stages_[index_];
    info() << "Stage " << s.name() << " (" << s.type() << ") begins at t = " << t << " s, step " << step
           << ": bodies " << s.bodyList() << ", damping " << s.damping() << "\n";
}

template <int D>
void StageSequence<D>::start(MpmSolver<D>& solver, double t, long step)
{
    // Rows of stages.dat from a run this one replaces (a restart from an earlier time) go.
    const fs::path dat = fs::path(caseDir_) / "postProcessing/stages.dat";
    if (fs::exists(dat)) {
        std::ifstream in(dat);
        std::ostringstream kept;
        for (std::string line; std::getline(in, line);) {
            std::istringstream words(line);
            long index = 0;
            double t0 = 0, t1 = 0;
            if (line.rfind("#", 0) == 0 || !(words >> index >> t0 >> t1) || t1 <= t + 1e-12 * std::abs(t))
                kept << line << "\n";
        }
        in.close();
        std::ofstream(dat) << kept.str();
    }
    if (begun_) {
        Stage<D>& s = *stages_[index_];
        s.resume(solver, progress_, startTime_);
        info() << "Stage " << s.name() << " (" << s.type() << ") carries on at t = " << t << " s, step " << step
               << " (begun at t = " << startTime_ << " s, step " << startStep_ << ")\n";
        return;
    }
    if (fresh_) {
        // Everything sleeps until a stage wakes it: a fill starts from an empty box.
        pool_.exchange(
            solver, [](const Particles<D>&, std::size_t) { return true; }, [](const Particles<D>&, std::size_t) { return false; });
        fresh_ = false;
    }
    beginNext(solver, t, step);
}

template <int D>
void StageSequence<D>::beginNext(MpmSolver<D>& solver, double t, long step)
{
    while (!done()) {
        begun_ = true;
        startTime_ = t;
        startStep_ = step;
        logBegin(t, step);
        if (stages_[index_]->begin(solver, pool_, t, step) != StageEvent::ended) return;
        afterStep(solver, t, step, 0.0);  // ended at once: log and record it
    }
}

template <int D>
StageEvent StageSequence<D>::afterStep(MpmSolver<D>& solver, double t, long step, double dt)
{
    if (done()) return StageEvent::none;
    Stage<D>& s = *stages_[index_];
    // dt == 0: a stage that ended as it began (beginNext).
    const StageEvent event = dt > 0 ? s.afterStep(solver, pool_, t, step, dt) : StageEvent::ended;
    if (event != StageEvent::ended) return event;
    Record r{s.name(), s.type(), s.reason() + s.summary(), startTime_, t, startStep_, step, s.timedOut()};
    info() << "Stage " << r.name << " ended: " << r.reason << ", t = " << t << " s, " << step - startStep_
           << " steps\n";
    if (r.timedOut) warning(s.fileName(), s.line(), "stage " + r.name + " ended by its maxTime: " + r.reason);
    appendRow(r);
    records_.push_back(r);
    ++index_;
    begun_ = false;
    return StageEvent::ended;
}

template <int D>
void StageSequence<D>::appendRow(const Record& r) const
{
    const fs::path dir = fs::path(caseDir_) / "postProcessing";
    fs::create_directories(dir);
    const fs::path dat = dir / "stages.dat";
    const bool fresh = !fs::exists(dat);
    std::ofstream out(dat, std::ios::app);
    if (fresh) out << header << "\n";
    char times[160];
    std::snprintf(times, sizeof times, "%zu %.12g %.12g %ld %ld", index_, r.startTime, r.endTime, r.startStep,
                  r.endStep);
    out << times << " " << r.name << " " << r.type << " \"" << r.reason << "\"\n";
}

template <int D>
double StageSequence<D>::landOn() const
{
    return done() || !begun_ ? std::numeric_limits<double>::infinity() : stages_[index_]->landOn();
}

template <int D>
typename Space<D>::Vector StageSequence<D>::gravity() const
{
    return done() ? setup_.gravity : stages_[index_]->gravity();
}

template <int D>
void StageSequence<D>::writeStageFile(const std::string& timeDir, const std::string& timeName) const
{
    fs::create_directories(fs::path(timeDir) / "uniform");
    const fs::path file = fs::path(timeDir) / "uniform/stage";
    std::ofstream os(file);
    os << fileHeader("stage", timeName + "/uniform") << "index     " << index_ << ";\n"
       << "stage     " << (done() ? std::string("none") : stages_[index_]->name()) << ";\n"
       << "begun     " << (begun_ ? "yes" : "no") << ";\n"
       << "startTime " << exactNumber(startTime_) << ";\n"
       << "startStep " << startStep_ << ";\n";
    if (begun_) {
        os << "progress\n{\n";
        stages_[index_]->writeProgress(os);
        os << "}\n";
    }
    if (!os) throw RunError("cannot write " + file.string());
}

template class StageSequence<2>;
#if GPIC_WITH_3D
template class StageSequence<3>;
#endif

} // namespace gpic
