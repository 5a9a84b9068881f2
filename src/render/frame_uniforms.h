// Filling the Frame uniform block (render/gpu/blocks.h) for a camera: what
// every pass shares; each pass then sets its own camera, clip plane and
// output encoding.
#pragma once

#include "render/gpu/blocks.h"
#include "render/sky_light.h"
#include "swell/camera.h"
#include "swell/scene/grid.h"
#include "swell/scene/scene.h"

#include <glm/mat4x4.hpp>

namespace swell::detail {

// viewProj maps positions relative to `origin` (the render origin, absolute
// m, in the sea's frame: y = 0 at its mean level, like eye_m); size is the
// viewport in pixels. World boxes are left for the caller.
// The sun's light, the sky's colours and the ambient light come from `sky`.
FrameUniforms frameUniforms(const Scene& scene, const SkyLight& sky, const GridShape& gridShape,
                            const GridPlacement& grid, glm::dvec3 eye_m, const glm::dmat4& viewProj, glm::dvec3 origin,
                            glm::ivec2 size);

// Sets viewportSize and viewportInvSize for a target of `size` pixels.
void setViewport(FrameUniforms& f, glm::ivec2 size);

} // namespace swell::detail
