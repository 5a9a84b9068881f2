// The host's motion vectors (DrawOptions::motionVectors, docs/LIBRARY.md
// "Motion vectors"; issue 46, item 2), held to what they should be from
// outside the pass's arithmetic: on still water with a camera that moves and
// turns, the analytic reprojection of each pixel's point (the sea's plane
// met by its centre ray, or its direction for the sky) into the previous
// draw's view; on a Gerstner sea and on the spectral storm seen by a still
// camera, the drawn surface's material point under the pixel (a CPU ray cast
// on swell::DrawnSurface at t) carried by its grid vertices to t - dt; on a
// floating body, its mesh's point (a CPU ray cast) at its previous pose.
// And the host's own pixels keep what the host wrote; nothing is written
// when the option is off.
#include "host_frame.h"
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/mesh_ray_cast.h"
#include "support/open_sea.h"
#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/drawn_surface.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using swell::test::GlTest;

class MotionVectors : public GlTest {};

// What the host's attachment is cleared to: no motion vector is this.
const glm::vec2 kUntouched{-777.0f, 555.0f};

// A host's framebuffer: RGBA8 colour at attachment 0 (its draw buffer),
// RG32F motion vectors at attachment 1, 32-bit float depth; `samples`
// samples a pixel (0: not multisampled), the vectors then resolved to be read.
class MotionTarget {
public:
    explicit MotionTarget(glm::ivec2 size, int samples = 0)
        : size_(size), samples_(samples), color_(make(GL_RGBA8)), motion_(make(GL_RG32F)),
          depth_(make(GL_DEPTH_COMPONENT32F)), framebuffer_(swell::gl::Framebuffer::create())
    {
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, motion_.id(), 0);
        glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
        if (samples_ > 0) {
            resolved_ = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
            glTextureStorage2D(resolved_.id(), 1, GL_RG32F, size.x, size.y);
            resolve_ = swell::gl::Framebuffer::create();
            glNamedFramebufferTexture(resolve_.id(), GL_COLOR_ATTACHMENT0, resolved_.id(), 0);
        }
    }
    GLuint framebuffer() const { return framebuffer_.id(); }

    // The host's frame begun: colour, depth (the convention's far) and the
    // motion vectors cleared; then its own boxes, if any.
    void begin(const swell::View& view, const swell::test::HostScene* boxes = nullptr) const
    {
        const bool reversed = view.depth == swell::DepthMode::Reversed;
        const float colour[4] = {0.1f, 0.9f, 0.1f, 1.0f}, untouched[4] = {kUntouched.x, kUntouched.y, 0.0f, 0.0f};
        const float far = reversed ? 0.0f : 1.0f;
        glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, colour);
        glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far);
        const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(framebuffer_.id(), 2, both);
        glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, untouched);
        glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
        if (!boxes)
            return;
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
        glViewport(0, 0, size_.x, size_.y);
        glClipControl(GL_LOWER_LEFT, view.depth == swell::DepthMode::Standard ? GL_NEGATIVE_ONE_TO_ONE : GL_ZERO_TO_ONE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(reversed ? GL_GREATER : GL_LESS);
        glDepthMask(GL_TRUE);
        boxes->draw(view.projection * view.view);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    }

    // The motion vectors, bottom row first.
    // The window depths, bottom row first.
    std::vector<float> depths() const
    {
        std::vector<float> d(std::size_t(size_.x) * std::size_t(size_.y));
        glFinish();
        glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(d.size() * sizeof(float)), d.data());
        return d;
    }

    std::vector<glm::vec2> motion() const
    {
        std::vector<glm::vec2> rg(std::size_t(size_.x) * std::size_t(size_.y));
        GLuint read = motion_.id();
        if (samples_ > 0) {
            glNamedFramebufferReadBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT1);
            glBlitNamedFramebuffer(framebuffer_.id(), resolve_.id(), 0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glNamedFramebufferReadBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
            read = resolved_.id();
        }
        glFinish();
        glGetTextureImage(read, 0, GL_RG, GL_FLOAT, GLsizei(rg.size() * sizeof(glm::vec2)), rg.data());
        return rg;
    }

