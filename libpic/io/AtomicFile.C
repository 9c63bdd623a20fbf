#include "io/AtomicFile.H"

#include "core/error.H"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace gpic {
namespace detail {

namespace {
constexpr std::size_t bufferBytes = 1 << 18;
}

AtomicFile::AtomicFile(std::string path, std::string what)
    : path_(std::move(path)), tmp_(path_ + ".tmp"), what_(std::move(what))
{
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) fail(errno);
    buffer_.resize(bufferBytes);
}

AtomicFile::~AtomicFile()
{
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) {
        std::error_code ec;
        std::filesystem::remove(tmp_, ec);
    }
}

void AtomicFile::write(const void* data, std::size_t bytes)
{
    const auto* c = static_cast<const unsigned char*>(data);
    while (bytes > 0) {
        if (buffered_ == buffer_.size()) flush();
        const std::size_t take = std::min(bytes, buffer_.size() - buffered_);
        std::memcpy(buffer_.data() + buffered_, c, take);
        buffered_ += take;
        c += take;
        bytes -= take;
    }
}

void AtomicFile::flush()
{
    std::size_t done = 0;
    while (done < buffered_) {
        const ssize_t n = ::write(fd_, buffer_.data() + done, buffered_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(n < 0 ? errno : ENOSPC);
        done += static_cast<std::size_t>(n);
    }
    buffered_ = 0;
}

void AtomicFile::commit()
{
    flush();
    const int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0) fail(errno);
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) fail(ec.value());
    committed_ = true;
}

void AtomicFile::fail(int error)
{
    // A full disk is what the user must hear of, with where (before the partial file goes).
    std::error_code ec;
    const auto space = std::filesystem::space(std::filesystem::path(tmp_).parent_path(), ec);
    const bool full = error == ENOSPC || error == EDQUOT || (!ec && space.available < 4096);
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    std::filesystem::remove(tmp_, ec);
    committed_ = true;  // nothing left to remove
    throw RunError("cannot write " + what_ + " to " + path_ + ": " +
                   (full ? std::string("no space left on device") : std::strerror(error)));
}

} // namespace detail
} // namespace gpic
