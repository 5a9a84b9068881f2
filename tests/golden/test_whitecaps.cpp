// Whitecap cover of the rendered spectral sea against Monahan &
// O'Muircheartaigh (1980): the share of a top-down view's water that the
// shading covers with foam (the foam debug view's grey level, decoded from
// sRGB: each pixel's covered share), over nine places of one frame.
//
// In the golden tier (Release only): CoverFollowsMonahan renders 36 frames,
// each replaying the foam's history, 44 s on an idle 2-core machine with
// llvmpipe; AStillAtTimeZeroShowsTheDevelopedFoam 27 (50 s on a loaded one).
#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "support/statistics.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr int kWhitecapsView = 192; // pixels a side of the top-down views

using namespace swell;

class Whitecaps : public test::GlTest {};

Scene foamScene(double windSpeed_mps)
{
    Scene scene = defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.waves.model = WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = windSpeed_mps;
    scene.sea.wind->fetch_km = 3000.0; // fully developed, as Monahan's open-ocean data
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
    const Image image = renderer.renderImage(camera, time_s, {kWhitecapsView, kWhitecapsView});
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

// The largest Pearson correlation of two top-down views over every
// relative shift of up to maxShift pixels each way, on their overlap: the
// anti-tiling warp moves a repeated patch by up to tens of metres, nearly
// rigidly across a view, so an exact patch shift would miss the repetition.
double largestShiftedCorrelation(const std::vector<double>& a, const std::vector<double>& b, int maxShift)
{
    double best = -1.0;
    for (int dy = -maxShift; dy <= maxShift; ++dy)
        for (int dx = -maxShift; dx <= maxShift; ++dx) {
            double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
            int n = 0;
            for (int y = std::max(0, -dy); y < std::min(kWhitecapsView, kWhitecapsView - dy); ++y)
                for (int x = std::max(0, -dx); x < std::min(kWhitecapsView, kWhitecapsView - dx); ++x) {
                    const double va = a[size_t(y * kWhitecapsView + x)], vb = b[size_t((y + dy) * kWhitecapsView + x + dx)];
                    sa += va;
                    sb += vb;
                    saa += va * va;
                    sbb += vb * vb;
                    sab += va * vb;
                    ++n;
                }
            const double cov = sab - sa * sb / n, va = saa - sa * sa / n, vb = sbb - sb * sb / n;
            if (va > 0.0 && vb > 0.0)
                best = std::max(best, cov / std::sqrt(va * vb));
        }
    return best;
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

// A still shows the foam its history made. A frame that starts a sequence
// (or jumps in time) replays the foam's history on the steps
// foamReplayOffsets_s() gives (every kFoamReplayStep_s over
// kFoamReplayLifetimes lifetimes), the steps before the last transforming
// only the cascades that fold into foam. A sequence of frames on the same
// steps takes them with every field transformed, after its own first
// frame's replay: its foam holds the still's, texel by texel, and exceeds
// it by at most that first frame's foam decayed over the replayed span
// (exp(-10 s / 3.85 s) = 0.074 of it). So no pixel of the still shows more
// foam than the sequence's (the covered share grows with the foam), and
// their mean difference is allowed that share of the sequence's cover
// (measured: 0.0032 of 0.0068 allowed). A replay that made its foam from
// other fields than the sequence's differs far more (one cascade
// transformed instead of two: 0.069).
void expectTheStillsFoamIsItsHistorys(double lifetime_s)
{
    Scene scene = foamScene(16.0);
    scene.waves.foamLifetime_s = lifetime_s;
    // Each pixel's own share: FXAA's blend across edges depends on the
    // contrast it finds, so it would not keep one view's foam within the other's.
    scene.antialiasing = swell::Antialiasing::Off;
    const double span_s = spectral::foamReplayOffsets_s(lifetime_s).front();
    const int steps = int(std::lround(span_s / spectral::kFoamReplayStep_s));
    const double time_s = 60.0;
    Renderer still(scene);
    const std::vector<double> replayed = foamFrom300m(still, scene, 400.0, -300.0, time_s);
    Renderer sequence(scene);
    Camera camera = cameraAt(scene.camera, 0.0);
    camera.position_m = {400.0, 300.0, -300.0};
    camera.pitch_deg = -89.0;
    // The frames before the last only step the foam (the picture's size
    // does not change it).
    for (int i = steps; i >= 1; --i)
        sequence.renderImage(camera, time_s - i * spectral::kFoamReplayStep_s, {8, 8});
    const std::vector<double> stepped = foamFrom300m(sequence, scene, 400.0, -300.0, time_s);

    const double carried = std::exp(-span_s / lifetime_s);
    double replayedMean = 0.0, steppedMean = 0.0, meanDifference = 0.0, largestDeficit = 0.0;
    for (size_t i = 0; i < replayed.size(); ++i) {
        replayedMean += replayed[i];
        steppedMean += stepped[i];
        meanDifference += std::abs(stepped[i] - replayed[i]);
        largestDeficit = std::max(largestDeficit, replayed[i] - stepped[i]);
    }
    const double n = double(replayed.size());
    replayedMean /= n;
    steppedMean /= n;
    meanDifference /= n;
    std::printf("lifetime %.2f s, %zu replay steps against %d: foam cover: still %.4f, sequence %.4f; mean "
                "|difference| %.4f; the still above the sequence by %.4f at most; the sequence's first foam "
                "carried: %.3f\n",
                lifetime_s, spectral::foamReplayOffsets_s(lifetime_s).size() - 1, steps, replayedMean, steppedMean,
                meanDifference, largestDeficit, carried);
    ASSERT_GT(replayedMean, 0.005) << "no foam to compare";
    // One level of the 8-bit sRGB output near the darkest greys.
    EXPECT_LE(largestDeficit, test::srgbToLinear(1)) << "the still shows foam its history did not make";
    EXPECT_LE(meanDifference, carried * steppedMean);
}

TEST_F(Whitecaps, AStillShowsTheFoamItsHistoryMade) { expectTheStillsFoamIsItsHistorys(3.85); }

// The same at the longest lifetime waves.foam_lifetime_s allows (60 s: 300
// replay steps; the sequence renders 300 frames, about 90 s on llvmpipe).
TEST_F(Whitecaps, AStillShowsTheFoamItsHistoryMadeAtTheLongestLifetime) { expectTheStillsFoamIsItsHistorys(60.0); }

// The mean covered share of the foam view straight down from 1200 m
// (1386 m across, inside level 1's window of 1536 m; the levels sample the
// same folds, so they have the same cover) over nine places of one frame,
// each replayed: 16 times the area of the views from 300 m for the same
// replays, so the cover of one time varies less from place to place.
double wideCoverAt(const Scene& scene, double time_s)
{
    constexpr int kWide = 256;
    Renderer renderer(scene);
    double white = 0.0;
    long long total = 0;
    for (int k = 0; k < 9; ++k) {
        Camera camera = cameraAt(scene.camera, 0.0);
        camera.position_m = {4937.0 * k, 1200.0, -7603.0 * k};
        camera.pitch_deg = -89.0;
        const Image image = renderer.renderImage(camera, time_s, {kWide, kWide});
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                white += test::srgbToLinear(image.pixel(x, y)[0]);
                ++total;
            }
    }
    return white / double(total);
}

// A still at t = 0 (swell render's default time) shows the sea the wind has
// been making for ever: its foam cover is that of a still at 60 s within 10%
// (issue 28, item 3). With history_start_s = 0 the foam starts at t = 0:
// a still there shows only the breaking of that instant.
TEST_F(Whitecaps, AStillAtTimeZeroShowsTheDevelopedFoam)
{
    Scene scene = foamScene(16.0);
    const double atZero = wideCoverAt(scene, 0.0), atSixty = wideCoverAt(scene, 60.0);
    scene.historyStart_s = 0.0;
    const double fromZero = wideCoverAt(scene, 0.0);
    std::printf("foam cover at t = 0: %.4f; at t = 60 s: %.4f; at t = 0 with the history starting there: %.4f\n",
                atZero, atSixty, fromZero);
    EXPECT_NEAR(atZero, atSixty, 0.1 * atSixty);
    EXPECT_LT(fromZero, 0.8 * atZero) << "history_start_s = 0 made no difference";
}

// No tiling of the foam (issue 12's criterion for the heightfield, applied
// to the foam): a view's correlation with the view one foam cascade's patch
// away (along x, and along the diagonal), averaged over three places, is at
// most 0.3 (a repeated patch gives 1). The anti-tiling warp and the foam
// kept in the world bring it there; the best correlation over every shift
// of up to 60 m (the warp moves a repeated patch nearly rigidly by tens of
// metres) is printed beside it, with that of unrelated places (chance).
TEST_F(Whitecaps, FoamDoesNotRepeatWithThePatches)
{
    const double windSpeed_mps = 16.0;
    const Scene scene = foamScene(windSpeed_mps);
    const spectral::SpectralField field =
        spectral::makeSpectralField(SeaSpectrum(*scene.sea.wind), scene.waves.choppiness, scene.sea.wind->seed);
    Renderer renderer(scene);
    // 346 m across: 1.8 m a pixel.
    const int maxShift = int(std::lround(60.0 / (2.0 * 300.0 * std::tan(30.0 * 3.14159265358979 / 180.0) / kWhitecapsView)));
    const glm::dvec2 places[] = {{0.0, 0.0}, {-5231.0, 3877.0}, {8123.0, -6311.0}};
    std::vector<std::vector<double>> views;
    for (const glm::dvec2 place : places)
        views.push_back(foamFrom300m(renderer, scene, place.x, place.y, 60.0));
    // Over the places, the mean correlation with the view `shift_m` away, and
    // the mean best over shifts of up to 60 m.
    auto compare = [&](glm::dvec2 shift_m, const char* what) {
        double exact = 0.0, best = 0.0;
        for (size_t k = 0; k < views.size(); ++k) {
            const glm::dvec2 at = places[k] + shift_m;
            const std::vector<double> there = foamFrom300m(renderer, scene, at.x, at.y, 60.0);
            exact += swell::test::correlation(views[k], there) / double(views.size());
            best += largestShiftedCorrelation(views[k], there, maxShift) / double(views.size());
        }
        std::printf("%s, shift (%.1f, %.1f) m: correlation %.3f, best within 60 m %.3f (means of 3 places)\n", what,
                    shift_m.x, shift_m.y, exact, best);
        return exact;
    };
    compare({1013.0, 707.0}, "unrelated places");
    for (int c = 0; c < spectral::kFoamCascades; ++c) {
        const double patch_m = field.cascades[size_t(c)].patch_m;
        for (const glm::dvec2 shift : {glm::dvec2(patch_m, 0.0), glm::dvec2(patch_m, patch_m)}) {
            const std::string what = "cascade " + std::to_string(c) + "'s patch";
            EXPECT_LT(compare(shift, what.c_str()), 0.3) << "the foam repeats with cascade " << c << "'s patch";
        }
    }
}

} // namespace
