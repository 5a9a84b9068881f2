// Anti-aliasing of the main pass and the render scale (swell::Renderer,
// render/render_target.*). A dark box floats high above the camera against
// the sky, turned so that its silhouette runs slanted across the pixels.
// Without anti-aliasing every pixel on that silhouette is either box or sky:
// hard steps. With MSAA, FXAA or a reduced render scale (its bilinear
// upscale), pixels on the edge take intermediate values. The debug views,
// which read the reflection and refraction targets, look the same with and
// without MSAA away from edges.
#include "support/expect_input_error.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"
#include "support/golden.h"
#include "support/stage.h"
#include "swell/renderer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

class Antialiasing : public swell::test::GlTest {};

constexpr glm::ivec2 kAntialiasingSize{160, 120};

// The box's edge against the sky is far brighter than anything on either
// side varies over three pixels: the sky's gradient moves a few levels, the
// box's flat faces not at all. So a 3x3 neighbourhood whose luma spans more
// than this holds an edge.
constexpr double kEdgeContrast = 60.0;
// A pixel on such an edge is "intermediate" when its luma lies at least this
// fraction of the span away from both the darkest and the brightest pixel
// around it. A hard step leaves every pixel within a few levels of one end
// (the sky's gradient, about 2% of the span); a pixel half covered sits at 50%.
constexpr double kIntermediateFraction = 0.2;

struct EdgeCount {
    int edges = 0;        // pixels whose 3x3 neighbourhood holds an edge
    int intermediate = 0; // of those, the ones between the two sides
    double share() const { return edges > 0 ? double(intermediate) / double(edges) : 0.0; }
};

double luma(const std::uint8_t* p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

EdgeCount countEdges(const swell::Image& image)
{
    EdgeCount count;
    for (int y = 1; y + 1 < image.height; ++y)
        for (int x = 1; x + 1 < image.width; ++x) {
            double lo = 255.0, hi = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const double l = luma(image.pixel(x + dx, y + dy));
                    lo = std::min(lo, l);
                    hi = std::max(hi, l);
                }
            if (hi - lo < kEdgeContrast)
                continue;
            ++count.edges;
            const double l = luma(image.pixel(x, y));
            const double margin = kIntermediateFraction * (hi - lo);
            count.intermediate += l > lo + margin && l < hi - margin;
        }
    return count;
}

// A 2 m box of one colour (linear RGB), written as a glTF file; returns its path.
std::string boxModel(const std::string& name, glm::vec3 color)
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "antialiasing";
    fs::create_directories(folder);
    swell::test::writeGltf(swell::test::makeBox(1.0f, color), folder / (name + ".gltf"));
    return (folder / (name + ".gltf")).string();
}

swell::Scene boxAgainstTheSky(swell::Antialiasing mode)
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    scene.sun.intensity = 0.0;
    // A 16 m box, nearly black so that it stands out from the bright sky.
    scene.objects = {{boxModel("dark_box", glm::vec3(0.02f)), {0.0, 30.0, -30.0}, 30.0, 8.0, false}};
    scene.camera.position_m = {0.0, 2.0, 0.0};
    scene.camera.yaw_deg = 0.0;
    scene.camera.pitch_deg = 40.0; // the water is below the frame
    scene.camera.path.clear();
    scene.antialiasing = mode;
    return scene;
}

swell::Image render(swell::Antialiasing mode, double renderScale, const std::string& name)
{
    const swell::Scene scene = boxAgainstTheSky(mode);
    swell::Renderer renderer(scene);
    renderer.setRenderScale(renderScale);
    const swell::Image image = renderer.renderImage(swell::cameraAt(scene.camera, 0.0), 0.0, kAntialiasingSize);
    swell::test::saveTestImage(image, name);
    return image;
}

// The share of edge pixels that are intermediate. An edge marks the pixels
// on both sides of it (3x3 neighbourhoods), so a one-pixel ramp makes at
// most about a third of them intermediate. Measured on this scene (Mesa
// 22.3 llvmpipe): off 0.000 (not one), msaa4 0.26, fxaa 0.45, msaa4 at
// render scale 0.5 0.88, render scale 0.5 without anti-aliasing 0.74. The
// bounds sit far from both groups.
constexpr double kHardShare = 0.05;   // at most this without anti-aliasing
constexpr double kSmoothShare = 0.15; // at least this with it

TEST_F(Antialiasing, OffLeavesOnlyHardStepsOnTheSilhouette)
{
    const EdgeCount off = countEdges(render(swell::Antialiasing::Off, 1.0, "antialiasing_off"));
    // The box is in the frame: its outline is over a hundred pixels long.
    EXPECT_GT(off.edges, 100);
    EXPECT_LE(off.share(), kHardShare) << off.intermediate << " of " << off.edges;
}

TEST_F(Antialiasing, Msaa4SmoothsTheSilhouette)
{
    const EdgeCount msaa = countEdges(render(swell::Antialiasing::Msaa4, 1.0, "antialiasing_msaa4"));
    EXPECT_GT(msaa.edges, 100);
    EXPECT_GE(msaa.share(), kSmoothShare) << msaa.intermediate << " of " << msaa.edges;
}

