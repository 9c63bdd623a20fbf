#include "run/ToolForceWatch.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gpic {

template <int D>
ToolForceWatch<D>::ToolForceWatch(std::vector<std::string> names, std::vector<bool> rigid, std::string cure,
                                  Limits limits)
    : limits_(limits), cure_(std::move(cure))
{
    bodies_.resize(names.size());
    for (std::size_t b = 0; b < names.size(); ++b) {
        bodies_[b].name = std::move(names[b]);
        bodies_[b].watched = b < rigid.size() && rigid[b];
    }
}

template <int D> std::vector<std::string> ToolForceWatch<D>::add(double t, const std::vector<RigidBodyLoad<D>>& loads)
{
    std::vector<std::string> lines;
    if (loads.size() != bodies_.size()) return lines;
    if (windowStart_ < 0) windowStart_ = t;
    const bool closing = t - windowStart_ >= limits_.window;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        Body& b = bodies_[k];
        if (!b.watched || b.reported) continue;
        b.samples.push_back(loads[k].force);
        if (!closing) continue;
        std::string line = closeWindow(b);
        if (!line.empty()) lines.push_back(std::move(line));
    }
    if (closing) windowStart_ = t;
    return lines;
}

template <int D> std::string ToolForceWatch<D>::closeWindow(Body& b)
{
    Vector mean = Vector::Zero();
    for (const Vector& f : b.samples) mean += f;
    mean /= static_cast<double>(b.samples.size());
    const double size = mean.norm();
    double swing = -1;  // -1: a window without contact
    b.largestMean = std::max(b.largestMean, size);
    if (size > 0.1 * b.largestMean && size > 0) {
        const Vector u = mean / size;
        double squares = 0;
        for (const Vector& f : b.samples) squares += (f.dot(u) - size) * (f.dot(u) - size);
        swing = std::sqrt(squares / static_cast<double>(b.samples.size())) / size;
    }
    b.samples.clear();
    b.swings.push_back(swing);
    const std::size_t keep = static_cast<std::size_t>(limits_.persist + limits_.lookBack);
    while (b.swings.size() > keep) b.swings.pop_front();
    if (b.swings.size() < static_cast<std::size_t>(limits_.persist + 1)) return {};  // one window before them

    const auto recent = b.swings.end() - limits_.persist;
    if (!std::all_of(recent, b.swings.end(), [&](double s) { return s > limits_.swing; })) return {};
    double smallest = -1;
    for (auto it = b.swings.begin(); it != recent; ++it)
        if (*it >= 0 && (smallest < 0 || *it < smallest)) smallest = *it;
    if (smallest < 0 || *recent < limits_.growth * smallest) return {};
    b.reported = true;
    std::ostringstream line;
    line << std::setprecision(2) << "rigid body '" << b.name << "': its contact force swings by " << 100 * swing
         << " % (RMS) of its mean, up from " << 100 * smallest << " % in the "
         << limits_.window * static_cast<double>(b.swings.size() - static_cast<std::size_t>(limits_.persist))
         << " s before, and growing: energy is being made at the tool; " << cure_
         << " (doc/stability.md, \"Tools\")";
    return line.str();
}

template class ToolForceWatch<2>;
#if GPIC_WITH_3D
template class ToolForceWatch<3>;
#endif

} // namespace gpic
