// The water drawn in two passes (render/water_visibility.h; issue 45): a
// visibility pass, then one shading run per water pixel.
//   - The picture is the one the grid shaded in its own fragments gives,
//     in presets of both wave models, from above and below the water, with
//     the wake's sources, and at a render scale resolved over time.
//   - The pipeline's counters show each water pixel shaded once (within
//     5%) at the render scales the viewer uses, where the one pass shades
//     it 1.3 times or more.
#include "support/gl_test.h"

#include "swell/debug.h"
#include "swell/image.h"
#include "swell/pass_observer.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"
#include "swell/gl/handle.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

using namespace swell;
namespace fs = std::filesystem;

class WaterTwoPasses : public test::GlTest {};

Scene preset(const char* name) { return loadScene(fs::path(SWELL_SOURCE_DIR) / "scenes" / (std::string(name) + ".toml")); }

Image renderWith(const Scene& scene, bool twoPasses, double time_s, glm::ivec2 size, double scale = 1.0,
                 bool temporal = false)
{
    Renderer renderer(scene);
    RendererTesting::setWaterInTwoPasses(renderer, twoPasses);
    renderer.setRenderScale(scale);
    renderer.setTemporalResolve(temporal);
    // Resolved over time: a few frames, so the history holds more than one.
    const int frames = temporal ? 4 : 1;
    Image image;
    for (int i = 0; i < frames; ++i) {
        const double t = time_s + (i - frames + 1) / 30.0;
        image = renderer.renderImage(renderer.sceneCameraAt(t), t, size);
    }
    return image;
}

// The share of pixels of which a channel differs by more than `levels`.
double shareBeyond(const Image& a, const Image& b, int levels)
{
    long long beyond = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])) > levels) {
                    ++beyond;
                    break;
                }
    return double(beyond) / double(a.width * a.height);
}

TEST_F(WaterTwoPasses, ThePictureIsTheOnePassOnes)
{
    constexpr glm::ivec2 kSize{192, 108};
    constexpr double kTime_s = 7.0;
    struct Case {
        const char* preset;
        double scale;
        bool temporal;
    };
    // The paper's Gerstner sea, the spectral storm (spray), the view from
    // under the water, a boat's wake (surface sources), and the viewer's
    // way: half scale, resolved over time; and a size that is no whole
    // number of the shading pass's tiles (58 x 32 at 0.3: the last
    // column's and row's tiles reach past the viewport).
    const Case cases[] = {{"paper", 1.0, false},     {"storm", 1.0, false},     {"underwater", 1.0, false},
                          {"under-way", 1.0, false}, {"trade-wind", 0.5, true}, {"paper", 0.3, false}};
    for (const Case& c : cases) {
        const Scene scene = preset(c.preset);
        Image one, two;
        if (c.temporal) {
            // A renderer each: the resolve's history is the frames before.
            one = renderWith(scene, false, kTime_s, kSize, c.scale, c.temporal);
            two = renderWith(scene, true, kTime_s, kSize, c.scale, c.temporal);
        } else {
            // One renderer drawing the same still both ways: a still does
            // not depend on the frames before it
            // (BodiesRender.SameTimeSameImageHoweverTheFramesFell), and the
            // bodies' history and the foam's replay are made once.
            Renderer renderer(scene);
            renderer.setRenderScale(c.scale);
            const Camera camera = renderer.sceneCameraAt(kTime_s);
            RendererTesting::setWaterInTwoPasses(renderer, false);
            one = renderer.renderImage(camera, kTime_s, kSize);
            RendererTesting::setWaterInTwoPasses(renderer, true);
            two = renderer.renderImage(camera, kTime_s, kSize);
        }
        const ImageDifference d = compareImages(one, two);
        const double beyond = shareBeyond(one, two, 8);
        std::printf("%s at scale %.1f%s: mean %.4f, max %d, %.3f%% of pixels beyond 8 levels\n", c.preset, c.scale,
                    c.temporal ? " resolved over time" : "", d.meanChannel, d.maxChannel, 100.0 * beyond);
        // What differs is the rasteriser's interpolation against the
        // shading pass's (the same weights, rounded otherwise), and at a
        // few triangle edges the derivatives of a quad that straddles two
        // triangles: measured (2026-12-07) at most a mean of 0.05 levels
        // for a frame drawn once and 0.143 for the trade wind resolved over
        // four frames at half scale (the one pass interpolates the warp's
        // lookups from the vertices, and the shading's footprint-long slope
        // filter sharpens what differs), and 0.04% of pixels beyond 8
        // levels. A misplaced triangle, a wrong weight or a footprint off by
        // a pixel moves whole regions.
        EXPECT_LT(d.meanChannel, 0.15) << c.preset;
        EXPECT_LT(beyond, 0.002) << c.preset;
        // Not the same bits: both ways were drawn (the interpolations'
        // roundings differ somewhere in every case, 2 to 30 levels at most).
        EXPECT_GT(d.maxChannel, 0) << c.preset << ": one way drawn twice";
        if (HasFailure()) {
            const std::string stem = std::string(SWELL_TEST_OUTPUT_DIR) + "/water-two-passes-" + c.preset;
            writePng(one, stem + "-one-pass.png");
            writePng(two, stem + "-two-passes.png");
            writePng(d.diff, stem + "-diff.png");
        }
    }
}

