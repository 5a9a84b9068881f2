// Paths that files name (a scene's models and sky faces, a model's buffers),
// resolved against the naming file's folder and kept inside it.
//
// A path is decoded by its caller (glTF URIs are percent-encoded), then
// resolved with every "..", "." and symbolic link followed; it is inside
// the folder when the result lies strictly below the folder's own resolved
// path. Comparing the strings as written would let "../x" or a link out of
// the folder through.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace swell::detail {

// `folder`, resolved: absolute, with links followed as far as they exist.
// Throws InputError naming `folder` when it cannot be resolved (a link loop).
std::filesystem::path resolvedFolder(const std::filesystem::path& folder);

// `path` (relative to `folder`, or absolute) resolved like resolvedFolder;
// nothing when it does not lie strictly below `folder`, which must already
// be resolved. Links that cannot be followed (a loop) are judged as written;
// opening the path then fails. Reads nothing but the links on the way, so a
// refusal says nothing about the file outside.
std::optional<std::filesystem::path> resolveInside(const std::filesystem::path& folder, const std::filesystem::path& path);

} // namespace swell::detail
