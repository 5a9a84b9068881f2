// A compute program that calls the shaders' own functions, for tests that
// hold a GLSL model to its C++ twin or to a formula: `text` becomes
// "probe.comp", and may include any of the embedded shader files. Needs a
// current GL 4.5 context.
#pragma once

#include "swell/gl/handle.h"
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

// Runs `program` in `groups` work groups over `in` (the shader storage
// buffer at binding 0) and reads back `outCount` values from the one at
// binding 1. Leaves no program or buffer bound.
template <class In, class Out>
std::vector<Out> runShaderProbe(const gl::Program& program, const std::vector<In>& in, size_t outCount, GLuint groups)
{
    gl::Buffer input = gl::Buffer::create(), output = gl::Buffer::create();
    glNamedBufferData(input.id(), GLsizeiptr(in.size() * sizeof(In)), in.data(), GL_STATIC_DRAW);
    glNamedBufferData(output.id(), GLsizeiptr(outCount * sizeof(Out)), nullptr, GL_DYNAMIC_READ);
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<Out> out(outCount);
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(outCount * sizeof(Out)), out.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
    return out;
}

} // namespace swell::test
