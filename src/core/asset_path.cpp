// Resolving paths inside a folder (see asset_path.h).
#include "core/asset_path.h"

#include "swell/error.h"

namespace swell::detail {

namespace fs = std::filesystem;

fs::path resolvedFolder(const fs::path& folder)
{
    std::error_code ec;
    fs::path absolute = fs::absolute(folder.empty() ? fs::path(".") : folder, ec);
    fs::path resolved = ec ? fs::path() : fs::weakly_canonical(absolute, ec);
    if (ec)
        throw InputError({folder.string()}, "cannot resolve the folder: " + ec.message());
    return resolved;
}

std::optional<fs::path> resolveInside(const fs::path& folder, const fs::path& path)
{
    std::error_code ec;
    const fs::path joined = path.is_absolute() ? path : folder / path;
    fs::path resolved = fs::weakly_canonical(joined, ec);
    // Links that cannot be followed (a loop) lead nowhere: judge the path as
    // written, and let opening it report the loop.
    if (ec || resolved.empty())
        resolved = joined.lexically_normal();
    const fs::path relative = resolved.lexically_relative(folder);
    if (relative.empty() || relative == "." || *relative.begin() == "..")
        return std::nullopt;
    return resolved;
}

} // namespace swell::detail
