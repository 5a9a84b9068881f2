// Reflections checked against geometry, not against earlier renders: a box
// of one colour floats above the water, and every pixel of the water that the
// box changes must lie where a mirror (flat water) or a rippled mirror (the
// slopes of known waves) could show it. Run for every reflection mode.
#include "support/camera_rays.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/param_names.h"
#include "support/gltf_writer.h"
#include "support/stage.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"
#include "swell/wave_model.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using swell::test::projectToPixel;

class Reflection : public swell::test::GlTest, public ::testing::WithParamInterface<swell::ReflectionMode> {};
// The default mode only: the paper's fixed-distance lookup is an approximation
// that finds the box only where the ray's point 5 m out happens to cover it.
class ReflectionRayMarch : public swell::test::GlTest {};

constexpr glm::ivec2 kReflectionSize{480, 360};

// The box: 3 m on a side, centred 3.5 m up and 40 m ahead, so it hangs
// 2 m above the water (its mirror image is apart from it, and nothing of it is
// under the water for the refraction to show).
constexpr double kHalf_m = 1.5;
const glm::dvec3 kCentre_m{0.0, 3.5, -40.0};

// A pixel "shows the box" when the box changes any channel by more than this
// many levels. The box is magenta and lit; the sky it hides is pale blue, so
// even at 5% Fresnel (the nearest water in view) its reflection moves red or
// green by more than 10 levels, while two renders of the same scene are
// identical on one machine (llvmpipe is deterministic), so nothing else moves.
constexpr int kChangedLevels = 6;

fs::path boxModel(const char* name = "box", glm::vec3 color = {0.9f, 0.05f, 0.7f})
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "reflection_box";
    fs::create_directories(folder);
    const fs::path path = folder / (std::string(name) + ".gltf");
    swell::test::writeGltf(swell::test::makeBox(float(kHalf_m), color), path);
    return path;
}

swell::Scene stage(swell::ReflectionMode mode, bool withBox)
{
    swell::Scene scene = swell::test::emptyStage();
    scene.reflection.mode = mode;
    // Full size: the 2 px bound is about the geometry, not the texture's
    // resolution (at the default 0.5 one texel covers 2 px).
    scene.reflection.resolutionScale = 1.0;
    scene.camera.position_m = {0.0, 3.0, 0.0};
    scene.camera.pitch_deg = -5.0;
    if (withBox)
        scene.objects.push_back({boxModel().string(), kCentre_m, 0.0, 1.0, false});
    return scene;
}

// A convex polygon in pixels (the hull of a box's projected corners).
using Polygon = std::vector<glm::dvec2>;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

Polygon convexHull(std::vector<glm::dvec2> points)
{
    std::sort(points.begin(), points.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    Polygon hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// Signed distance in pixels from p to the polygon's edge: negative inside.
double signedDistance(const Polygon& polygon, glm::dvec2 p)
{
    double nearest = 1e30;
    bool left = true, right = true; // on one side of every edge: inside, whichever the winding
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const glm::dvec2 ab = b - a;
        const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        nearest = std::min(nearest, glm::length(p - (a + s * ab)));
        left = left && cross(ab, p - a) >= 0.0;
        right = right && cross(ab, p - a) <= 0.0;
    }
    return left || right ? -nearest : nearest;
}

// The box as the camera sees it, directly or mirrored about the plane y = 0.
Polygon footprint(const swell::Camera& camera, bool mirrored, glm::dvec3 centre_m = kCentre_m)
{
    std::vector<glm::dvec2> corners;
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 c = centre_m + kHalf_m * glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
        if (mirrored)
            c.y = -c.y;
        corners.push_back(projectToPixel(camera, kReflectionSize, c));
    }
    return convexHull(corners);
}

bool changed(const swell::Image& a, const swell::Image& b, int x, int y)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])) > kChangedLevels)
            return true;
    return false;
}

// Pixels per radian of view angle at pixel row/column p: the focal length in
// pixels over cos^2 of the angle off the axis (d/da of f*tan(a)), the larger
// of the two axes.
double pixelsPerRadian(const swell::Camera& camera, glm::dvec2 p)
{
    const double focal_px = 0.5 * kReflectionSize.y / std::tan(glm::radians(camera.fovY_deg) * 0.5);
    const double tx = (p.x - 0.5 * kReflectionSize.x) / focal_px, ty = (p.y - 0.5 * kReflectionSize.y) / focal_px;
    return focal_px * (1.0 + std::max(tx * tx, ty * ty));
}

