// The waterline mask: for each pixel of the main pass, whether its view ray
// starts (at the near plane) above or below the water (see shaders/underwater.glsl).
// Near the surface it is drawn from the water grid itself, so a camera in the
// waves sees a split that follows them; far from it, it is cleared to the
// side the whole view lies on, at no drawing cost.
#pragma once

#include "render/render_target.h"
#include "swell/gl/handle.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace swell::detail {

// Where the camera's near plane lies relative to the water.
enum class NearPlaneMedium {
    Air,   // wholly above every wave: every pixel looks out from the air
    Water, // wholly below every trough: every pixel looks out from the water
    Both,  // within the waves' reach: decided pixel by pixel
};

// Classifies a view's near plane, given by its corners (relative to the
// mean level, m: its rectangle spans the heights between them), against a
// surface whose heights stay within +-reach.vertical_m of the mean level.
NearPlaneMedium nearPlaneMedium(const std::array<glm::dvec3, 4>& nearCorners_m, const WaveReach& reach);

// The corners of a view's near plane: the inverse of its view-projection at
// the near plane's NDC z (-1, or 0 for GL_ZERO_TO_ONE, or 1 reversed).
std::array<glm::dvec3, 4> nearPlaneCorners(const glm::dmat4& inverseViewProj, double nearNdcZ);

// Whether the eye (relative to the mean level, m) is below the surface at
// time_s (WaveModel::heightAt under it): decides which half of the world the
// refraction pass renders. An eye beyond the waves' reach (`reach_m`, the
// most the surface moves from the mean level) is answered without asking
// the model.
bool eyeUnderwater(glm::dvec3 eye_m, const SurfaceQuery& model, double time_s, double reach_m);

// Whether the surface under an eye (relative to the mean level, m) must be
// asked for to tell which side of it the eye is: only within the waves' reach.
inline bool eyeWithinReach(glm::dvec3 eye_m, double reach_m) { return std::abs(eye_m.y) <= reach_m; }

class WaterlineMask {
public:
    // Allocates the mask for the main pass's size, and the 1x1 "all above" mask
    // that every other pass binds.
    void resize(glm::ivec2 size);
    // Clears the mask to one side for every pixel (no water drawn).
    void fill(NearPlaneMedium medium);
    // The framebuffer the water grid is drawn into (colour cleared to "no hit" first).
    GLuint framebuffer() const { return target_.framebuffer(); }
    glm::ivec2 size() const { return target_.size(); }
    // The main pass's mask, and the one for passes that see no water from below.
    GLuint texture() const { return target_.color(); }
    GLuint allAbove() const { return allAbove_.id(); }

private:
    RenderTarget target_;
    gl::Texture allAbove_;
};

} // namespace swell::detail
