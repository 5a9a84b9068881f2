#include "render/waterline.h"

#include "swell/gpu/underwater.h"

#include <algorithm>

namespace swell::detail {

NearPlaneMedium nearPlaneMedium(const std::array<glm::dvec3, 4>& nearCorners_m, const WaveReach& reach)
{
    double lowest = nearCorners_m[0].y, highest = lowest;
    for (const glm::dvec3& corner : nearCorners_m) {
        lowest = std::min(lowest, corner.y);
        highest = std::max(highest, corner.y);
    }
    if (lowest > reach.vertical_m)
        return NearPlaneMedium::Air;
    if (highest < -reach.vertical_m)
        return NearPlaneMedium::Water;
    return NearPlaneMedium::Both;
}

std::array<glm::dvec3, 4> nearPlaneCorners(const glm::dmat4& inverseViewProj, double nearNdcZ)
{
    std::array<glm::dvec3, 4> corners;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec4 p = inverseViewProj * glm::dvec4(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, nearNdcZ, 1.0);
        corners[size_t(i)] = glm::dvec3(p) / p.w;
    }
    return corners;
}

bool eyeUnderwater(glm::dvec3 eye_m, const SurfaceQuery& model, double time_s, double reach_m)
{
    if (!eyeWithinReach(eye_m, reach_m))
        return eye_m.y < 0.0;
    return eye_m.y < model.heightAt({eye_m.x, eye_m.z}, time_s);
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