struct Tally {
    int outside = 0;      // box-changed water pixels farther than allowed from the mirror footprint
    int unfilled = 0;     // pixels well inside the mirror footprint the box left unchanged
    int reflected = 0;    // box-changed water pixels in all
    glm::ivec2 worst{-1}; // the farthest offender
    double worstDistance_px = 0.0;
};

// Every water pixel the box changes must lie within allowed_px(pixel) of its
// mirror footprint; with fill, every pixel 2 px inside it must be changed.
template <class Allowance>
Tally judge(const swell::Camera& camera, const swell::Image& with, const swell::Image& without, Allowance allowed_px,
            bool fill)
{
    const Polygon direct = footprint(camera, false);
    const Polygon mirror = footprint(camera, true);
    Tally t;
    for (int y = 0; y < kReflectionSize.y; ++y)
        for (int x = 0; x < kReflectionSize.x; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            // The box itself and its anti-aliased or rasterised edge.
            if (signedDistance(direct, p) <= 2.0)
                continue;
            const double d = signedDistance(mirror, p);
            if (changed(with, without, x, y)) {
                ++t.reflected;
                if (d > allowed_px(p)) {
                    ++t.outside;
                    if (d > t.worstDistance_px)
                        t.worstDistance_px = d, t.worst = {x, y};
                }
            } else if (fill && d < -2.0) {
                ++t.unfilled;
            }
        }
    return t;
}

std::string modeName(swell::ReflectionMode mode) { return mode == swell::ReflectionMode::FixedDistance ? "fixed" : "raymarch"; }

TEST_P(Reflection, CalmWaterMirrorsTheBoxIntoItsMirrorFootprintAndFillsIt)
{
    const swell::Scene withBox = stage(GetParam(), true);
    const swell::Camera camera = swell::cameraAt(withBox.camera, 0.0);
    swell::Renderer renderer(withBox);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Image with = renderer.renderImage(camera, 0.0, kReflectionSize);
    renderer.setScene(stage(GetParam(), false));
    const swell::Image without = renderer.renderImage(camera, 0.0, kReflectionSize);

    // 2 px: the bound; a pixel is 0.11 m at 40 m here, and rasterising
    // the box's edges into the reflection texture moves them up to a pixel.
    const Tally t = judge(camera, with, without, [](glm::dvec2) { return 2.0; }, true);
    const std::string name = "reflection_calm_" + modeName(GetParam());
    EXPECT_GT(t.reflected, 400) << "hardly any reflection of the box: " << swell::test::saveTestImage(with, name);
    EXPECT_EQ(t.outside, 0) << "box colour in the water outside its mirror image, worst at " << t.worst.x << ","
                            << t.worst.y << " (" << t.worstDistance_px << " px out): " << swell::test::saveTestImage(with, name);
    EXPECT_EQ(t.unfilled, 0) << "holes in the mirror image: " << swell::test::saveTestImage(with, name);
}

TEST_F(ReflectionRayMarch, AFaceSeenInTheMirrorHasTheColourItHasSeenDirectly)
{
    // The box's face towards the camera (normal +z) is seen both directly and
    // in flat water; lit by the same sun and sky it has one colour, and the
    // reflection alone (debug view) shows it unchanged. The sun is behind the
    // box, so that face gets only sky light: lit as if it faced the other
    // way, its mirror image would be several times brighter.
    swell::Scene scene = stage(swell::ReflectionMode::RayMarch, true);
    scene.debugView = swell::DebugView::Reflection;
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const swell::Image image = renderer.renderImage(camera, 0.0, kReflectionSize);
    const glm::dvec3 faceCentre = kCentre_m + glm::dvec3(0.0, 0.0, kHalf_m);
    const glm::dvec2 direct = projectToPixel(camera, kReflectionSize, faceCentre);
    const glm::dvec2 mirrored = projectToPixel(camera, kReflectionSize, faceCentre * glm::dvec3(1.0, -1.0, 1.0));
    const std::uint8_t* a = image.pixel(int(direct.x), int(direct.y));
    const std::uint8_t* b = image.pixel(int(mirrored.x), int(mirrored.y));
    // 3 levels: the face is one flat colour; its texel is sampled between
    // texels and stored as half floats before the output's 8 bits.
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(int(b[c]), int(a[c]), 3) << "channel " << c << ": " << swell::test::saveTestImage(image, "reflection_face_colour");
}

