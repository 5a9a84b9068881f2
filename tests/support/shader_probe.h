// A compute program that calls the shaders' own functions, for tests that
// hold a GLSL model to its C++ twin or to a formula: `text` becomes
// "probe.comp", and may include any of the embedded shader files. Needs a
// current GL 4.5 context.
#pragma once

#include "swell/gl/shader.h"
#include "swell/gl/shader_sources.h"

#include <map>
#include <string>
#include <vector>

namespace swell::test {

inline gl::Program buildShaderProbe(const char* text, const std::vector<std::string>& defines = {})
{
    const gl::ShaderSources embedded = gl::ShaderSources::embedded();
    std::map<std::string, std::string> files;
    for (const std::string& name : embedded.fileNames())
        files[name] = embedded.file(name);
    files["probe.comp"] = text;
    return gl::buildProgram(gl::ShaderSources::fromMap(files), {{GL_COMPUTE_SHADER, "probe.comp"}}, defines);
}

} // namespace swell::test
