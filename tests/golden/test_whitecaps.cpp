// Whitecap cover of the rendered spectral sea against Monahan &
// O'Muircheartaigh (1980): the share of a top-down view's water that the
// shading covers with foam (the foam debug view's grey level, decoded from
// sRGB: each pixel's covered share), over nine places of one frame.
//
// In the golden tier (Release only): it renders 36 frames, each replaying
// the foam's history, about 30 s on llvmpipe.
#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/whitecaps.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/renderer.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using namespace swell;

class Whitecaps : public test::GlTest {};

Scene foamScene(double windSpeed_mps)
{
    Scene scene = defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.waves.model = WaveModelKind::Spectral;
    scene.waves.wind->windSpeed_mps = windSpeed_mps;
    scene.waves.wind->fetch_km = 3000.0; // fully developed, as Monahan's open-ocean data
    scene.debugView = DebugView::Foam;
    return scene;
}

// The foam debug view straight down from 300 m over (x, z), as each pixel's
// covered share (linear).
std::vector<double> foamFrom300m(Renderer& renderer, const Scene& scene, double x_m, double z_m, double time_s)
{
    Camera camera = cameraAt(scene.camera, 0.0);
    camera.position_m = {x_m, 300.0, z_m};
    camera.pitch_deg = -89.0;
    const Image image = renderer.renderImage(camera, time_s, {192, 192});
    std::vector<double> share;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            share.push_back(test::srgbToLinear(image.pixel(x, y)[0]));
    return share;
}

double renderedCover(double windSpeed_mps)
{
    const Scene scene = foamScene(windSpeed_mps);
    Renderer renderer(scene);
    double white = 0.0;
    long long total = 0;
    // Looking straight down from 300 m (2*300*tan(30 deg) = 346 m across) at
    // 9 places of one frame, spread over the largest patch so that they see
    // different breakings: each place's foam history is replayed.
    for (int k = 0; k < 9; ++k)
        for (const double share : foamFrom300m(renderer, scene, 1237.0 * k, -2903.0 * k, 60.0)) {
            white += share;
            ++total;
        }
    return white / double(total);
}

// Pearson's correlation of two equally long series.
double correlation(const std::vector<double>& a, const std::vector<double>& b)
{
    double ma = 0.0, mb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        ma += a[i];
        mb += b[i];
    }
    ma /= double(a.size());
    mb /= double(b.size());
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return ab / std::sqrt(aa * bb);
}

TEST_F(Whitecaps, CoverFollowsMonahan)
{
    struct Case {
        double windSpeed_mps, allowedFactor;
    };
    // The issue asks for a factor of 1.5 at every wind. Measured (seeded, so
    // the same on every run of one build): see docs/RENDERING.md.
    for (const Case c : {Case{8.0, 1.5}, Case{12.0, 1.5}, Case{16.0, 1.5}, Case{20.0, 1.5}}) {
        const double cover = renderedCover(c.windSpeed_mps);
        const double expected = spectral::monahanWhitecapCover(c.windSpeed_mps);
        std::printf("U10 %.0f m/s: rendered cover %.4f, Monahan %.4f, ratio %.2f\n", c.windSpeed_mps, cover, expected,
                    cover / expected);
        EXPECT_LT(cover, expected * c.allowedFactor) << "at " << c.windSpeed_mps << " m/s";
        EXPECT_GT(cover, expected / c.allowedFactor) << "at " << c.windSpeed_mps << " m/s";
    }
}

// No visible tiling of the foam (issue 12): foam kept in the periodic
// cascades repeated with their patches, a grid of whitecaps seen from high
// up. Kept in the world, the foam one patch away is other foam: the
// correlation of the view with the same view one foam cascade's patch away
// (along x, and along the diagonal) is as low as between unrelated places.
TEST_F(Whitecaps, FoamDoesNotRepeatWithThePatches)
{
    const double windSpeed_mps = 16.0;
    const Scene scene = foamScene(windSpeed_mps);
    const spectral::SpectralField field =
        spectral::makeSpectralField(SeaSpectrum(*scene.waves.wind), scene.waves.choppiness, scene.waves.wind->seed);
    Renderer renderer(scene);
    const std::vector<double> here = foamFrom300m(renderer, scene, 0.0, 0.0, 60.0);
    for (int c = 0; c < spectral::kFoamCascades; ++c) {
        const double patch_m = field.cascades[size_t(c)].patch_m;
        for (const glm::dvec2 shift : {glm::dvec2(patch_m, 0.0), glm::dvec2(patch_m, patch_m)}) {
            const double r = correlation(here, foamFrom300m(renderer, scene, shift.x, shift.y, 60.0));
            std::printf("cascade %d: patch %.1f m, shift (%.1f, %.1f) m: correlation %.3f\n", c, patch_m, shift.x,
                        shift.y, r);
            EXPECT_LT(r, 0.3) << "the foam repeats with cascade " << c << "'s patch";
        }
    }
}

} // namespace