private:
    swell::gl::Texture make(GLenum format) const
    {
        if (samples_ > 0) {
            swell::gl::Texture t = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D_MULTISAMPLE));
            glTextureStorage2DMultisample(t.id(), samples_, format, size_.x, size_.y, GL_TRUE);
            return t;
        }
        swell::gl::Texture t = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(t.id(), 1, format, size_.x, size_.y);
        return t;
    }
    glm::ivec2 size_;
    int samples_ = 0;
    swell::gl::Texture color_, motion_, depth_, resolved_;
    swell::gl::Framebuffer framebuffer_, resolve_;
};

// One draw of the host's: the simulation at time_s, then the view with
// motion vectors into attachment 1 (unless options say 0 explicitly).
std::vector<glm::vec2> drawMotion(swell::Renderer& renderer, const MotionTarget& target, const swell::View& view,
                                  double time_s, swell::DrawOptions options = {},
                                  const swell::test::HostScene* boxes = nullptr, bool motion = true)
{
    target.begin(view, boxes);
    renderer.advanceTo(time_s, view.eye_m());
    options.motionVectors = motion ? GL_COLOR_ATTACHMENT1 : 0;
    renderer.draw(view, target.framebuffer(), options);
    return target.motion();
}

// Where a world point (w = 1) or a direction (w = 0) is seen through
// viewProj, in window pixels of `viewport` (GL's lower-left origin).
glm::dvec2 windowOf(const glm::dmat4& viewProj, glm::dvec4 p, glm::ivec4 viewport)
{
    const glm::dvec4 clip = viewProj * p;
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return glm::dvec2(viewport.x, viewport.y) + (ndc * 0.5 + 0.5) * glm::dvec2(viewport.z, viewport.w);
}

// The unit world direction of the ray through window point w (pixels).
glm::dvec3 rayThrough(const swell::View& view, glm::dvec2 w)
{
    const glm::dvec4 v = view.viewport;
    const glm::dvec2 ndc = (w - glm::dvec2(v.x, v.y)) / glm::dvec2(v.z, v.w) * 2.0 - 1.0;
    const glm::dmat4 inverse = glm::inverse(view.projection * view.view);
    const double z = view.depth == swell::DepthMode::Standard ? 0.0 : 0.5; // any depth inside the frustum
    const glm::dvec4 p = inverse * glm::dvec4(ndc, z, 1.0);
    return glm::normalize(glm::dvec3(p) / p.w - view.eye_m());
}

swell::Camera cameraPosedAt(glm::dvec3 position_m, double yaw_deg, double pitch_deg, double roll_deg = 0.0)
{
    swell::Camera camera;
    camera.position_m = position_m;
    camera.yaw_deg = yaw_deg;
    camera.pitch_deg = pitch_deg;
    camera.roll_deg = roll_deg;
    return camera;
}

// A reversed-Z projection with its far plane at infinity (the host tests').
glm::dmat4 motionReversedInfinite(const glm::dmat4& standard, double near_m)
{
    glm::dmat4 p = standard;
    p[2][2] = 0.0;
    p[3][2] = near_m;
    return p;
}

glm::vec2 at(const std::vector<glm::vec2>& image, glm::ivec2 size, int x, int y)
{
    return image[std::size_t(y) * std::size_t(size.x) + std::size_t(x)];
}

bool untouched(glm::vec2 v) { return v == kUntouched; }

struct StillWaterCase {
    std::string name;
    bool reversedZ = false;
    double renderScale = 1.0;
    swell::Antialiasing antialiasing = swell::Antialiasing::Off;
    glm::ivec4 viewport{0, 0, 160, 120}; // in a 200 x 150 framebuffer
    int hostSamples = 0;                 // the host's framebuffer multisampled (its vectors resolved to be read)
};

