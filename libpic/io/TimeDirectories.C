#include "io/TimeDirectories.H"

#include "core/error.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace fs = std::filesystem;

namespace gpic {

namespace {

//- The value of a name that is wholly a finite number (strtod, nothing left over).
bool parseTime(const std::string& name, double& value)
{
    if (name.empty() || std::isspace(static_cast<unsigned char>(name.front()))) return false;
    char* end = nullptr;
    value = std::strtod(name.c_str(), &end);
    return end == name.c_str() + name.size() && std::isfinite(value);
}

bool sameTime(double a, double b)
{
    return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

[[noreturn]] void fsFailure(const std::string& what, const fs::path& path,
                            const std::error_code& ec)
{
    throw RunError("cannot " + what + " " + path.string() + ": " + ec.message());
}

} // namespace

std::string timeName(double t, int precision)
{
    if (t == 0.0) return "0";  // also for -0.0
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, t);
    return buffer;
}

std::vector<std::pair<double, std::string>> listTimeDirectories(const std::string& caseDir)
{
    std::error_code ec;
    if (!fs::is_directory(caseDir, ec))
        throw InputError(caseDir, 0, "case directory does not exist");
    std::vector<std::pair<double, std::string>> times;
    for (fs::directory_iterator it(caseDir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name.front() == '.') continue;  // hidden, and our .tmp/.old
        if (name == "constant" || name == "system" || name == "postProcessing") continue;
        std::error_code dirEc;
        if (!it->is_directory(dirEc)) continue;
        double value = 0.0;
        if (parseTime(name, value)) times.emplace_back(value, name);
    }
    if (ec) throw InputError(caseDir, 0, "cannot list case directory: " + ec.message());
    std::sort(times.begin(), times.end());
    return times;
}

std::string latestTime(const std::string& caseDir)
{
    const auto times = listTimeDirectories(caseDir);
    if (times.empty())
        throw InputError(caseDir, 0, "no time directories (such as 0/) in the case directory");
    return times.back().second;
}

std::string findTime(const std::string& caseDir, double t)
{
    const auto times = listTimeDirectories(caseDir);
    const std::pair<double, std::string>* best = nullptr;
    for (const auto& entry : times)
        if (!best || std::abs(entry.first - t) < std::abs(best->first - t)) best = &entry;
    if (best && sameTime(best->first, t)) return best->second;

    std::ostringstream message;
    // The shortest name that reads back as t: "-time 0.3" is reported as 0.3.
    int digits = 6;
    while (digits < 17 && std::strtod(timeName(t, digits).c_str(), nullptr) != t) ++digits;
    message << "no time directory for time " << timeName(t, digits) << "; available times:";
    if (times.empty()) message << " none";
    for (const auto& entry : times) message << ' ' << entry.second;
    throw InputError(caseDir, 0, message.str());
}

void writeTimeDirectoryAtomically(const std::string& caseDir, const std::string& name,
                                  const std::function<void(const std::string& tmpDir)>& fill)
{
    if (name.empty() || name.find('/') != std::string::npos)
        throw std::invalid_argument("writeTimeDirectoryAtomically: bad name '" + name + "'");
    const fs::path base(caseDir);
    const fs::path tmp = base / ("." + name + ".tmp");
    const fs::path old = base / ("." + name + ".old");
    const fs::path final = base / name;
    std::error_code ec;

    // A leftover from a run that died here is stale: start fresh.
    fs::remove_all(tmp, ec);
    if (ec) fsFailure("remove", tmp, ec);
    fs::create_directories(tmp, ec);
    if (ec) fsFailure("create", tmp, ec);

    try {
        fill(tmp.string());
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }

    // Move the earlier directory aside rather than deleting it first, so some complete copy
    // exists at every moment.
    const bool replacing = fs::exists(final, ec);
    if (replacing) {
        fs::remove_all(old, ec);
        fs::rename(final, old, ec);
        if (ec) {
            std::error_code ignore;
            fs::remove_all(tmp, ignore);
            fsFailure("move aside", final, ec);
        }
    }
    fs::rename(tmp, final, ec);
    if (ec) {
        std::error_code ignore;
        if (replacing) fs::rename(old, final, ignore);
        fs::remove_all(tmp, ignore);
        fsFailure("rename " + tmp.string() + " to", final, ec);
    }
    if (replacing) fs::remove_all(old, ec);  // a leftover .old is hidden and harmless
}

void removeTimeDirectory(const std::string& caseDir, const std::string& name)
{
    double value = 0.0;
    if (!parseTime(name, value))
        throw std::invalid_argument("removeTimeDirectory: '" + name + "' is not a time name");
    const fs::path dir = fs::path(caseDir) / name;
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (ec) fsFailure("remove", dir, ec);
}

} // namespace gpic