// Counts the fragment shader's runs and the samples written in one pass.
class PassCounter : public PassObserver {
public:
    explicit PassCounter(std::string pass) : pass_(std::move(pass)) {}
    void beginPass(const char* name) override
    {
        if (pass_ != name)
            return;
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, invocations_.id());
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
    }
    void endPass(const char* name) override
    {
        if (pass_ != name)
            return;
        glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint64 value = 0;
        glGetQueryObjectui64v(invocations_.id(), GL_QUERY_RESULT, &value);
        invocations += value;
        glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &value);
        samples += value;
    }
    unsigned long long invocations = 0, samples = 0;

private:
    static gl::Query generated()
    {
        GLuint name = 0;
        glGenQueries(1, &name);
        return gl::Query(name);
    }
    std::string pass_;
    // Mesa's glCreateQueries refuses the pipeline statistics targets in a
    // 4.5 context: a generated name takes its target when first begun.
    gl::Query invocations_ = generated();
    gl::Query samples_ = gl::Query::create(GLenum(GL_SAMPLES_PASSED));
};

// The water shading's runs a water pixel (the samples its pass writes).
double runsPerWaterPixel(const Scene& scene, bool twoPasses, double scale)
{
    Renderer renderer(scene);
    RendererTesting::setWaterInTwoPasses(renderer, twoPasses);
    renderer.setRenderScale(scale);
    // In one pass the water is shaded in "water" itself.
    PassCounter counter(twoPasses ? "water shading" : "water");
    renderer.setPassObserver(&counter);
    const double t_s = 7.0;
    renderer.renderImage(renderer.sceneCameraAt(t_s), t_s, {640, 360});
    renderer.setPassObserver(nullptr);
    EXPECT_GT(counter.samples, 0u);
    return double(counter.invocations) / double(std::max(counter.samples, 1ull));
}

TEST_F(WaterTwoPasses, EachWaterPixelIsShadedOnceAtEveryRenderScale)
{
    if (!epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query"))
        GTEST_SKIP() << "no pipeline statistics here";
    for (const char* name : {"paper", "trade-wind"}) {
        const Scene scene = preset(name);
        for (double scale : {1.0, 0.6, 0.3}) {
            const double two = runsPerWaterPixel(scene, true, scale);
            const double one = runsPerWaterPixel(scene, false, scale);
            std::printf("%s at scale %.1f: %.3f shading runs a water pixel in two passes, %.3f in one\n", name, scale,
                        two, one);
            EXPECT_LT(two, 1.05) << name << " at scale " << scale;
            EXPECT_GE(two, 1.0) << name << " at scale " << scale;
            // What the two passes are for: the one pass's overshading.
            EXPECT_GT(one, 1.3) << name << " at scale " << scale;
        }
    }
}

} // namespace