void PrintTo(const StillWaterCase& c, std::ostream* os) { *os << c.name; }

class MotionVectorsOnStillWater : public MotionVectors, public ::testing::WithParamInterface<StillWaterCase> {};

// Flat water and the sky, a camera that moves 0.75 m and turns 2.5 degrees
// between two draws: each pixel's vector is where its point (the plane met
// by its centre ray; the sky's direction) was seen in the first draw.
TEST_P(MotionVectorsOnStillWater, EqualTheAnalyticReprojectionOfTheCamerasMotion)
{
    const StillWaterCase& c = GetParam();
    const glm::ivec2 framebuffer(200, 150);
    swell::Scene scene = swell::test::openSea();
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const glm::ivec2 size(c.viewport.z, c.viewport.w);
    auto viewOf = [&](const swell::Camera& camera) {
        swell::View view = swell::viewOf(camera, size);
        view.viewport = c.viewport;
        if (c.reversedZ) {
            view.projection = motionReversedInfinite(view.projection, 0.1);
            view.depth = swell::DepthMode::Reversed;
        }
        return view;
    };
    const swell::View before = viewOf(cameraPosedAt({0.0, 3.0, 0.0}, 0.0, -12.0, 3.0));
    const swell::View after = viewOf(cameraPosedAt({0.4, 3.15, -0.6}, 2.0, -10.5, 3.0));
    swell::DrawOptions options;
    options.renderScale = c.renderScale;
    options.antialiasing = c.antialiasing;
    MotionTarget target(framebuffer, c.hostSamples);
    drawMotion(renderer, target, before, 1.0, options);
    const std::vector<glm::vec2> motion = drawMotion(renderer, target, after, 1.0 + 1.0 / 30.0, options);

    const glm::dmat4 previousViewProj = before.projection * before.view;
    const glm::dvec3 eye = after.eye_m();
    double worstWater_px = 0.0, worstSky_px = 0.0, largest_px = 0.0;
    int water = 0, sky = 0, horizonUnwritten = 0;
    for (int y = 0; y < framebuffer.y; ++y)
        for (int x = 0; x < framebuffer.x; ++x) {
            const glm::vec2 v = at(motion, framebuffer, x, y);
            const bool inViewport = x >= c.viewport.x && y >= c.viewport.y && x < c.viewport.x + c.viewport.z &&
                                    y < c.viewport.y + c.viewport.w;
            if (!inViewport) {
                EXPECT_TRUE(untouched(v)) << "outside the viewport at " << x << ", " << y;
                continue;
            }
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const glm::dvec3 d = rayThrough(after, centre);
            // Pixels along the horizon's band (the grid's far end meeting
            // the sky, within 0.6 degrees of level) are neither case
            // exactly; drawn through the view's own target, the depth
            // written back there may be neither the sky's nor the grid's
            // at this resolution, and the host's value stays.
            if (std::abs(d.y) < 0.01) {
                horizonUnwritten += untouched(v) ? 1 : 0;
                continue;
            }
            ASSERT_FALSE(untouched(v)) << "Swell draws every pixel here (water or sky), yet " << x << ", " << y
                                       << " was not written";
            if (d.y < 0.0) {
                const double range_m = -eye.y / d.y;
                if (range_m > 1000.0)
                    continue;
                const glm::dvec2 expected = windowOf(previousViewProj, glm::dvec4(eye + range_m * d, 1.0), before.viewport) - centre;
                worstWater_px = std::max(worstWater_px, glm::length(glm::dvec2(v) - expected));
                largest_px = std::max(largest_px, glm::length(expected));
                ++water;
            } else {
                const glm::dvec2 expected = windowOf(previousViewProj, glm::dvec4(d, 0.0), before.viewport) - centre;
                worstSky_px = std::max(worstSky_px, glm::length(glm::dvec2(v) - expected));
                ++sky;
            }
        }
    EXPECT_GT(water, size.x * size.y / 4);
    EXPECT_GT(sky, size.x * size.y / 10);
    EXPECT_GT(largest_px, 5.0) << "the camera's motion must show";
    EXPECT_LT(worstWater_px, 0.05) << water << " water pixels";
    EXPECT_LT(worstSky_px, 0.05) << sky << " sky pixels";
    EXPECT_LT(horizonUnwritten, size.x / 4);
    RecordProperty("worst_water_px", std::to_string(worstWater_px));
    std::printf("%s: worst %.5f px over %d water pixels, %.5f px over %d sky pixels; %d of the horizon's band "
                "unwritten\n",
                c.name.c_str(), worstWater_px, water, worstSky_px, sky, horizonUnwritten);
    RecordProperty("worst_sky_px", std::to_string(worstSky_px));
}

