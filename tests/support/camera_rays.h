// Where world points land in a rendered image and which way each pixel looks,
// computed on the CPU from the same camera the renderer uses.
#pragma once

#include "swell/camera.h"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace swell::test {

// Pixel coordinates (from the top left, pixel centres at +0.5) of a world point.
inline glm::dvec2 projectToPixel(const Camera& camera, glm::ivec2 size, glm::dvec3 point_m)
{
    const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
    const glm::dvec4 clip = camera.projection(double(size.x) / size.y) * camera.viewRelativeTo(origin) *
                            glm::dvec4(point_m - origin, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * size.x, (0.5 - ndc.y * 0.5) * size.y};
}

// Unit world direction of the ray through the centre of pixel (x, y), top row 0.
inline glm::dvec3 pixelRay(const Camera& camera, glm::ivec2 size, int x, int y)
{
    const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
    const glm::dmat4 inverse =
        glm::inverse(camera.projection(double(size.x) / size.y) * camera.viewRelativeTo(origin));
    const glm::dvec2 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (y + 0.5) / size.y * 2.0);
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
    return glm::normalize(glm::dvec3(farPoint) / farPoint.w - glm::dvec3(nearPoint) / nearPoint.w);
}

} // namespace swell::test
