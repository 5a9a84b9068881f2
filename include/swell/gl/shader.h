// GLSL programs built from the files in shaders/, with #include resolved by
// Swell (each file once per program) and #line directives so a compile error
// names the real file and line. Sources come from the copies embedded at build
// time, or from a folder on disk (the viewer's hot reload while developing).
#pragma once

#include "swell/export.h"

#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace swell::gl {

struct SWELL_API ShaderStage {
    GLenum stage;     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
    std::string file; // e.g. "water.vert"
};

// Compiles and links a program. Throws swell::InputError naming the shader
// file and line (through includes) with the driver's message on failure.
// transformFeedbackVaryings, when given, are captured interleaved.
SWELL_API Program buildProgram(const ShaderSources& sources, const std::vector<ShaderStage>& stages,
                     const std::vector<std::string>& defines = {},
                     const std::vector<std::string>& transformFeedbackVaryings = {});

// Rewrites a driver info log so that "0:12(5): error" reads "water.frag:12:5: error".
SWELL_API std::string mapInfoLog(const std::string& log, const std::vector<std::string>& fileNames);

} // namespace swell::gl
