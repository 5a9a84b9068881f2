// The surface sources the water draws (swell/surface_source.h), composed into one
// GLSL function for the water programs: each source's code becomes a file of
// its own ("surface_source_<i>.glsl", so a compile error names it), and
// "surface_sources.glsl" sums them in surfaceSourcesAt(p_m) (heights and slopes
// add, foam takes the largest), reading their parameters from the
// SurfaceSources block this uploads per view, with the lattices of the
// foam's texture (the whitecaps', shaders/whitecap_foam.glsl) anchored to
// the world for the view.
#pragma once

#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"
#include "swell/shader_constants.h"
#include "swell/surface_source.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <vector>

namespace swell::detail {

// Mirrors the SurfaceSources block of the generated surface_sources.glsl (std140).
struct alignas(16) SurfaceSourcesUniforms {
    // One lattice of the foam's texture (FoamNoise in shaders/whitecap_foam.glsl).
    struct alignas(16) FoamNoise {
        glm::vec4 map{0.0f}; // column-major: cells per metre along x, then along z
        glm::vec2 offset_cells{0.0f};
        float cyclesPerMetre = 0.0f;
    };
    glm::vec4 parameters[SWELL_MAX_SURFACE_SOURCES * 4];
    FoamNoise foamNoise[SWELL_FOAM_NOISE_MAPS];
    float breakingFoamAmount = 0.0f;
};
static_assert(sizeof(SurfaceSourcesUniforms::FoamNoise) == 32);
static_assert(sizeof(SurfaceSourcesUniforms) == 16 * (4 * SWELL_MAX_SURFACE_SOURCES + 2 * SWELL_FOAM_NOISE_MAPS + 1));

// Writes the sources' files into `sources` (replacing earlier ones) for
// programs built with SWELL_SURFACE_SOURCES = codes.size().
void setSurfaceSourceFiles(gl::ShaderSources& sources, const std::vector<std::string>& codes);

class SurfaceSourceParametersBuffer {
public:
    // Uploads each source's parameters for a view of time_s about
    // renderOrigin_m (absolute world, m) and binds the block.
    void upload(const std::vector<std::shared_ptr<const SurfaceSource>>& sources, double time_s,
                glm::dvec3 renderOrigin_m);
    void bind() const;

private:
    gl::Buffer buffer_;
};

} // namespace swell::detail
