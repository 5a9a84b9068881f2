// The default sky as a cubemap: the procedural sky (shaders/sky_procedural.glsl)
// rendered by the GPU into six faces, so the sky pass, the reflection pass and
// the water's reflection lookups all sample a cubemap, the procedural sky
// exactly as a user's six images.
#pragma once

#include "render/programs.h"
#include "swell/gl/handle.h"
#include "swell/scene/atmosphere.h"
#include "swell/scene/scene.h"

namespace swell::detail {

// Edge of each baked face, texels. The procedural sky has no feature narrower
// than the sun's 5-degree glow lobe except the kink of its gradient at the
// horizon; with linear filtering, 256 texels over 90 degrees (0.35 degrees a
// texel, about 5 pixels of a 1280x720 frame with a 60-degree field of view)
// reproduce it within 2 levels of 255 (tests/golden/test_sky_cubemap.cpp
// checks the baked sky against the formula). Magnified at every usual output
// size, so no mipmaps. The sun's disc, the only sharp feature, stays analytic.
inline constexpr int kSkyFaceSize = 256;
inline constexpr int kSkyFaces = 6;

// What the baked sky depends on; a bake is redone when this changes.
struct SkyBakeKey {
    SkyModel model = SkyModel::Gradient;
    glm::dvec3 zenith{0.0}, horizon{0.0}, sunDirection{0.0}, sunColor{0.0};
    double sunIntensity = 0.0;
    double exposure = 0.0;           // physical only
    AtmosphereSettings atmosphere{}; // physical only
    CloudSettings clouds{};          // physical only
    bool operator==(const SkyBakeKey&) const = default;
};

SkyBakeKey skyBakeKeyOf(const Scene& scene);

// Renders the procedural sky into `cube` (created when empty) with `program`
// (fullscreen.vert + sky_bake.frag), one draw per face (kSkyFaces). The frame uniform
// block must be bound with the scene's sun and sky. Leaves the framebuffer
// binding and viewport changed; every pass sets its own.
void bakeProceduralSky(const SkyBakeProgram& program, gl::Texture& cube, GLuint emptyVao);

// The physical sky's two tables (Atmosphere::transmittanceTable and
// multipleScatteringTable, the second in layers of a 2D array) as RGB32F
// textures, linear, clamped; made when
// empty. Bound to SWELL_UNIT_SKY_TRANSMITTANCE and SWELL_UNIT_SKY_MULTISCATTER
// by the caller for the bake.
struct AtmosphereTextures {
    gl::Texture transmittance, multipleScattering;
    void upload(const Atmosphere& atmosphere);
    void bind() const;
};

} // namespace swell::detail
