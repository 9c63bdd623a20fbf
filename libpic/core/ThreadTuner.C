#include "core/ThreadTuner.H"

#include <dirent.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace gpic {

namespace {
// A trial compares the counts in interleaved blocks (count a, b, a, b, ...), so that a run
// whose steps grow or shrink (a collapse spreading, a silo emptying) favours neither. A
// block: at least this many steps and this much wall, so that a scheduler's time slice (a
// few ms) is small against it; its first step, after the change of count, is not counted.
constexpr long blockSteps = 4;
constexpr double blockWall = 0.025;  // s
constexpr int rounds = 4;            // blocks per count in a trial
constexpr long startSteps = 5;       // the run's first steps (first touch, first sort) are not timed
constexpr double keepFactor = 30;    // the choice is kept 30 times as long as its trial
constexpr double minKeepWall = 3.0;  // s, at least
constexpr int startSamples = 5;      // of the other tasks, before a trial

} // namespace

int otherRunnableTasks()
{
    std::ifstream stat("/proc/stat");
    std::string key;
    int running = -1;
    while (stat >> key) {
        if (key == "procs_running") {
            stat >> running;
            break;
        }
        stat.ignore(1 << 16, '\n');
    }
    if (running < 0) return -1;
    int own = 0;
    if (DIR* tasks = opendir("/proc/self/task")) {
        while (const dirent* task = readdir(tasks)) {
            if (task->d_name[0] == '.') continue;
            std::ifstream taskStat(std::string("/proc/self/task/") + task->d_name + "/stat");
            std::string line;
            std::getline(taskStat, line);
            const auto close = line.rfind(')');  // the state follows the command name
            if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'R') ++own;
        }
        closedir(tasks);
    }
    return std::max(0, running - own);
}

namespace {

double median(std::vector<double> v)
{
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(mid), v.end());
    return v[mid];
}
} // namespace

ThreadTuner::ThreadTuner(int maxThreads, std::function<int()> otherTasks) : otherTasks_(std::move(otherTasks))
{
    for (int n = std::max(1, maxThreads); n > 1; n /= 2) candidates_.push_back(n);
    candidates_.push_back(1);
    maxThreads_ = candidates_.front();
    stepsAt_.assign(candidates_.size(), 0);
    blockMeans_.assign(candidates_.size(), {});
    tried_.assign(candidates_.size(), 1);
    skip_ = startSteps;
    startTrial();
}

int ThreadTuner::freeCores(int otherTasks) const
{
    return otherTasks < 0 ? maxThreads_ : std::max(1, maxThreads_ - otherTasks);
}

void ThreadTuner::use(std::size_t candidate)
{
    if (candidate != current_ || stepsAt_[current_] == 0) {
#ifdef _OPENMP
        omp_set_num_threads(candidates_[candidate]);
#endif
        skip_ = std::max(skip_, 1L);
    }
    current_ = candidate;
    blockSteps_ = 0;
    blockWall_ = 0;
}

void ThreadTuner::startTrial()
{
    round_ = 0;
    trialSeconds_ = 0;
    for (auto& means : blockMeans_) means.clear();
    others_.clear();
    // The count in use goes first: a tie keeps it.
    std::rotate(candidates_.begin(), candidates_.begin() + static_cast<long>(current_), candidates_.end());
    std::rotate(stepsAt_.begin(), stepsAt_.begin() + static_cast<long>(current_), stepsAt_.end());
    current_ = 0;
    // Counts beyond the cores other processes leave free now are not tried at all: the
    // median of a few samples, as a task may run for a moment on a quiet machine.
    std::vector<double> samples;
    for (int k = 0; k < startSamples && otherTasks_; ++k) {
        if (k > 0) std::this_thread::sleep_for(std::chrono::microseconds(500));
        samples.push_back(otherTasks_());
    }
    const int freeNow = freeCores(samples.empty() ? -1 : static_cast<int>(median(samples)));
    std::size_t first = candidates_.size(), nTried = 0;
    for (std::size_t c = 0; c < candidates_.size(); ++c) {
        tried_[c] = candidates_[c] <= freeNow;
        if (tried_[c]) {
            ++nTried;
            if (first == candidates_.size() || candidates_[c] > candidates_[first]) first = c;
        }
    }
    if (tried_[0]) first = 0;
    trying_ = nTried > 1;
    if (!trying_) {  // nothing to compare: the count that fits, looked at again after a while
        settledFor_ = 0;
        settleSeconds_ = minKeepWall;
    }
    use(first);
}

std::size_t ThreadTuner::nextTried(std::size_t c) const
{
    do c = (c + 1) % candidates_.size();
    while (!tried_[c]);
    return c;
}

void ThreadTuner::stepTook(double seconds)
{
    ++stepsAt_[current_];
    if (!trying_) {
        settledFor_ += seconds;
        if (settledFor_ >= settleSeconds_) startTrial();
        return;
    }
    trialSeconds_ += seconds;
    if (skip_ > 0) {
        --skip_;
        return;
    }
    ++blockSteps_;
    blockWall_ += seconds;
    if (blockSteps_ < blockSteps || blockWall_ < blockWall) return;
    blockMeans_[current_].push_back(blockWall_ / double(blockSteps_));
    others_.push_back(otherTasks_ ? otherTasks_() : -1);
    const std::size_t next = nextTried(current_);
    if (next <= current_ && ++round_ == rounds) {  // wrapped: a round is done
        settle();
        return;
    }
    use(next);
}

void ThreadTuner::settle()
{
    // Threads beyond the cores other processes leave free wait at every barrier for the one
    // the scheduler has set aside; short blocks do not show it (the scheduler lets a newly
    // busy process run first), so those counts are not taken, whatever their blocks gave.
    std::vector<double> others(others_.begin(), others_.end());
    const int freeNow = freeCores(others.empty() ? -1 : static_cast<int>(median(others)));
    // The shortest median block among those; the first tried (the count in use before) on a
    // tie within 3 %.
    std::size_t best = candidates_.size();
    double bestTime = 0;
    for (std::size_t c = 0; c < candidates_.size(); ++c) {
        if (!tried_[c] || blockMeans_[c].empty() || (candidates_[c] > freeNow && candidates_[c] > 1)) continue;
        const double t = median(blockMeans_[c]);
        if (best == candidates_.size() || t < 0.97 * bestTime) best = c, bestTime = t;
    }
    if (best == candidates_.size()) best = candidates_.size() - 1;  // one thread
    trying_ = false;
    settledFor_ = 0;
    settleSeconds_ = std::max(minKeepWall, keepFactor * trialSeconds_);
    use(best);
}

int ThreadTuner::mostUsed() const
{
    const auto most = std::max_element(stepsAt_.begin(), stepsAt_.end()) - stepsAt_.begin();
    return candidates_[static_cast<std::size_t>(most)];
}

std::string ThreadTuner::summary() const
{
    long total = 0;
    for (long s : stepsAt_) total += s;
    std::vector<std::size_t> order(candidates_.size());
    for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return stepsAt_[a] > stepsAt_[b]; });
    std::ostringstream os;
    bool first = true;
    for (std::size_t c : order) {
        if (stepsAt_[c] == 0) continue;
        os << (first ? "" : ", ") << candidates_[c] << (first ? (candidates_[c] > 1 ? " threads" : " thread") : "")
           << " for " << std::lround(100.0 * double(stepsAt_[c]) / double(std::max(total, 1L))) << " %"
           << (first ? " of the steps" : "");
        first = false;
    }
    return os.str();
}

} // namespace gpic
