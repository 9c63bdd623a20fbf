#include "run/TimeWriter.H"

#include "case/CaseFiles.H"
#include "core/Info.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

TimeWriter::TimeWriter(std::string caseDir, const OnDisk& start, int timePrecision, bool withGrid, int purgeWrite,
                       const Dictionary& controlDict)
    : caseDir_(std::move(caseDir)), startName_(start.name), digits_(timePrecision), withGrid_(withGrid),
      purgeWrite_(purgeWrite), controlDict_(controlDict), onDisk_(start)
{
    // A restart: the directories the earlier runs wrote up to the start (all but the case's
    // first, picInit's) count as written, so that purgeWrite keeps the last N across restarts
    // as in a straight run.
    if (purgeWrite_ <= 0) return;
    const auto times = listTimeDirectories(caseDir_);
    if (times.empty() || times.front().second == startName_) return;
    for (std::size_t k = 1; k < times.size(); ++k) {
        earlier_.push_back(times[k]);
        if (times[k].second == startName_) return;
    }
    earlier_.clear();  // the start is not among them
}

std::string TimeWriter::nameFor(double t)
{
    // A time this run wrote already keeps its name (the same state written again).
    const auto sameTime = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };
    for (const auto& w : written_)
        if (sameTime(w.first, t)) return w.second;
    // A name fits when no other directory of this run has it and it reads back nearer t than
    // the previous write (or the start): 0.15 is not written as "0.2" before 0.2 comes.
    const double previous = written_.empty() ? std::stod(startName_) : written_.back().first;
    const auto free = [&](const std::string& n) {
        if (n == startName_) return false;
        for (const auto& w : written_)
            if (w.second == n) return false;
        return true;
    };
    // Name n reads back as time `of`, nearer it than half the spacing to `other`.
    const auto readsBack = [](const std::string& n, double of, double other) {
        return std::abs(std::stod(n) - of) <= 0.5 * std::abs(of - other);
    };
    const auto fits = [&](const std::string& n) { return free(n) && readsBack(n, t, previous); };
    std::string name = timeName(t, digits_);
    if (fits(name)) return name;
    const std::string unfit = name;
    if (!written_.empty() && written_.back().second == unfit && readsBack(unfit, t, previous)) {
        // t's name is the rounded name of the previous write just before it (a last write at
        // endTime after a write at nearly the same time): that one takes the digits that tell
        // it from t, so that each directory holds the state its name says.
        auto& last = written_.back();
        std::string moved;
        for (int d = digits_ + 1; d <= 17 && moved.empty(); ++d) {
            const std::string n = timeName(last.first, d);
            if (n != unfit && free(n) && readsBack(n, last.first, t)) moved = n;
        }
        if (moved.empty()) throw RunError("time " + timeName(t, 17) + " s: no directory name of up to 17 digits is free");
        fs::rename(fs::path(caseDir_) / last.second, fs::path(caseDir_) / moved);
        PvdCollection pvd(pvdPath(caseDir_));
        pvd.removeTime(last.first);
        index(pvd, last.first, moved);
        pvd.write();
        if (onDisk_.name == last.second) onDisk_.name = moved;
        info() << "Time directory " << last.second << " (time " << std::setprecision(12) << last.first
              << " s) renamed " << moved << ": time " << t << " s is written as " << unfit << "\n";
        last.second = moved;
        return unfit;
    }
    int digits = digits_;
    while (!fits(name) && digits < 17) name = timeName(t, ++digits);
    if (!fits(name)) throw RunError("time " + timeName(t, 17) + " s: no directory name of up to 17 digits is free");
    std::ostringstream os;
    os << "keyword 'timePrecision': " << digits_ << " digits would name time " << std::setprecision(12) << t
       << " s '" << unfit << "' (another time's name, or nearer another time); time directories get " << digits
       << " digits from now on (raise timePrecision to keep their names alike)";
    warning(controlDict_.fileName(), controlDict_.lineOf("timePrecision"), os.str());
    digits_ = digits;
    return name;
}

void TimeWriter::written(double t, long step, const std::string& name)
{
    onDisk_ = {t, step, name};
    PvdCollection pvd(pvdPath(caseDir_));
    index(pvd, t, name);
    // purgeWrite: the oldest beyond N of those this run and the runs before it up to its
    // start wrote; never the case's first directory, never one after the start.
    written_.push_back({t, name});
    while (purgeWrite_ > 0 && static_cast<int>(earlier_.size() + written_.size()) > purgeWrite_) {
        auto& oldest = earlier_.empty() ? written_ : earlier_;
        pvd.removeTime(oldest.front().first);
        removeTimeDirectory(caseDir_, oldest.front().second);
        oldest.pop_front();
    }
    pvd.write();
}

void TimeWriter::writtenOutOfTurn(double t, long step, const std::string& name)
{
    PvdCollection pvd(pvdPath(caseDir_));
    index(pvd, t, name);
    pvd.write();
    onDisk_ = {t, step, name};
}

void TimeWriter::index(PvdCollection& pvd, double t, const std::string& name) const
{
    pvd.add(t, name + "/particles.vtp", 0);
    if (withGrid_) pvd.add(t, name + "/grid.vti", 1);
    for (std::size_t k = 0; k < moreParts_.size(); ++k) pvd.add(t, name + "/" + moreParts_[k], 2 + int(k));
}

std::string TimeWriter::newestPath() const { return (fs::path(caseDir_) / onDisk_.name).string(); }

} // namespace gpic