INSTANTIATE_TEST_SUITE_P(
    Views, MotionVectorsOnStillWater,
    ::testing::Values(StillWaterCase{"Standard", false, 1.0, swell::Antialiasing::Off, {0, 0, 160, 120}},
                      StillWaterCase{"OffsetViewport", false, 1.0, swell::Antialiasing::Off, {30, 20, 160, 120}},
                      StillWaterCase{"ReversedZHalfScale", true, 0.5, swell::Antialiasing::Off, {0, 0, 160, 120}},
                      StillWaterCase{"Msaa", false, 1.0, swell::Antialiasing::Msaa4, {20, 10, 160, 120}},
                      StillWaterCase{"MultisampledHost", true, 1.0, swell::Antialiasing::Off, {10, 10, 160, 120}, 4}),
    [](const ::testing::TestParamInfo<StillWaterCase>& c) { return c.param.name; });

// Where the ray from `eye` along d first meets the drawn surface (bisection
// on the height above it, marching 0.25 m steps out to 300 m): the drawn
// point, or none.
std::optional<swell::DrawnPoint> drawnHit(const swell::DrawnSurface& surface, glm::dvec3 eye, glm::dvec3 d)
{
    auto above = [&](double s, std::optional<swell::DrawnPoint>& under) {
        const glm::dvec3 p = eye + s * d;
        under = surface.at({p.x, p.z});
        return under ? p.y - under->position_m.y : 1.0;
    };
    std::optional<swell::DrawnPoint> under;
    double lo = 0.0;
    for (double s = 0.25; s < 300.0; s += 0.25) {
        if (above(s, under) > 0.0) {
            lo = s;
            continue;
        }
        double hi = s;
        for (int i = 0; i < 50; ++i) {
            const double mid = 0.5 * (lo + hi);
            (above(mid, under) > 0.0 ? lo : hi) = mid;
        }
        above(hi, under);
        return under;
    }
    return std::nullopt;
}

struct SeaFigures {
    double worst_px = 0.0;
    double median_px = 0.0; // of the expected vectors: how much the water moved
    int pixels = 0;
};

