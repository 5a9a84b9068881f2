// The waterline mask: for each pixel of the main pass, whether its view ray
// starts (at the near plane) above or below the water (see shaders/underwater.glsl).
// Near the surface it is drawn from the water grid itself, so a camera in the
// waves sees a split that follows them; far from it, it is cleared to the
// side the whole view lies on, at no drawing cost.
#pragma once

#include "render/render_target.h"
#include "swell/camera.h"
#include "swell/gl/handle.h"
#include "swell/wave_model.h"

#include <glm/vec2.hpp>

namespace swell::detail {

// Where the camera's near plane lies relative to the water.
enum class NearPlaneMedium {
    Air,   // wholly above every wave: every pixel looks out from the air
    Water, // wholly below every trough: every pixel looks out from the water
    Both,  // within the waves' reach: decided pixel by pixel
};

// Classifies a camera against a surface whose heights stay within
// +-reach.vertical_m of the mean level (y = 0). `aspect` is width / height.
NearPlaneMedium nearPlaneMedium(const Camera& camera, double aspect, const WaveReach& reach);

// Whether the eye itself is below the surface at time_s (WaveModel::heightAt
// under it): decides which half of the world the refraction pass renders.
bool eyeUnderwater(const Camera& camera, const WaveModel& model, double time_s);

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
