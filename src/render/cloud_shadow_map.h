// The cloud layer's shadows (shaders/cloud_shadow.glsl): the layer's
// transmittance along the sun's ray from each point of the sea's mean
// level, baked by the GPU from clouds.glsl (the twin of swell/scene/clouds.h's
// cloudShadowTransmittance) into an R32F map that follows the camera,
// snapped to its texels (a re-bake puts every texel's value back where it
// was, so nothing jumps as the camera goes on), and mipmapped, so a pixel
// averages the transmittance over its footprint. Baked again only when
// the clouds or the sun change or the camera has left the middle of the
// map (SWELL_CLOUD_SHADOW_REBAKE): the fractal noise is never evaluated
// per pixel. The sea, the world, the spray and the shafts look it up where
// the sun's ray through their point meets the mean level.
#pragma once

#include "render/gpu/blocks.h"
#include "swell/gl/handle.h"
#include "swell/gpu/sky.h"
#include "swell/scene/clouds.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace swell::detail {

class CloudShadowBakeProgram;


// The width of the map's texels, m.
inline constexpr double kCloudShadowTexel_m = SWELL_CLOUD_SHADOW_EXTENT_M / SWELL_CLOUD_SHADOW_SIZE;

class CloudShadowMap {
public:
    // Makes the map hold `clouds` for the sun `sun` (towards it, unit,
    // the frame's) around the render origin origin_m (absolute, sea frame,
    // m), baking it with `program` when any of them changed or the origin
    // left the map's middle; writes the uniform block (skySun: the
    // layer's transmittance towards the sun from the sky's observer).
    // Returns whether it baked (one draw and one mip chain), leaving the
    // framebuffer, viewport and clip control as the next pass must set them.
    bool update(const CloudShadowBakeProgram& program, GLuint emptyVao, const CloudSettings& clouds, glm::vec3 sun,
                glm::dvec3 origin_m, float skySun);
    // Bakes again at the next update() (the bake shader may have changed).
    void forget() { baked_.reset(); }
    // Binds the map and its block for the programs that read them.
    void bind() const;
    const CloudShadowUniforms& uniforms() const { return uniforms_; }
    GLuint texture() const { return texture_.id(); }
    // The absolute x, z of texel (0, 0)'s outer corner of the last bake, m.
    glm::dvec2 bakedCorner_m() const { return glm::dvec2(bakedCornerTexel_) * kCloudShadowTexel_m; }

private:
    struct Key {
        CloudSettings clouds;
        glm::vec3 sun{0.0f};
        glm::ivec2 cornerTexel{0};
        bool operator==(const Key&) const = default;
    };
    void create();

    CloudShadowUniforms uniforms_;
    std::optional<Key> baked_;
    glm::ivec2 bakedCornerTexel_{0};
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    gl::Buffer block_;
};

} // namespace swell::detail
