#include "io/DataRows.H"

#include "io/AtomicFile.H"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace gpic {

namespace {
//- Is a row of printed time `t` at or before `time`? The rows print 12 significant digits:
//  the row of the restart's own step may read back a few units of its last digit above it.
bool notAfter(double t, double time)
{
    return t <= time || (std::isfinite(time) && t - time <= 1e-11 * std::abs(time));
}
} // namespace

std::size_t keepRowsUpTo(const std::string& path, double time)
{
    std::string text;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) return 0;
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::size_t keep = 0;  // bytes kept
    std::size_t dropped = 0;
    bool cut = false;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        const bool whole = end != std::string::npos;
        const std::string line = text.substr(at, whole ? end - at : std::string::npos);
        const std::size_t next = whole ? end + 1 : text.size();
        if (!cut) {
            if (whole && (line.empty() || line[0] == '#')) {
                keep = next;
            } else {
                char* stop = nullptr;
                const double t = std::strtod(line.c_str(), &stop);
                const bool timed = stop != line.c_str() && std::isfinite(t);
                if (whole && timed && notAfter(t, time))
                    keep = next;
                else
                    cut = true;  // the rows are in time order: every later one goes too
            }
        }
        if (cut && !line.empty() && line[0] != '#') ++dropped;
        at = next;
    }
    if (keep == text.size()) return 0;
    detail::AtomicFile out(path, "the rows up to t = " + std::to_string(time) + " s");
    out.write(text.data(), keep);
    out.commit();
    return dropped;
}

} // namespace gpic
