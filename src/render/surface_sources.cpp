#include "render/surface_sources.h"

#include "ocean/foam/foam_texture.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/ocean.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <array>
#include <cmath>

namespace swell::detail {

void setSurfaceSourceFiles(gl::ShaderSources& sources, const std::vector<std::string>& codes)
{
    if (codes.size() > SWELL_MAX_SURFACE_SOURCES)
        throw Error(fmt::format("{} surface sources: at most {} are drawn", codes.size(), SWELL_MAX_SURFACE_SOURCES));
    std::string sum = R"(// Written by the renderer from its surface sources (src/render/surface_sources.h).
#ifndef SWELL_SURFACE_SOURCES_GLSL
#define SWELL_SURFACE_SOURCES_GLSL
// What a source's code may use besides its parameters: the ocean's shared
// constants and swell/constants.h's.
#include "swell/gpu/ocean.h"
#include "gpu/constants.glsl"
#include "whitecap_foam.glsl"

// The sources' parameters, and their foam's texture: the whitecaps'
// lattices anchored to the world at the render origin (p_m = 0), not drawn
// out along any wind (swell::detail::SurfaceSourcesUniforms, src/render/gpu/blocks.h).
#include "gpu/surface_sources_block.glsl"

)";
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const std::string file = fmt::format("surface_source_{}.glsl", i);
        sources.set(file, codes[i]);
        sum += fmt::format("#define SWELL_SOURCE_FUNCTION surfaceSource{}\n#include \"{}\"\n#undef SWELL_SOURCE_FUNCTION\n",
                           i, file);
    }
    sum += R"(
// The sources' sum at p_m (relative to the render origin): height m, dh/dx,
// dh/dz, and the amount of foam, 0..1 (the largest; water.frag gives it the
// whitecaps' look with sourceFoamNoise).
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
    SurfaceSourcesUniforms u{};
    for (std::size_t i = 0; i < sources.size() && i < SWELL_MAX_SURFACE_SOURCES; ++i) {
        const SurfaceSourceParameters p = sources[i]->gpuParameters(time_s, renderOrigin_m);
        for (std::size_t k = 0; k < 4; ++k)
            u.parameters[4 * i + k] = p[k];
    }
    // The whitecaps' lattices laid from the render origin (the sources' p_m
    // is relative to it), so the foam's texture stays on the water however
    // the origin moves; no streaks (a wake's foam lies along the course,
    // not the wind).
    const auto maps = foam::foamNoiseMaps(glm::dvec2(renderOrigin_m.x, renderOrigin_m.z), glm::dvec2(1.0, 0.0), 1.0);
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const glm::mat2& m = maps[i].map;
        u.foamNoise[i].map = glm::vec4(m[0][0], m[0][1], m[1][0], m[1][1]);
        u.foamNoise[i].offset_cells = maps[i].offset_cells;
        u.foamNoise[i].cyclesPerMetre = maps[i].cyclesPerMetre;
    }
    u.breakingFoamAmount = float(std::exp(-foam::kBreakingFoamAge_s / SWELL_SOURCE_FOAM_LIFETIME_S));
    if (!buffer_) {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), sizeof(u), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(buffer_.id(), 0, sizeof(u), &u);
    bind();
}

void SurfaceSourceParametersBuffer::bind() const
{
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_SURFACE_SOURCES, buffer_.id());
}

} // namespace swell::detail
