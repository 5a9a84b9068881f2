// The foam debug view of a scene, looked at straight down: what the foam
// tests measure (the whitecaps' texture, the wake's wash).
#pragma once

#include "support/golden.h"
#include "swell/camera.h"
#include "swell/renderer.h"
#include "swell/scene.h"

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

} // namespace swell::test
