// A text file compiled into the library (see cmake/EmbedFiles.cmake).
#pragma once

#include <span>
#include <string_view>

namespace swell::detail {

struct EmbeddedFile {
    std::string_view path; // relative to the shaders/ folder, '/'-separated
    std::string_view text;
};

// The GLSL sources, the constants headers they share with C++ (swell/gpu/*.h)
// and the files generated from C++ (gpu/*.glsl), as they were at build time.
std::span<const EmbeddedFile> embeddedShaderFiles();

// The built-in models' glTF files (relative to assets/models/), as
// assets/models/make_models.py wrote them.
std::span<const EmbeddedFile> embeddedModelFiles();

} // namespace swell::detail