// A still camera over `scene`'s sea, drawn at each of `times_s`: the last
// draw's vectors against the drawn surface's material points (every third
// pixel of the water within 300 m).
SeaFigures seaAgainstDrawnSurface(const swell::Scene& scene, const std::vector<double>& times_s)
{
    swell::Renderer renderer(scene);
    const glm::ivec2 size(160, 120);
    const swell::Camera camera = cameraPosedAt({0.0, 6.0, 0.0}, 20.0, -18.0);
    const swell::View view = swell::viewOf(camera, size);
    MotionTarget target(size);
    std::vector<glm::vec2> motion;
    for (double t : times_s)
        motion = drawMotion(renderer, target, view, t);
    const double now_s = times_s.back(), previous_s = times_s[times_s.size() - 2];
    const swell::DrawnSurface nowSurface = renderer.drawnSurface(camera, now_s);
    const swell::DrawnSurface previousSurface = renderer.drawnSurface(camera, previous_s);
    const glm::dmat4 viewProj = view.projection * view.view;
    SeaFigures figures;
    std::vector<double> moved;
    for (int y = 0; y < size.y; y += 3)
        for (int x = 0; x < size.x; x += 3) {
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const glm::dvec3 d = rayThrough(view, centre);
            if (d.y > -0.05)
                continue;
            const std::optional<swell::DrawnPoint> hit = drawnHit(nowSurface, view.eye_m(), d);
            if (!hit)
                continue;
            glm::dvec3 previous(0.0);
            for (int k = 0; k < 3; ++k)
                previous += hit->weights[k] * previousSurface.vertex(hit->corners[std::size_t(k)].x,
                                                                     hit->corners[std::size_t(k)].y);
            const glm::dvec2 expected = windowOf(viewProj, glm::dvec4(previous, 1.0), view.viewport) - centre;
            figures.worst_px = std::max(figures.worst_px, glm::length(glm::dvec2(at(motion, size, x, y)) - expected));
            moved.push_back(glm::length(expected));
        }
    figures.pixels = int(moved.size());
    if (!moved.empty()) {
        std::nth_element(moved.begin(), moved.begin() + std::ptrdiff_t(moved.size() / 2), moved.end());
        figures.median_px = moved[moved.size() / 2];
    }
    return figures;
}

// Enough water seen moving, each pixel's vector within 0.1 px of the
// drawn surface's motion; the figures printed and recorded.
void expectTheWatersOwnMotion(const SeaFigures& f)
{
    EXPECT_GT(f.pixels, 500);
    EXPECT_GT(f.median_px, 0.3) << "the waves' own motion must show";
    EXPECT_LT(f.worst_px, 0.1) << f.pixels << " pixels";
    testing::Test::RecordProperty("worst_px", std::to_string(f.worst_px));
    testing::Test::RecordProperty("median_motion_px", std::to_string(f.median_px));
    std::printf("worst %.5f px over %d water pixels moving %.3f px (median)\n", f.worst_px, f.pixels, f.median_px);
}

// A Gerstner sea and a still camera: the water's own motion between two
// draws 0.1 s apart is the drawn surface's at t and t - dt.
TEST_F(MotionVectors, OnAGerstnerSeaFollowTheDrawnSurfacesMaterialPoints)
{
    const SeaFigures f = seaAgainstDrawnSurface(swell::test::openSea(), {2.0, 2.1});
    expectTheWatersOwnMotion(f);
}

// The spectral storm: the vectors need the previous draw's cascades, which
// the model keeps from the draw that first asked for motion vectors on.
TEST_F(MotionVectors, OnTheSpectralStormFollowThePreviousCascades)
{
    const SeaFigures f =
        seaAgainstDrawnSurface(swell::test::openSpectralStorm(), {3.0, 3.0 + 1.0 / 30.0, 3.0 + 2.0 / 30.0});
    expectTheWatersOwnMotion(f);
}