// Small sine ripples (steepness 0: no horizontal motion), their slopes summed.
swell::WaveSet ripples()
{
    swell::WaveSet set;
    set.waves = {{{1.0, 0.3}, 1.7, 0.002, 0.0, 0.0}, {{0.6, 1.0}, 2.9, 0.0035, 0.0, 1.3}, {{-0.8, 0.5}, 1.1, 0.0012, 0.0, 2.1}};
    return set;
}

// The scene with the box and without it, seen by one renderer from one
// camera at t = 3 s: what the box adds is where the two differ.
std::pair<swell::Image, swell::Image> renderWithAndWithout(const swell::Scene& withBox, const swell::Scene& without,
                                                           const swell::Camera& camera)
{
    swell::Renderer renderer(withBox);
    const double time_s = 3.0;
    swell::Image with = renderer.renderImage(camera, time_s, kReflectionSize);
    renderer.setScene(without);
    return {std::move(with), renderer.renderImage(camera, time_s, kReflectionSize)};
}

TEST_P(Reflection, RippledWaterKeepsTheBoxWithinWhatTheSlopesAllow)
{
    const swell::WaveSet set = ripples();
    // The surface y = sum A_i sin(k_i . x - w_i t + phi_i) has gradient
    // sum A_i k_i d_i cos(...), so its slope is at most sum A_i k_i (triangle
    // inequality), and the normal tilts at most atan of that from vertical.
    // Tilting a mirror by theta turns the reflected ray by at most 2 theta
    // (the law of reflection: the ray turns twice as far as the normal), and a point
    // met along a ray turned by 2 theta is seen from the eye at most 2 theta
    // from where the untilted ray's point is (the exterior angle of the
    // triangle eye, surface, point). The surface also stands up to sum A_i
    // above or below the plane the footprint mirrors about: at least 38 m
    // away (the box's nearest face), 2 sum A_i subtends at most 2 sum A_i / 38 m.
    double slope = 0.0, amplitude_m = 0.0;
    for (const swell::Wave& w : set.waves) {
        slope += w.amplitude_m * 2.0 * std::numbers::pi / w.wavelength_m;
        amplitude_m += w.amplitude_m;
    }
    const double bound_rad = 2.0 * std::atan(slope) + 2.0 * amplitude_m / (-kCentre_m.z - kHalf_m);
    ASSERT_LT(bound_rad, 0.06) << "the ripples are meant to be small";

    swell::Scene withBox = stage(GetParam(), true);
    withBox.waves.listed = set.waves;
    swell::Scene without = withBox;
    without.objects.clear();
    const swell::Camera camera = swell::cameraAt(withBox.camera, 0.0);
    const auto [with, withoutImage] = renderWithAndWithout(withBox, without, camera);

    // 2 px as on calm water, plus the angle the slopes allow in pixels.
    const Tally t = judge(
        camera, with, withoutImage, [&](glm::dvec2 p) { return 2.0 + bound_rad * pixelsPerRadian(camera, p); }, false);
    const std::string name = "reflection_ripples_" + modeName(GetParam());
    EXPECT_GT(t.reflected, 300) << "hardly any reflection of the box: " << swell::test::saveTestImage(with, name);
    EXPECT_EQ(t.outside, 0) << "box colour where no ripple could reflect it, worst at " << t.worst.x << ","
                            << t.worst.y << " (" << t.worstDistance_px << " px out, bound "
                            << bound_rad * pixelsPerRadian(camera, t.worst) << " px): " << swell::test::saveTestImage(with, name);
}

// Where each pixel's line of sight meets the rest plane y = 0; NaN where it
// sees no water.
std::vector<glm::dvec3> restPlanePoints(const swell::Camera& camera)
{
    std::vector<glm::dvec3> points(size_t(kReflectionSize.x) * kReflectionSize.y, glm::dvec3(std::nan("")));
    for (int y = 0; y < kReflectionSize.y; ++y)
        for (int x = 0; x < kReflectionSize.x; ++x) {
            const glm::dvec3 d = swell::test::pixelRay(camera, kReflectionSize, x, y);
            if (d.y < -1e-3)
                points[size_t(y) * kReflectionSize.x + x] = camera.position_m - camera.position_m.y / d.y * d;
        }
    return points;
}

