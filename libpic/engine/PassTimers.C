#include "engine/PassTimers.H"

#include <cstdio>

namespace gpic {

double PassTimers::seconds(const std::string& pass) const
{
    auto it = seconds_.find(pass);
    return it == seconds_.end() ? 0.0 : it->second;
}

double PassTimers::total() const
{
    double sum = 0;
    for (const auto& [name, s] : seconds_) sum += s;
    return sum;
}

void PassTimers::print(std::ostream& os) const
{
    const double all = total();
    os << "Time per pass:\n";
    char line[128];
    for (const auto& [name, s] : seconds_) {
        std::snprintf(line, sizeof line, "    %-18s %10.3f s  %5.1f %%\n", name.c_str(), s,
                      all > 0 ? 100.0 * s / all : 0.0);
        os << line;
    }
}

} // namespace gpic