TEST_F(Antialiasing, FxaaSmoothsTheSilhouette)
{
    const EdgeCount fxaa = countEdges(render(swell::Antialiasing::Fxaa, 1.0, "antialiasing_fxaa"));
    EXPECT_GT(fxaa.edges, 100);
    EXPECT_GE(fxaa.share(), kSmoothShare) << fxaa.intermediate << " of " << fxaa.edges;
}

TEST_F(Antialiasing, MsaaAtAReducedScaleStillSmooths)
{
    // The resolve and the upscale are two steps (render_target.cpp).
    const EdgeCount scaled = countEdges(render(swell::Antialiasing::Msaa4, 0.5, "antialiasing_msaa4_half"));
    EXPECT_GE(scaled.share(), kSmoothShare) << scaled.intermediate << " of " << scaled.edges;
}

TEST_F(Antialiasing, DebugViewsReadTheirTargetsTheSameWithMsaa)
{
    // The water's debug views show the reflection and refraction targets,
    // looked up at gl_FragCoord, which MSAA of the main pass must not move:
    // away from the few edge pixels the two images are the same. On still
    // water a large magenta box stands above the surface (filling much of
    // the reflection) and another lies just under it (filling much of the
    // refraction), so a moved lookup moves something large.
    for (const swell::DebugView view : {swell::DebugView::Reflection, swell::DebugView::Refraction}) {
        swell::Scene scene = swell::test::emptyStage();
        scene.reflection.resolutionScale = 1.0;
        const std::string box = boxModel("magenta_box", glm::vec3(0.8f, 0.1f, 0.6f));
        scene.objects = {{box, {-12.0, 8.0, -50.0}, 20.0, 8.0, false}, {box, {4.0, -7.0, -22.0}, 20.0, 6.0, false}};
        scene.camera.position_m = {0.0, 8.0, 0.0};
        scene.camera.pitch_deg = -25.0;
        scene.debugView = view;
        scene.antialiasing = swell::Antialiasing::Off;
        swell::Renderer renderer(scene);
        const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
        const swell::Image off = renderer.renderImage(camera, 0.0, kAntialiasingSize);
        scene.antialiasing = swell::Antialiasing::Msaa4;
        renderer.setScene(scene);
        const swell::Image msaa = renderer.renderImage(camera, 0.0, kAntialiasingSize);
        swell::test::saveTestImage(msaa, "antialiasing_debug_view_" + std::to_string(int(view)));
        double sum = 0.0;
        int far = 0;
        for (size_t i = 0; i < off.rgba.size(); ++i) {
            const int d = std::abs(int(off.rgba[i]) - int(msaa.rgba[i]));
            sum += d;
            far += d > 24;
        }
        const double mean = sum / double(off.rgba.size());
        const double farShare = double(far) / double(off.rgba.size());
        // Measured (reflection, refraction): means of 0.14 and 0.50 levels,
        // 0.23% and 0.57% of the channels off by more than 24 levels (the
        // boxes' outlines). The refraction looked up with the viewport of a
        // target twice the size (a deliberate break) gave 4.7 and 6.1%.
        EXPECT_LT(mean, 1.0) << "debug view " << int(view);
        EXPECT_LT(farShare, 0.01) << "debug view " << int(view);
    }
}

TEST_F(Antialiasing, RenderScaleKeepsTheImageSizeAndScalesUpFiltered)
{
    const swell::Image full = render(swell::Antialiasing::Off, 1.0, "render_scale_1");
    const swell::Image half = render(swell::Antialiasing::Off, 0.5, "render_scale_0.5");
    ASSERT_EQ(half.width, kAntialiasingSize.x);
    ASSERT_EQ(half.height, kAntialiasingSize.y);
    // Drawn at 80x60 and scaled up bilinearly: the silhouette is a ramp
    // two output pixels wide, so it has intermediate pixels without AA.
    EXPECT_GE(countEdges(half).share(), kSmoothShare);
    // The same picture: the box where it was, within the blur (measured: a
    // mean difference of 1.0 level, all of it on the box's outline; a box
    // drawn elsewhere or at another size differs by tens of levels over its
    // whole area).
    double sum = 0.0;
    for (size_t i = 0; i < full.rgba.size(); ++i)
        sum += std::abs(int(full.rgba[i]) - int(half.rgba[i]));
    EXPECT_LT(sum / double(full.rgba.size()), 4.0);
}

TEST_F(Antialiasing, RenderScaleOutsideItsRangeIsRefused)
{
    swell::Renderer renderer(swell::defaultScene());
    for (const double bad : {0.0, -1.0, 5.0, 0.05, std::nan("")})
        EXPECT_THROW(renderer.setRenderScale(bad), swell::InputError) << bad;
    EXPECT_EQ(renderer.renderScale(), 1.0);
    renderer.setRenderScale(swell::kMaxRenderScale);
    EXPECT_EQ(renderer.renderScale(), swell::kMaxRenderScale);
}

} // namespace
