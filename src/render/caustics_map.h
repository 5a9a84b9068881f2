// The caustics map (shaders/caustics.glsl): each view, the sun's light
// refracted by the drawn surface down to SWELL_CAUSTICS_SLICES level slices,
// splatted into an R32F texture array that follows the camera (snapped to
// its texels, so the pattern stays put in the world as the camera moves),
// and the Caustics uniform block saying where it lies. The world's shading
// (mesh.frag) looks it up under the water.
#pragma once

#include "render/gpu/blocks.h"
#include "swell/gl/handle.h"
#include "swell/gpu/underwater.h"
#include "swell/debug.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace swell::detail {

struct CausticsPrograms;


// The slices' depths below the mean level, m: 1 m, where the short waves'
// light comes to its first foci, 3 m and 8 m, where the longer waves' do
// (a wave of length L and height H focuses at about 4 R = L^2 / (pi^2 H)
// under its crest: 0.5 to 1 m waves a few cm high within these depths).
inline constexpr std::array<float, SWELL_CAUSTICS_SLICES> kCausticsSliceDepths_m{1.0f, 3.0f, 8.0f};

class CausticsMap {
public:
    // Places the map around the render origin `origin_m` (absolute, sea
    // frame, m) for the sun `sun` (towards it, unit), the wave model's grid
    // centre at gridCenter_m relative to the render origin; writes the
    // uniform block. Once per view, whether the map is drawn or not (the
    // world's shading reads the block either way).
    void place(glm::dvec3 origin_m, glm::vec2 gridCenter_m, glm::vec3 sun);
    // Draws the map with `programs` (the wave model's GLSL in the first):
    // the wave model's buffers and textures bound. Refracts the source grid
    // and forms the slices' triangles in two compute dispatches (every core
    // or multiprocessor shares them, where a geometry stage would run on
    // few), then draws each slice. Sets the state it needs and leaves the
    // framebuffer, viewport and blending as the next pass must set them,
    // and builds the map's mip chain (one glGenerateTextureMipmap). Returns
    // the source triangles drawn.
    long long render(const CausticsPrograms& programs);
    // What a render() writes other than by drawing, as GpuWork counts it:
    // its two dispatches and their barriers, the refracted grid and the
    // slices' triangles they write, the clear of every slice's base level
    // and the mip chain's levels 1 and up (bytes), its one
    // glGenerateTextureMipmap.
    static GpuWork renderWork();
    // Binds the map and the uniform block for the world's programs.
    void bind() const;
    const CausticsUniforms& uniforms() const { return uniforms_; }
    GLuint texture() const { return texture_.id(); }

private:
    void create();

    CausticsUniforms uniforms_;
    gl::Texture texture_;
    std::array<gl::Framebuffer, SWELL_CAUSTICS_SLICES> sliceFramebuffers_; // each slice's base level
    gl::Buffer block_, sources_, images_;
    gl::VertexArray vertexArray_;
};

} // namespace swell::detail
