// GLSL programs built from the files in shaders/, with #include resolved by
// Swell (each file once per program) and #line directives so a compile error
// names the real file and line. Sources come from the copies embedded at build
// time, or from a folder on disk (the viewer's hot reload while developing).
#pragma once

#include "swell/gl/handle.h"

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace swell::gl {

class ShaderSources {
public:
    // The sources embedded in the library at build time.
    static ShaderSources embedded();
    // Sources read from a folder laid out like shaders/ (plus swell/shader_constants.h
    // looked up in includeDir). Files are read when first needed.
    static ShaderSources fromDirectory(std::filesystem::path shaderDir, std::filesystem::path includeDir);
    // In-memory sources, for tests.
    static ShaderSources fromMap(std::map<std::string, std::string> files);

    // Files read from disk are kept after their first read; this forgets them
    // so the next build reads them again (hot reload).
    void forgetCachedFiles() { cache_.clear(); }

    // The names of the files held in memory (embedded or given), sorted;
    // empty for sources read from a folder.
    std::vector<std::string> fileNames() const;

    // The text of one file. Throws swell::InputError when it does not exist.
    const std::string& file(const std::string& name) const;

    // The preprocessed source of `name`: "#version 450 core", then `defines`,
    // then the file with its includes expanded. fileNames receives the file
    // behind each #line source number.
    std::string expand(const std::string& name, const std::vector<std::string>& defines,
                       std::vector<std::string>& fileNames) const;

private:
    std::map<std::string, std::string> loaded_;
    std::filesystem::path shaderDir_, includeDir_;
    bool fromDisk_ = false;
    mutable std::map<std::string, std::string> cache_;
};

struct ShaderStage {
    GLenum stage;     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
    std::string file; // e.g. "water.vert"
};

// Compiles and links a program. Throws swell::InputError naming the shader
// file and line (through includes) with the driver's message on failure.
// transformFeedbackVaryings, when given, are captured interleaved.
Program buildProgram(const ShaderSources& sources, const std::vector<ShaderStage>& stages,
                     const std::vector<std::string>& defines = {},
                     const std::vector<std::string>& transformFeedbackVaryings = {});

// Rewrites a driver info log so that "0:12(5): error" reads "water.frag:12:5: error".
std::string mapInfoLog(const std::string& log, const std::vector<std::string>& fileNames);

} // namespace swell::gl
