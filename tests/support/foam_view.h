// The foam debug view of a scene, looked at straight down: what the foam
// tests measure (the whitecaps' texture, the wake's wash).
#pragma once

#include "support/golden.h"
#include "swell/camera.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace swell::test {

// The scene showing the foam's share alone, each pixel's own (FXAA would
// blend across the edges the tests look for).
inline Scene foamDebugView(Scene scene)
{
    scene.debugView = DebugView::Foam;
    scene.antialiasing = Antialiasing::Off;
    return scene;
}

// The foam view straight down from position_m (the scene camera's yaw
// unless one is given) at time_s, size x size pixels, as linear shares row
// by row; saved as a test image when named.
inline std::vector<double> foamViewDown(Renderer& renderer, const Scene& scene, glm::dvec3 position_m,
                                        std::optional<double> yaw_deg, double time_s, int size, const char* name)
{
    Camera camera = cameraAt(scene.camera, 0.0);
    camera.position_m = position_m;
    if (yaw_deg)
        camera.yaw_deg = *yaw_deg;
    camera.pitch_deg = -89.0;
    const Image image = renderer.renderImage(camera, time_s, {size, size});
    if (name)
        saveTestImage(image, name);
    std::vector<double> share;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            share.push_back(srgbToLinear(image.pixel(x, y)[0]));
    return share;
}

// Where a second square view (size x size shares) matches the first best:
// the mean |a - b| over their overlap with b moved by (dx, dy) pixels, a
// margin of `margin` pixels left out, least over dx in -margin..margin and
// dy in -8..8. What the "stays on the water" tests ask of a texture that
// must move with the water, not with the camera.
struct ShiftMatch {
    int dx = 0, dy = 0;
    double difference = 0.0; // at (dx, dy)
    double unmoved = 0.0;    // at (0, 0)
};

inline double shiftedDifference(const std::vector<double>& a, const std::vector<double>& b, int size, int margin,
                                int dx, int dy)
{
    double sum = 0.0;
    int n = 0;
    for (int y = margin; y < size - margin; ++y)
        for (int x = margin; x < size - margin; ++x) {
            sum += std::abs(a[size_t(y * size + x)] - b[size_t((y + dy) * size + x + dx)]);
            ++n;
        }
    return sum / n;
}

inline ShiftMatch bestShift(const std::vector<double>& a, const std::vector<double>& b, int size, int margin)
{
    ShiftMatch best{0, 0, 1e9, shiftedDifference(a, b, size, margin, 0, 0)};
    for (int dy = -8; dy <= 8; ++dy)
        for (int dx = -margin; dx <= margin; ++dx) {
            const double d = shiftedDifference(a, b, size, margin, dx, dy);
            if (d < best.difference) {
                best.difference = d;
                best.dx = dx;
                best.dy = dy;
            }
        }
    std::printf("best match at (%d, %d) pixels: mean |difference| %.4f; unmoved: %.4f\n", best.dx, best.dy,
                best.difference, best.unmoved);
    return best;
}

} // namespace swell::test
