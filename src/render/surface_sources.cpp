#include "render/surface_sources.h"

#include "swell/error.h"
#include "swell/shader_constants.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <array>

namespace swell::detail {

void setSurfaceSourceFiles(gl::ShaderSources& sources, const std::vector<std::string>& codes)
{
    if (codes.size() > SWELL_MAX_SURFACE_SOURCES)
        throw Error(fmt::format("{} surface sources: at most {} are drawn", codes.size(), SWELL_MAX_SURFACE_SOURCES));
    std::string sum = R"(// Written by the renderer from its surface sources (src/render/surface_sources.h).
#ifndef SWELL_SURFACE_SOURCES_GLSL
#define SWELL_SURFACE_SOURCES_GLSL
#include "swell/shader_constants.h"

layout(std140, binding = SWELL_BINDING_SURFACE_SOURCES) uniform SurfaceSources {
    vec4 surfaceSourceParameters[SWELL_MAX_SURFACE_SOURCES * 4];
};

)";
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const std::string file = fmt::format("surface_source_{}.glsl", i);
        sources.set(file, codes[i]);
        sum += fmt::format("#define SWELL_SOURCE_FUNCTION surfaceSource{}\n#include \"{}\"\n#undef SWELL_SOURCE_FUNCTION\n",
                           i, file);
    }
    sum += R"(
// The sources' sum at p_m (relative to the render origin): height m, dh/dx, dh/dz, foam 0..1.
vec4 surfaceSourcesAt(vec2 p_m)
{
    vec4 sum = vec4(0.0);
)";
    for (std::size_t i = 0; i < codes.size(); ++i)
        sum += fmt::format("    {{\n        vec4 s = surfaceSource{0}(p_m, vec4[4](surfaceSourceParameters[{1}], "
                           "surfaceSourceParameters[{2}], surfaceSourceParameters[{3}], surfaceSourceParameters[{4}]));\n"
                           "        sum = vec4(sum.xyz + s.xyz, max(sum.w, s.w));\n    }}\n",
                           i, 4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3);
    sum += "    return sum;\n}\n#endif\n";
    sources.set("surface_sources.glsl", sum);
}

void SurfaceSourceParametersBuffer::upload(const std::vector<std::shared_ptr<const SurfaceSource>>& sources, double time_s,
                                        glm::dvec3 renderOrigin_m)
{
    std::array<glm::vec4, SWELL_MAX_SURFACE_SOURCES * 4> parameters{};
    for (std::size_t i = 0; i < sources.size() && i < SWELL_MAX_SURFACE_SOURCES; ++i) {
        const SurfaceSourceParameters p = sources[i]->gpuParameters(time_s, renderOrigin_m);
        for (std::size_t k = 0; k < 4; ++k)
            parameters[4 * i + k] = p[k];
    }
    if (!buffer_) {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), sizeof(parameters), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(buffer_.id(), 0, sizeof(parameters), parameters.data());
    bind();
}

void SurfaceSourceParametersBuffer::bind() const
{
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_SURFACE_SOURCES, buffer_.id());
}

} // namespace swell::detail
