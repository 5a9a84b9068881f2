// Scene files: TOML in, swell::Scene out, and back. The format is described
// in docs/SCENE.md; the keys, units and ranges of the values come from the
// parameter table (swell/scene/parameters.h).
//
// Loading is all or nothing: a scene that loads is valid in every field
// (ranges, cross-field rules, referenced files, the wave set), so the
// renderer never has to half-render. Any problem throws swell::InputError
// whose place is the file, line and column of the offending key or value.
#pragma once

#include "swell/export.h"

#include "swell/gpu/limits.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace swell {

// Larger inputs are refused before parsing: a real scene is a few KiB, and
// the cap bounds the parser's time and memory on whatever it is handed.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{4} << 20; // 4 MiB

// Longest arrays a scene file may hold. Waves are capped by the shader's
// uniform block (SWELL_MAX_WAVES), objects by kMaxSceneObjects
// (swell/scene/parameters.h); camera keys by what stays interactive: each is a
// line of the file.
inline constexpr std::size_t kMaxCameraKeys = 10000;

// Structural limits checked before the TOML parser sees the text, because
// its recursion depth follows them: dotted parts in one key or table header
// ("waves.wind.speed_mps" has 3), and [ ] / { } nested inside one value.
inline constexpr int kMaxSceneKeyParts = 8;
inline constexpr int kMaxSceneNesting = 16;
// Also checked before parsing, because the parser builds a node for each
// before the limits above can be applied: entries of one [ ] array (the
// longest list a scene holds), and [[...]] headers in the file (every list
// at its longest, together).
inline constexpr std::size_t kMaxSceneArrayItems = kMaxCameraKeys;
inline constexpr int kMaxSceneTableArrayHeaders = int(kMaxCameraKeys + kMaxSceneObjects) + SWELL_MAX_WAVES;

// Reads and validates the scene file at `path`. Relative object paths and
// sky cubemap faces are resolved against the file's folder.
// Throws InputError: missing, unreadable, too large, not UTF-8 TOML, or any
// invalid content (see parseScene).
SWELL_API Scene loadScene(const std::filesystem::path& path);

// Parses and validates scene TOML held in memory. `virtualPath` is used for
// error places and as the base for relative paths in the file (its folder;
// the working directory when it has none); it need not exist.
// Throws InputError for syntax errors, unknown keys (with a suggestion when
// one is close), wrong types, values out of range or not finite, broken
// cross-field rules, referenced files that are missing or unreadable, unknown
// built-in objects, arrays over their limits, and wave sets that fail
// validate().
SWELL_API Scene parseScene(std::string_view toml, const std::filesystem::path& virtualPath);

// The checks parseScene makes after reading, for a scene built in code (the
// viewer's edits): every parameter in range, the cross-field rules, the
// referenced files relative to `sceneFile`'s folder, the wave set. Throws
// InputError naming the key, at its place in Scene::keyPlaces when the
// scene has one (a loaded scene, a sweep's sample), else at `sceneFile`
// with no line.
SWELL_API void validateScene(const Scene& scene, const std::filesystem::path& sceneFile);

// validateScene() for an edit of `before` (already valid) into `after`, as a
// viewer's slider makes: values and rules always, but the files the scene
// names only when sceneChanges() says the world changed, and the wave set only
// when the waves did, so a slider tick neither touches the disk nor
// generates waves.
SWELL_API void validateSceneChange(const Scene& before, const Scene& after, const std::filesystem::path& sceneFile);

// The scene as TOML that parseScene reads back to an equal scene. Every
// parameter is written, with its unit and range in a comment. When the wind
// is set the listed waves are not written (the wind replaces them).
SWELL_API std::string saveScene(const Scene& scene);

// Writes saveScene(scene) to `path` atomically: to a temporary file in the
// same folder, flushed to disk, then renamed over `path`, so a failure leaves
// any existing file untouched. Relative paths inside the scene are written
// as they are, so save next to the original to keep them valid.
// Throws InputError naming `path` when it cannot be written.
SWELL_API void saveSceneFile(const Scene& scene, const std::filesystem::path& path);

} // namespace swell