bool rayMeetsBox(glm::dvec3 origin, glm::dvec3 r, glm::dvec3 centre_m, double half_m)
{
    const glm::dvec3 lo = centre_m - glm::dvec3(half_m), hi = centre_m + glm::dvec3(half_m);
    double enter = 0.0, exit = 1e30;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(r[a]) < 1e-12) {
            if (origin[a] < lo[a] || origin[a] > hi[a])
                return false;
            continue;
        }
        const double t0 = (lo[a] - origin[a]) / r[a], t1 = (hi[a] - origin[a]) / r[a];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return enter <= exit;
}

// Can a facet seen in pixel (x, y) send its reflected ray to the box? The
// normal is the wave model's, filtered by the pixel's footprint as water.frag
// filters it (fwidth of the rest point, from the pixel's 2x2 quad as the
// rasteriser takes derivatives). Where along the line of sight the facet is
// depends on the grid: it carries only the waves its cells resolve, so the
// drawn surface lies anywhere between the rest plane and the true surface,
// within the waves' height band; at a grazing view a few millimetres of
// height move the point by decimetres, a good part of a ripple. So every
// height in the band is tried (in steps of an eighth of the band): some
// (everyHeight: every) one of them must send the ray to the box.
bool facetSendsRayToBox(const swell::SurfaceQuery& waves, const swell::Camera& camera, double time_s,
                        const std::vector<glm::dvec3>& plane, double band_m, int x, int y, glm::dvec3 centre_m,
                        double half_m, bool everyHeight)
{
    auto at = [&](int u, int v) { return plane[size_t(std::min(v, kReflectionSize.y - 1)) * kReflectionSize.x + std::min(u, kReflectionSize.x - 1)]; };
    const glm::dvec3 onPlane = at(x, y);
    if (std::isnan(onPlane.x))
        return false;
    const int x0 = x & ~1, y0 = y & ~1;
    const glm::dvec3 dx = at(x0 + 1, y0) - at(x0, y0), dy = at(x0, y0 + 1) - at(x0, y0);
    double footprint_m = std::max(std::abs(dx.x) + std::abs(dy.x), std::abs(dx.z) + std::abs(dy.z));
    if (std::isnan(footprint_m))
        footprint_m = 0.0;
    const glm::dvec3 eye = camera.position_m;
    const glm::dvec3 d = glm::normalize(onPlane - eye);
    for (int j = -4; j <= 4; ++j) {
        const glm::dvec3 surface = eye + (band_m * j / 4.0 - eye.y) / d.y * d;
        const glm::dvec3 n = waves.surfaceAt({surface.x, surface.z}, time_s, {std::max(footprint_m, 1e-3), 1.0}).normal;
        if (rayMeetsBox(surface, d - 2.0 * glm::dot(d, n) * n, centre_m, half_m) != everyHeight)
            return !everyHeight;
    }
    return everyHeight;
}

