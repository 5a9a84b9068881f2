// Regular files only, opened so that they cannot block (see input_file.h).
#include "core/input_file.h"

#include "swell/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swell::detail {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& message)
{
    throw InputError({path.string()}, message);
}

// What a file of this mode is, for the message; empty for a regular file.
std::string kindOf(mode_t mode)
{
    if (S_ISREG(mode))
        return {};
    if (S_ISDIR(mode))
        return "a folder";
    if (S_ISFIFO(mode))
        return "a FIFO (named pipe)";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

[[noreturn]] void failNotRegular(const std::filesystem::path& path, const std::string& what, mode_t mode)
{
    fail(path, fmt::format("cannot read the {}: it is {}, not a regular file", what, kindOf(mode)));
}

// Why stat() or open() failed, in the user's terms.
[[noreturn]] void failErrno(const std::filesystem::path& path, const std::string& what, int error)
{
    struct stat link {};
    if (error == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
        fail(path, fmt::format("cannot read the {}: it is a symbolic link to a file that does not exist", what));
    if (error == ENOENT || error == ENOTDIR)
        fail(path, fmt::format("{} not found", what));
    if (error == ELOOP)
        fail(path, fmt::format("cannot read the {}: its symbolic links form a loop", what));
    fail(path, fmt::format("cannot read the {}: {}", what, std::strerror(error)));
}

// An open descriptor, closed on every way out.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor()
    {
        if (fd_ >= 0)
            ::close(fd_);
    }
    Descriptor(Descriptor&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    Descriptor& operator=(Descriptor&&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

// Opens `path` for reading after checking, before and after the open, that it is a regular file.
Descriptor openRegular(const std::filesystem::path& path, const std::string& what, struct stat& info)
{
    // Before: a FIFO or device is never opened at all (opening some devices has effects).
    if (::stat(path.c_str(), &info) != 0)
        failErrno(path, what, errno);
    if (!S_ISREG(info.st_mode))
        failNotRegular(path, what, info.st_mode);
    // After: the path may have been replaced in between; O_NONBLOCK keeps a
    // FIFO's open from waiting, and fstat sees what was really opened.
    Descriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0)
        failErrno(path, what, errno);
    if (::fstat(fd.get(), &info) != 0)
        failErrno(path, what, errno);
    if (!S_ISREG(info.st_mode))
        failNotRegular(path, what, info.st_mode);
    return fd;
}

} // namespace

void checkInputFile(const std::filesystem::path& path, const std::string& what)
{
    struct stat info {};
    (void)openRegular(path, what, info);
}

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const std::string& what)
{
    struct stat info {};
    const Descriptor fd = openRegular(path, what, info);
    if (std::uintmax_t(info.st_size) > maxBytes)
        fail(path, fmt::format("the {} is {} bytes; at most {} are allowed", what, info.st_size, maxBytes));
    // Read at most one byte past the limit whatever the size said: the file may grow.
    std::string bytes;
    bytes.reserve(std::size_t(info.st_size));
    char buffer[64 * 1024];
    while (bytes.size() <= maxBytes) {
        const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            failErrno(path, what, errno);
        if (n == 0)
            break;
        bytes.append(buffer, std::size_t(n));
    }
    if (bytes.size() > maxBytes)
        fail(path, fmt::format("the {} is over {} bytes; at most {} are allowed", what, maxBytes, maxBytes));
    return bytes;
}

} // namespace swell::detail
