// Horizon filtering: with the normals filtered by each pixel's footprint and
// the highlight spread by the slopes they leave out, the far water is a
// stable sheen; shaded with every wave in the normal it shimmers. Measured
// as issue 13 asks: a slow camera pan at 60 frames a second, the mean
// absolute frame-to-frame change of the far half of the water, filtered
// against unfiltered (the shading with SWELL_TERM_FILTERING left out).
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/gpu/variants.h"
#include "swell/renderer.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

class HorizonFiltering : public swell::test::GlTest {};

constexpr glm::ivec2 kHorizonFilteringSize{640, 360};
constexpr int kFrames = 9;
constexpr double kPan_degps = 10.0; // a slow pan: 6 s for 60 degrees

swell::Scene openSea(bool spectral)
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    if (spectral) {
        scene.waves.model = swell::WaveModelKind::Spectral;
        scene.sea.wind->windSpeed_mps = 10.0;
    }
    return scene;
}

// Mean absolute change of luma (0..255) between consecutive frames over the
// far half of the water: the rows from just below the horizon to half way
// down to the bottom of the image.
double shimmer(const swell::Scene& scene, unsigned omittedTerms)
{
    const std::unique_ptr<swell::Renderer> created = swell::RendererTesting::create(scene, {}, omittedTerms);
    swell::Renderer& renderer = *created;
    const swell::Camera start = swell::cameraAt(scene.camera, 0.0);
    // The horizon's row: the camera looks pitch_deg below it.
    const double halfHeight = 0.5 * kHorizonFilteringSize.y;
    const double horizonRow =
        halfHeight - std::tan(glm::radians(-start.pitch_deg)) / std::tan(glm::radians(0.5 * scene.camera.fovY_deg)) * halfHeight;
    const int first = int(std::ceil(horizonRow)) + 3, last = int((horizonRow + kHorizonFilteringSize.y) / 2.0);
    std::vector<double> previous;
    double sum = 0.0;
    long long count = 0;
    for (int k = 0; k < kFrames; ++k) {
        const double t = k / 60.0;
        swell::Camera camera = start;
        camera.yaw_deg += kPan_degps * t;
        const swell::Image image = renderer.renderImage(camera, t, kHorizonFilteringSize);
        std::vector<double> luma;
        for (int y = first; y < last; ++y)
            for (int x = 0; x < kHorizonFilteringSize.x; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                luma.push_back(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
            }
        if (!previous.empty())
            for (size_t i = 0; i < luma.size(); ++i) {
                sum += std::abs(luma[i] - previous[i]);
                ++count;
            }
        previous = std::move(luma);
    }
    return sum / double(count);
}

void expectStable(const swell::Scene& scene, const char* what)
{
    const double filtered = shimmer(scene, 0), unfiltered = shimmer(scene, SWELL_TERM_FILTERING);
    std::printf("%s: far water changes %.2f levels a frame filtered, %.2f unfiltered (ratio %.2f)\n", what, filtered,
                unfiltered, filtered / unfiltered);
    // The goal: at most half the change of the unfiltered shading.
    EXPECT_LE(filtered, 0.5 * unfiltered) << what;
}

TEST_F(HorizonFiltering, GerstnerFarWaterIsStableUnderASlowPan) { expectStable(openSea(false), "Gerstner, default sea"); }

TEST_F(HorizonFiltering, SpectralFarWaterIsStableUnderASlowPan) { expectStable(openSea(true), "spectral, 10 m/s"); }

} // namespace
