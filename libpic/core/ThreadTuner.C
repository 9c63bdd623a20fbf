#include "core/ThreadTuner.H"

#include <algorithm>
#include <cmath>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace gpic {

namespace {
// A trial: at least this many steps and this much wall, so that the median is of enough
// steps and a scheduler's time slice (a few ms) is small against it.
constexpr long trialSteps = 8;
constexpr double trialWall = 0.05;    // s
constexpr long warmUpSteps = 2;       // after a change of count
constexpr double keepFactor = 30;     // the choice is kept 30 times as long as its trials
constexpr double minKeepWall = 3.0;   // s, at least

double median(std::vector<double> v)
{
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(mid), v.end());
    return v[mid];
}
} // namespace

ThreadTuner::ThreadTuner(int maxThreads)
{
    for (int n = std::max(1, maxThreads); n > 1; n /= 2) candidates_.push_back(n);
    candidates_.push_back(1);
    stepsAt_.assign(candidates_.size(), 0);
    median_.assign(candidates_.size(), 0.0);
    if (candidates_.size() == 1) trying_ = false;
    use(0);
}

void ThreadTuner::use(std::size_t candidate)
{
    current_ = candidate;
#ifdef _OPENMP
    omp_set_num_threads(candidates_[candidate]);
#endif
    skip_ = warmUpSteps;
    window_.clear();
}

void ThreadTuner::stepTook(double seconds)
{
    ++stepsAt_[current_];
    if (!trying_) {
        settledFor_ += seconds;
        if (settledFor_ < settleSeconds_) return;
        // Try again, from the count in use: its time now is the reference.
        trying_ = true;
        trialSeconds_ = 0;
        std::rotate(candidates_.begin(), candidates_.begin() + static_cast<long>(current_), candidates_.end());
        std::rotate(stepsAt_.begin(), stepsAt_.begin() + static_cast<long>(current_), stepsAt_.end());
        trial_ = 0;
        use(0);
        return;
    }
    trialSeconds_ += seconds;
    if (skip_ > 0) {
        --skip_;
        return;
    }
    window_.push_back(seconds);
    double wall = 0;
    for (double s : window_) wall += s;
    if (static_cast<long>(window_.size()) < trialSteps || wall < trialWall) return;
    median_[trial_] = median(window_);
    if (++trial_ < candidates_.size()) use(trial_);
    else settle();
}

void ThreadTuner::settle()
{
    // The shortest median; the first candidate (the count in use before) on a tie within 3 %.
    std::size_t best = 0;
    for (std::size_t c = 1; c < candidates_.size(); ++c)
        if (median_[c] < 0.97 * median_[best]) best = c;
    trying_ = false;
    settledFor_ = 0;
    settleSeconds_ = std::max(minKeepWall, keepFactor * trialSeconds_);
    if (best != current_) use(best);
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
