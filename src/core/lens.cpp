// Brown-Conrady lens distortion (swell/dataset/sensor.h).
#include "swell/dataset/sensor.h"

#include <glm/geometric.hpp>

namespace swell {

LensDistortion lensOf(const CameraSettings& c)
{
    return {c.distortionK1, c.distortionK2, c.distortionK3, c.distortionP1, c.distortionP2};
}

glm::dvec2 distort(const LensDistortion& l, glm::dvec2 u)
{
    const double x = u.x, y = u.y, r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
    return {x * radial + 2.0 * l.p1 * x * y + l.p2 * (r2 + 2.0 * x * x),
            y * radial + l.p1 * (r2 + 2.0 * y * y) + 2.0 * l.p2 * x * y};
}

glm::dvec2 undistort(const LensDistortion& l, glm::dvec2 d)
{
    // x = (x_d - tangential(x)) / radial(x), iterated from x = x_d (as
    // OpenCV's undistortPoints does).
    glm::dvec2 u = d;
    for (int i = 0; i < 50; ++i) {
        const double x = u.x, y = u.y, r2 = x * x + y * y;
        const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
        const glm::dvec2 tangential(2.0 * l.p1 * x * y + l.p2 * (r2 + 2.0 * x * x),
                                    l.p1 * (r2 + 2.0 * y * y) + 2.0 * l.p2 * x * y);
        const glm::dvec2 next = (d - tangential) / radial;
        const double step = glm::distance(next, u);
        u = next;
        if (step < 1e-12)
            break;
    }
    return u;
}

} // namespace swell