// A boat under way, heaving and rolling, seen by a still camera from its
// side: its pixels' vectors are its mesh's points (a CPU ray cast at its
// pose now) at its pose in the previous draw.
TEST_F(MotionVectors, OnAFloatingBodyFollowItsMeshsPoints)
{
    swell::Scene scene = swell::test::openSea();
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = glm::dvec3(12.0, 0.0, -14.0);
    boat.yaw_deg = 90.0;
    boat.floats = true;
    boat.density_kg_per_m3 = 400.0;
    boat.velocity_m_per_s = glm::dvec3(-4.0, 0.0, 0.0);
    scene.objects.push_back(boat);
    swell::Renderer renderer(scene);
    const glm::ivec2 size(240, 180);
    const swell::Camera camera = cameraPosedAt({0.0, 1.0, 0.0}, 0.0, -2.0);
    const swell::View view = swell::viewOf(camera, size);
    swell::DrawOptions options;
    options.sceneWorld = true;
    MotionTarget target(size);
    const double previous_s = 4.0, now_s = 4.0 + 1.0 / 30.0;
    drawMotion(renderer, target, view, previous_s, options);
    const glm::dmat4 previousPose = renderer.objectTransforms().at(0);
    const std::vector<glm::vec2> motion = drawMotion(renderer, target, view, now_s, options);
    const glm::dmat4 pose = renderer.objectTransforms().at(0);

    const std::vector<float> depth = target.depths();
    const swell::DrawnSurface surface = renderer.drawnSurface(view.eye_m());
    const swell::detail::MeshData mesh = swell::detail::makeBuiltinModel("boat");
    const glm::dmat4 viewProj = view.projection * view.view;
    const glm::dmat4 fromWindow = glm::inverse(viewProj);
    // How far from the eye the drawn point of pixel (x, y) is, by the depth.
    auto drawnDistance = [&](int x, int y) {
        const double z = 2.0 * depth[std::size_t(y) * std::size_t(size.x) + std::size_t(x)] - 1.0;
        const glm::dvec4 p = fromWindow * glm::dvec4((x + 0.5) / size.x * 2.0 - 1.0, (y + 0.5) / size.y * 2.0 - 1.0, z, 1.0);
        return glm::length(glm::dvec3(p) / p.w - view.eye_m());
    };
    double worst_px = 0.0, largest_px = 0.0;
    int onBoat = 0, hidden = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            // Only pixels whose four neighbours show the boat too (its
            // outline's pixels are the water's or the boat's by a hair).
            bool inside = true;
            std::optional<swell::test::MeshHit> hit;
            for (glm::ivec2 o : {glm::ivec2(0, 0), glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
                const auto h = swell::test::rayHitOnMesh(mesh, pose, view.eye_m(), rayThrough(view, centre + glm::dvec2(o)));
                inside = inside && h.has_value();
                if (o == glm::ivec2(0, 0))
                    hit = h;
                if (!inside)
                    break;
            }
            if (!inside)
                continue;
            // Where the drawn point is not the mesh's (a crest in front of
            // the hull, the lid the open hull's volume puts at its
            // gunwale), the pixel's vector is that point's.
            if (std::abs(drawnDistance(x, y) - hit->distance_m) > 0.01) {
                ++hidden;
                continue;
            }
            // At the waterline the water and the hull meet within the
            // depth's tolerance: either's vector may be the pixel's.
            const glm::dvec3 point(pose * glm::dvec4(hit->model_m, 1.0));
            const std::optional<swell::DrawnPoint> water = surface.at({point.x, point.z});
            if (water && point.y - water->position_m.y < 0.15)
                continue;
            const glm::dvec3 previous(previousPose * glm::dvec4(hit->model_m, 1.0));
            const glm::dvec2 expected = windowOf(viewProj, glm::dvec4(previous, 1.0), view.viewport) - centre;
            worst_px = std::max(worst_px, glm::length(glm::dvec2(at(motion, size, x, y)) - expected));
            largest_px = std::max(largest_px, glm::length(expected));
            ++onBoat;
        }
    EXPECT_GT(onBoat, 200) << hidden << " hidden";
    EXPECT_GT(largest_px, 1.5) << "the boat's motion must show";
    EXPECT_LT(worst_px, 0.1) << onBoat << " boat pixels";
    RecordProperty("worst_px", std::to_string(worst_px));
    std::printf("floating body: worst %.5f px over %d pixels moving up to %.2f px (%d hidden)\n", worst_px, onBoat,
                largest_px, hidden);
}

// Where the ray from eye along d meets the box [lo, hi] (the slab test),
// or a negative distance where it misses.
double rayHitOnBox(glm::dvec3 eye, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi)
{
    double near = 0.0, far = 1e30;
    for (int a = 0; a < 3; ++a) {
        const double t0 = (lo[a] - eye[a]) / d[a], t1 = (hi[a] - eye[a]) / d[a];
        near = std::max(near, std::min(t0, t1));
        far = std::min(far, std::max(t0, t1));
    }
    return near <= far ? near : -1.0;
}

