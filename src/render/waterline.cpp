#include "render/waterline.h"

#include "swell/shader_constants.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace swell::detail {

NearPlaneMedium nearPlaneMedium(const Camera& camera, double aspect, const WaveReach& reach)
{
    // The farthest any point of the near plane's rectangle lies from the eye:
    // its corners, near_m / cos of the half-diagonal angle.
    const double t = std::tan(glm::radians(camera.fovY_deg) * 0.5);
    const double corner_m = camera.near_m * std::sqrt(1.0 + t * t * (1.0 + aspect * aspect));
    const double y = camera.position_m.y;
    if (y - corner_m > reach.vertical_m)
        return NearPlaneMedium::Air;
    if (y + corner_m < -reach.vertical_m)
        return NearPlaneMedium::Water;
    return NearPlaneMedium::Both;
}

bool eyeUnderwater(const Camera& camera, const WaveModel& model, double time_s)
{
    const glm::dvec3 eye = camera.position_m;
    return eye.y < model.heightAt({eye.x, eye.z}, time_s);
}

void WaterlineMask::resize(glm::ivec2 size)
{
    target_.resize(size, GL_R8);
    if (!allAbove_) {
        allAbove_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(allAbove_.id(), 1, GL_R8, 1, 1);
        const float above = SWELL_WATERLINE_ABOVE;
        glClearTexImage(allAbove_.id(), 0, GL_RED, GL_FLOAT, &above);
    }
}

void WaterlineMask::fill(NearPlaneMedium medium)
{
    const float value = medium == NearPlaneMedium::Water ? SWELL_WATERLINE_BELOW : SWELL_WATERLINE_ABOVE;
    glClearTexImage(target_.color(), 0, GL_RED, GL_FLOAT, &value);
}

} // namespace swell::detail