TEST_F(ReflectionRayMarch, EveryReflectedPixelHasAFacetThatSendsItsRayToTheBox)
{
    // A harder stage than the others: a camera 8 m up (a ship's bridge),
    // ripples four times as steep (slope up to 0.09), the box standing just
    // clear of the crests 30 m out, and a grey wall far behind it. Many
    // reflected rays pass over the box and, in the reflection texture, behind
    // its mirror image: only geometry a ray really meets may show there.
    swell::Scene withBox = stage(swell::ReflectionMode::RayMarch, false);
    swell::WaveSet set = ripples();
    for (swell::Wave& w : set.waves)
        w.amplitude_m *= 4.0; // sum 0.027 m: the box's bottom at 0.05 m stays dry
    withBox.waves.listed = set.waves;
    withBox.camera.position_m = {0.0, 8.0, 0.0};
    withBox.camera.pitch_deg = -10.0;
    const glm::dvec3 centre_m{0.0, 0.05 + kHalf_m, -30.0};
    // The wall: the same 3 m cube scaled 12 times, 36 m, 400 m out.
    withBox.objects.push_back({boxModel("wall", {0.5f, 0.5f, 0.45f}).string(), {-10.0, 18.0, -400.0}, 0.0, 12.0, false});
    swell::Scene without = withBox;
    withBox.objects.push_back({boxModel().string(), centre_m, 0.0, 1.0, false});
    const swell::Camera camera = swell::cameraAt(withBox.camera, 0.0);
    // One renderer for both images and the facets' waves.
    swell::Renderer renderer(withBox);
    const double time_s = 3.0;
    const swell::Image with = renderer.renderImage(camera, time_s, kReflectionSize);
    renderer.setScene(without);
    const swell::Image withoutImage = renderer.renderImage(camera, time_s, kReflectionSize);

    // Grown by 2 texels' width at the box (the texture is full size: 1 texel
    // is a pixel's angle), for where the texture's edge pixels fall: a ray
    // passing that close to the box may find its edge texels.
    const double pixelAngle = 2.0 * std::tan(glm::radians(camera.fovY_deg) * 0.5) / kReflectionSize.y;
    const double margin_m = 2.0 * pixelAngle * (-centre_m.z + kHalf_m);
    std::vector<char> reaches(size_t(kReflectionSize.x) * kReflectionSize.y), surelyReaches(size_t(kReflectionSize.x) * kReflectionSize.y);
    const std::vector<glm::dvec3> plane = restPlanePoints(camera);
    double band_m = 0.0; // the highest the waves reach: sum of amplitudes
    for (const swell::Wave& w : set.waves)
        band_m += w.amplitude_m;
    for (int y = 0; y < kReflectionSize.y; ++y)
        for (int x = 0; x < kReflectionSize.x; ++x) {
            reaches[size_t(y) * kReflectionSize.x + x] =
                facetSendsRayToBox(renderer.waveModel(), camera, time_s, plane, band_m, x, y, centre_m, kHalf_m + margin_m, false);
            surelyReaches[size_t(y) * kReflectionSize.x + x] =
                facetSendsRayToBox(renderer.waveModel(), camera, time_s, plane, band_m, x, y, centre_m, kHalf_m - margin_m, true);
        }
    // 1 px: the CPU takes the facet at the pixel's centre, the GPU at the
    // fragment's (the same point) but from a rest point interpolated over a
    // grid triangle and derivatives shared by a 2x2 quad; a facet's edge may
    // sit a pixel off. (With 0 px the correct lookup shows 2 stray pixels.)
    auto within1px = [&](const std::vector<char>& map, int x, int y, bool all) {
        bool any = false, every = true;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int u = std::clamp(x + dx, 0, kReflectionSize.x - 1), v = std::clamp(y + dy, 0, kReflectionSize.y - 1);
                const bool hit = map[size_t(v) * kReflectionSize.x + u] != 0;
                any = any || hit;
                every = every && hit;
            }
        return all ? every : any;
    };
    const Polygon direct = footprint(camera, false, centre_m);
    int falseHits = 0, missed = 0, reflected = 0;
    glm::ivec2 firstFalse{-1}, firstMissed{-1};
    for (int y = 0; y < kReflectionSize.y; ++y)
        for (int x = 0; x < kReflectionSize.x; ++x) {
            if (signedDistance(direct, {x + 0.5, y + 0.5}) <= 2.0)
                continue;
            if (changed(with, withoutImage, x, y)) {
                ++reflected;
                if (!within1px(reaches, x, y, false) && falseHits++ == 0)
                    firstFalse = {x, y};
            } else if (within1px(surelyReaches, x, y, true) && missed++ == 0) {
                firstMissed = {x, y};
            }
        }
    const std::string path = swell::test::saveTestImage(with, "reflection_facets_raymarch");
    EXPECT_GT(reflected, 300) << path;
    EXPECT_EQ(falseHits, 0) << "box colour where no facet sends the ray to the box, first at " << firstFalse.x << ","
                            << firstFalse.y << ": " << path;
    EXPECT_EQ(missed, 0) << "no box where every facet around sends the ray to it, first at " << firstMissed.x << ","
                         << firstMissed.y << ": " << path;
    // 48 / 0.6, as for the other effects: llvmpipe repeats its pixels on one
    // machine, and another CPU's math library moves a few pixels on the
    // ripples' and the box's edges by a few levels; a reflection that lost
    // its ripples or smeared the box moves hundreds of pixels by tens.
    swell::test::expectMatchesGolden(with, "reflection_rippled_box", 48, 0.6);
}

INSTANTIATE_TEST_SUITE_P(Modes, Reflection, ::testing::Values(swell::ReflectionMode::FixedDistance, swell::ReflectionMode::RayMarch),
                         [](const ::testing::TestParamInfo<swell::ReflectionMode>& param) { return swell::paramName(param.param); });

} // namespace