// The host's box, above the waves in front of the camera, keeps the host's
// value in the attachment (depth-tested as the water is), a view's first
// draw writes zero, and with the option off nothing is written and nothing
// drawn for it.
TEST_F(MotionVectors, LeaveTheHostsPixelsAndAnOptionOffAlone)
{
    swell::Renderer renderer(swell::test::openSea());
    const glm::ivec2 size(160, 120);
    const swell::View view = swell::viewOf(cameraPosedAt({0.0, 3.0, 0.0}, 0.0, -10.0), size);
    const glm::dvec3 lo(-1.0, 1.2, -9.0), hi(1.0, 2.5, -7.0);
    const swell::test::HostScene boxes({{lo, hi, {1.0f, 0.0f, 0.0f}}});
    MotionTarget target(size);
    const std::vector<glm::vec2> first = drawMotion(renderer, target, view, 1.0, {}, &boxes);
    const std::vector<glm::vec2> second = drawMotion(renderer, target, view, 1.0 + 1.0 / 30.0, {}, &boxes);
    EXPECT_GT(renderer.counters().motionVectorDraws, 0);
    auto onBox = [&](int x, int y) { return rayHitOnBox(view.eye_m(), rayThrough(view, {x + 0.5, y + 0.5}), lo, hi) > 0.0; };
    int host = 0, swell = 0;
    float firstLargest_px = 0.0f;
    for (int y = 1; y + 1 < size.y; ++y)
        for (int x = 1; x + 1 < size.x; ++x) {
            const bool box = onBox(x, y);
            // The box's outline: its pixels are the host's or Swell's by a hair.
            if (box != onBox(x + 1, y) || box != onBox(x - 1, y) || box != onBox(x, y + 1) || box != onBox(x, y - 1))
                continue;
            if (box) {
                ++host;
                EXPECT_TRUE(untouched(at(second, size, x, y))) << "the host's pixel " << x << ", " << y;
            } else {
                ++swell;
                EXPECT_FALSE(untouched(at(second, size, x, y))) << "Swell's pixel " << x << ", " << y;
                firstLargest_px = std::max(firstLargest_px, glm::length(at(first, size, x, y)));
            }
        }
    EXPECT_GT(host, 300);
    EXPECT_GT(swell, 10000);
    EXPECT_LT(firstLargest_px, 1e-6f) << "a view's first draw has no previous one: zero";

    const std::vector<glm::vec2> off = drawMotion(renderer, target, view, 1.0 + 2.0 / 30.0, {}, &boxes, false);
    EXPECT_EQ(renderer.counters().motionVectorDraws, 0);
    EXPECT_EQ(renderer.counters().motionVectorTriangles, 0);
    EXPECT_EQ(std::count_if(off.begin(), off.end(), untouched), std::ptrdiff_t(off.size()));
}

// A framebuffer with no float attachment there is refused before anything is drawn.
TEST_F(MotionVectors, RefuseAnAttachmentTheyCannotBeWrittenTo)
{
    swell::Renderer renderer(swell::test::openSea());
    const glm::ivec2 size(64, 48);
    const swell::View view = swell::viewOf(cameraPosedAt({0.0, 3.0, 0.0}, 0.0, -10.0), size);
    swell::test::HostTarget host(size);
    renderer.advanceTo(1.0, view.eye_m());
    swell::DrawOptions options;
    options.motionVectors = GL_COLOR_ATTACHMENT1; // nothing there
    EXPECT_THROW(renderer.draw(view, host.framebuffer(), options), swell::Error);
    options.motionVectors = GL_COLOR_ATTACHMENT0; // RGBA8: not a float format
    EXPECT_THROW(renderer.draw(view, host.framebuffer(), options), swell::Error);
    options.motionVectors = 7; // not an attachment
    EXPECT_THROW(renderer.draw(view, host.framebuffer(), options), swell::Error);
}

} // namespace
