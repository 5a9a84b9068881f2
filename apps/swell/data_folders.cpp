#include "data_folders.h"

#include <cstdlib>
#include <system_error>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

// The running executable's folder ("" when /proc is not mounted).
fs::path executableFolder()
{
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    return error ? fs::path() : self.parent_path();
}

} // namespace

DataFolders dataFolders()
{
    const fs::path bin = executableFolder();
    // bin/../share/swell, as install(DIRECTORY ... DESTINATION share/swell) lays it out.
    const fs::path share = bin.empty() ? fs::path() : bin.parent_path() / "share" / "swell";
    std::error_code error;
    if (!share.empty() && fs::is_directory(share / "scenes", error))
        return {share / "scenes", share / "models", share / "shaders", share / "include", true};
    const fs::path source = SWELL_SOURCE_DIR;
    return {source / "scenes", source / "assets" / "models", source / "shaders", source / "include", false};
}

void nameTheDerivedDataCache()
{
    if (std::getenv("SWELL_CACHE_DIR") != nullptr)
        return;
    fs::path folder;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg == '/')
        folder = fs::path(xdg) / "swell";
    else if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/')
        folder = fs::path(home) / ".cache" / "swell";
    else
        return;
    // Before any thread reads the environment: the first thing main() does.
    ::setenv("SWELL_CACHE_DIR", folder.c_str(), 0);
}

} // namespace swell::app
