#include "run/WriteBudget.H"

#include "core/ByteSize.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "time/TimeControl.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include <sys/statvfs.h>

namespace gpic {

namespace fs = std::filesystem;

namespace {
//- The bytes of the regular files under `dir`.
double directoryBytes(const fs::path& dir)
{
    double bytes = 0;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_regular_file(ec)) bytes += static_cast<double>(it->file_size(ec));
    return bytes;
}
} // namespace

void checkWriteBudget(const TimeControl& control, const Dictionary& controlDict, double t, double deltaT,
                      const std::string& caseDir, const std::string& startName)
{
    const std::string& writeControl = control.writeControl();
    const double interval = control.writeInterval();
    const int line = controlDict.lineOf("writeInterval");
    std::ostringstream what;
    what << "writeControl " << writeControl << ", writeInterval " << interval;
    if (writeControl != "timeStep" && interval < deltaT) {
        std::ostringstream os;
        os << "writeInterval " << interval << " s is shorter than the time step " << deltaT << " s: "
           << (writeControl == "runTime" ? "every step is written"
                                         : "every step is cut to writeInterval and written");
        warning(controlDict.fileName(), line, os.str());
    }
    if (!control.hasEndTime() || !(deltaT > 0)) return;
    const double span = std::max(control.endTime() - t, 0.0);
    const double writes = writeControl == "timeStep"        ? span / deltaT / interval
                          : writeControl == "runTime"       ? span / std::max(interval, deltaT)
                                                            : span / interval;
    if (!(writes > maxTimeDirectories)) return;
    const double each = directoryBytes(fs::path(caseDir) / startName);
    const int purge = control.purgeWrite();
    const double kept = purge > 0 ? std::min(writes, static_cast<double>(purge)) : writes;
    std::ostringstream os;
    os << std::fixed << std::setprecision(0) << "the run would write about " << writes << " time directories (" << what.str() << ") of about "
       << byteSize(each) << " each";
    if (purge > 0)
        os << ", of which purgeWrite keeps " << purge << " (" << byteSize(kept * each) << ")";
    else
        os << ": " << byteSize(kept * each) << " in all";
    struct statvfs fsStat {};
    if (::statvfs(caseDir.c_str(), &fsStat) == 0) {
        const double free = static_cast<double>(fsStat.f_bavail) * static_cast<double>(fsStat.f_frsize);
        if (kept * each > free)
            throw InputError(controlDict.fileName(), line,
                             os.str() + ", more than the " + byteSize(free) + " free on " + caseDir +
                                 "'s file system: raise writeInterval or set purgeWrite");
    }
    warning(controlDict.fileName(), line, os.str() + ": raise writeInterval or set purgeWrite if that is more than meant");
}

} // namespace gpic
