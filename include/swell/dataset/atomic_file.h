// Writing a file so that it is either whole or not there: a temporary file
// in the same folder, flushed to disk, then renamed over the target (a
// symbolic link's target, not the link). A crash or a full disk at any
// point leaves the old file, or none, never a half-written one.
#pragma once

#include "swell/export.h"

#include <filesystem>
#include <string_view>

namespace swell {

// Throws swell::Error naming `path` and the system's reason on failure
// (the temporary file removed).
SWELL_API void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace swell
