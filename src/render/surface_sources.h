// The surface sources the water draws (swell/surface_source.h), composed into one
// GLSL function for the water programs: each source's code becomes a file of
// its own ("surface_source_<i>.glsl", so a compile error names it), and
// "surface_sources.glsl" sums them in surfaceSourcesAt(p_m) (heights and slopes
// add, foam takes the largest), reading their parameters from the
// SurfaceSources block this uploads per view (render/gpu/blocks.h), with the lattices of the
// foam's texture (the whitecaps', shaders/whitecap_foam.glsl) anchored to
// the world for the view.
#pragma once

#include "render/gpu/blocks.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"
#include "swell/surface_source.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <vector>

namespace swell::detail {


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
