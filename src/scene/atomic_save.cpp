// Writing a file atomically (swell/dataset/atomic_file.h), and saving a scene file
// with it (saveSceneFile in swell/scene/scene_file.h).
#include "swell/dataset/atomic_file.h"
#include "swell/scene/scene_file.h"

#include "scene/places.h"
#include "swell/error.h"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swell {

using detail::scenefile::fail;
namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& path, std::string_view text)
{
    // Write next to the file a symbolic link points at, not over the link.
    std::error_code ec;
    fs::path target = path;
    if (fs::is_symlink(path, ec)) {
        fs::path resolved = fs::canonical(path, ec);
        if (!ec)
            target = resolved;
    }
    fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    static std::atomic<unsigned> counter{0};
    fs::path temp = folder / fmt::format(".{}.{}-{}.tmp", target.filename().string(), ::getpid(), counter++);

    auto failWith = [&](int error, int fd) {
        if (fd >= 0)
            ::close(fd);
        ::unlink(temp.c_str());
        throw Error(fmt::format("cannot write {}: {}", path.string(), std::strerror(error)));
    };

    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        throw Error(fmt::format("cannot write {}: {} ({})", path.string(), std::strerror(errno), temp.string()));
    // Keep the permissions of the file being replaced.
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0)
        ::fchmod(fd, existing.st_mode & 07777);

    for (std::size_t written = 0; written < text.size();) {
        ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            failWith(n < 0 ? errno : EIO, fd);
        written += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0)
        failWith(errno, fd);
    if (::close(fd) != 0)
        failWith(errno, -1);
    if (::rename(temp.c_str(), target.c_str()) != 0)
        failWith(errno, -1);
    // Make the rename itself durable; a failure here loses nothing already written.
    int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

void saveSceneFile(const Scene& scene, const fs::path& path)
{
    try {
        writeFileAtomically(path, saveScene(scene));
    } catch (const Error& e) {
        fail({path.string(), 0, 0}, fmt::format("cannot save the scene: {}", e.what()));
    }
}

} // namespace swell
