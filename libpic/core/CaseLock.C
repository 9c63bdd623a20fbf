#include "core/CaseLock.H"

#include "core/error.H"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gpic {

namespace {
//- What a lock file says of its holder ("picSolver, process 123 on host h"); "" if nothing.
std::string holder(int fd)
{
    char text[512] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    if (n <= 0) return "";
    std::string s(text, static_cast<std::size_t>(n));
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

std::string hostName()
{
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}
} // namespace

std::string CaseLock::path(const std::string& caseDir)
{
    return (std::filesystem::path(caseDir) / ".picLock").string();
}

CaseLock::CaseLock(const std::string& caseDir, const std::string& application) : path_(path(caseDir))
{
    // Another process may remove the file (its holder ending) between our open and our lock:
    // the lock must be on the file that is at the path when we hold it, so look again.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
            throw RunError("cannot make the case's lock file " + path_ + ": " + std::strerror(errno));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            const std::string who = holder(fd);
            ::close(fd);
            if (error == EWOULDBLOCK)
                throw InputError(path_, 0, "the case is in use by " + (who.empty() ? "another process" : who) +
                                               ": wait for it to end, or stop it first");
            throw RunError("cannot lock the case's lock file " + path_ + ": " + std::strerror(error));
        }
        struct stat held {}, there {};
        if (::fstat(fd, &held) != 0 || ::stat(path_.c_str(), &there) != 0 || held.st_ino != there.st_ino ||
            held.st_dev != there.st_dev) {
            ::close(fd);  // removed by its holder meanwhile: take the new one
            continue;
        }
        if (const std::string stale = holder(fd); !stale.empty())
            warning(path_, 0, "taking over the stale lock of " + stale + ": that process is gone (killed or crashed)");
        const std::string me =
            application + ", process " + std::to_string(::getpid()) + " on host " + hostName() + "\n";
        if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
            const int error = errno;
            ::close(fd);
            throw RunError("cannot write the case's lock file " + path_ + ": " + std::strerror(error));
        }
        fd_ = fd;
        return;
    }
    throw RunError("cannot lock the case: its lock file " + path_ + " keeps changing");
}

CaseLock::~CaseLock()
{
    if (fd_ < 0) return;
    // Removed while still held: a process waiting to lock the old file looks again.
    ::unlink(path_.c_str());
    ::close(fd_);
}

} // namespace gpic
