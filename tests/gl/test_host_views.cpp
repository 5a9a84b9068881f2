// Renderer::draw for a host: several views of one simulated time (split
// screen), the linear output encoding, the GL state it restores, and the
// bad views, framebuffers and callbacks it refuses with the host's frame
// left as it was.
#include "host_frame.h"
#include "support/gl_test.h"

#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/gl/shader_sources.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <epoxy/gl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using swell::test::GlTest;
using swell::test::HostBox;
using swell::test::HostScene;
using swell::test::HostTarget;

constexpr glm::ivec2 kHalf{160, 90};
constexpr glm::ivec2 kWhole{2 * kHalf.x, kHalf.y};

// One half of a side-by-side frame (x: 0 left, 1 right).
swell::View halfView(const swell::Camera& camera, int half)
{
    swell::View view = swell::viewOf(camera, kHalf);
    view.viewport = {half * kHalf.x, 0, kHalf.x, kHalf.y};
    return view;
}

// The pixels of a frame's half (bottom row first).
std::vector<std::uint8_t> halfOf(const std::vector<std::uint8_t>& rgba, int half)
{
    std::vector<std::uint8_t> out;
    for (int y = 0; y < kWhole.y; ++y) {
        const auto row = rgba.begin() + (std::ptrdiff_t(y) * kWhole.x + half * kHalf.x) * 4;
        out.insert(out.end(), row, row + std::ptrdiff_t(kHalf.x) * 4);
    }
    return out;
}

void clearHost(const HostTarget& target, glm::vec4 color = {0.2f, 0.1f, 0.3f, 1.0f})
{
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearColor(color.r, color.g, color.b, color.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

class HostViews : public GlTest {};

// Split screen: two views of one time, drawn side by side in one frame,
// are exactly what each draws alone, and drawing simulates nothing.
TEST_F(HostViews, SplitScreenDrawsEachViewAsAloneAndSimulatesOnce)
{
    const swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    swell::Renderer renderer(scene);
    const double time_s = 12.0;
    const swell::Camera a = swell::cameraAt(scene.camera, time_s);
    swell::Camera b = a;
    b.position_m += glm::dvec3(2400.0, 4.0, -1800.0); // far: its grid and foam lie elsewhere
    b.yaw_deg += 120.0;
    b.pitch_deg = -12.0;

    renderer.advanceTo(time_s, a.position_m);
    const swell::FrameCounters simulated = renderer.counters();
    EXPECT_EQ(simulated.simulationSteps, 1);
    EXPECT_GE(simulated.oceanTransforms, 1) << "the spectral ocean's FFTs ran in advanceTo()";

    HostTarget aloneA(kWhole), aloneB(kWhole), split(kWhole);
    clearHost(aloneA);
    renderer.draw(halfView(a, 0), aloneA.framebuffer());
    clearHost(aloneB);
    renderer.draw(halfView(b, 1), aloneB.framebuffer());
    clearHost(split);
    renderer.draw(halfView(a, 0), split.framebuffer());
    renderer.draw(halfView(b, 1), split.framebuffer());

    const swell::FrameCounters drawn = renderer.counters();
    EXPECT_EQ(drawn.views, 4);
    EXPECT_EQ(drawn.simulationSteps, 1) << "drawing four views took no step of its own";
    EXPECT_EQ(drawn.oceanTransforms, simulated.oceanTransforms);
    EXPECT_EQ(drawn.foamSteps, simulated.foamSteps);
    EXPECT_EQ(drawn.bodySteps, simulated.bodySteps);

    const std::vector<std::uint8_t> s = split.pixels(), pa = aloneA.pixels(), pb = aloneB.pixels();
    EXPECT_TRUE(halfOf(s, 0) == halfOf(pa, 0)) << "the left view is what it draws alone";
    EXPECT_TRUE(halfOf(s, 1) == halfOf(pb, 1)) << "the right view is what it draws alone";
    EXPECT_FALSE(halfOf(s, 0) == halfOf(s, 1)) << "the two views differ";

    // The same time and viewpoint again is no step; a new time is one.
    renderer.advanceTo(time_s, a.position_m);
    EXPECT_EQ(renderer.counters().simulationSteps, 0);
    renderer.advanceTo(time_s + 0.5, a.position_m);
    EXPECT_EQ(renderer.counters().simulationSteps, 1);
}

// A view draws only inside its viewport: the other half of the host's
// frame keeps the host's pixels.
TEST_F(HostViews, AViewDrawsOnlyInsideItsViewport)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    renderer.advanceTo(3.0, camera.position_m);
    HostTarget target(kWhole);
    clearHost(target);
    const std::vector<std::uint8_t> before = target.pixels();
    renderer.draw(halfView(camera, 1), target.framebuffer());
    const std::vector<std::uint8_t> after = target.pixels();
    EXPECT_TRUE(halfOf(after, 0) == halfOf(before, 0));
    EXPECT_FALSE(halfOf(after, 1) == halfOf(before, 1));
}

float srgbEncode(float linear)
{
    linear = std::max(linear, 0.0f);
    return linear < 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Linear output is the display frame before its sRGB encoding: encoded by
// the test, it matches the sRGB frame within a level of rounding.
TEST_F(HostViews, LinearOutputIsTheDisplayFrameBeforeItsEncoding)
{
    swell::Scene scene = swell::defaultScene();
    scene.antialiasing = swell::Antialiasing::Off;
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    renderer.advanceTo(3.0, camera.position_m);
    HostTarget display(kHalf), linear(kHalf, GL_RGBA16F);
    clearHost(display);
    clearHost(linear);
    const swell::View view = swell::viewOf(camera, kHalf);
    renderer.draw(view, display.framebuffer());
    swell::DrawOptions options;
    options.encoding = swell::OutputEncoding::Linear;
    renderer.draw(view, linear.framebuffer(), options);
    const std::vector<std::uint8_t> d = display.pixels();
    const std::vector<float> l = linear.floatPixels();
    int largest = 0, darkerThanDisplay = 0, midtones = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (i % 4 == 3)
            continue;
        const int encoded = int(std::lround(std::min(srgbEncode(l[i]), 1.0f) * 255.0f));
        largest = std::max(largest, std::abs(encoded - int(d[i])));
        // Linear values of mid-tones lie well below their display values.
        if (d[i] > 40 && d[i] < 215) {
            ++midtones;
            darkerThanDisplay += l[i] < float(d[i]) / 255.0f - 0.05f;
        }
    }
    EXPECT_LE(largest, 2) << "encoded linear frame vs the sRGB frame, levels of 255";
    EXPECT_GT(midtones, 1000);
    EXPECT_EQ(darkerThanDisplay, midtones) << "the linear frame is linear, not the display values";
}

// What a host's passes leave, read back through GL.
struct SavedHostState {
    GLint drawFramebuffer, readFramebuffer, program, vertexArray, activeTexture, depthFunc, frontFace, clipDepth;
    std::array<GLint, 4> viewport, scissor;
    std::array<GLboolean, 4> colorMask;
    GLboolean depthMask, blend, cull, scissorTest, srgb, depthTest, clip0;
    std::array<GLint, 2> polygonMode;
    std::array<GLfloat, 4> clearColor;
    GLint packAlignment, unpackAlignment;
    std::array<GLint, 4> blendFactors;
    GLint blendEquation;

    static SavedHostState read()
    {
        SavedHostState s{};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.drawFramebuffer);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.readFramebuffer);
        glGetIntegerv(GL_CURRENT_PROGRAM, &s.program);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vertexArray);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &s.activeTexture);
        glGetIntegerv(GL_DEPTH_FUNC, &s.depthFunc);
        glGetIntegerv(GL_FRONT_FACE, &s.frontFace);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &s.clipDepth);
        glGetIntegerv(GL_VIEWPORT, s.viewport.data());
        glGetIntegerv(GL_SCISSOR_BOX, s.scissor.data());
        glGetBooleanv(GL_COLOR_WRITEMASK, s.colorMask.data());
        glGetBooleanv(GL_DEPTH_WRITEMASK, &s.depthMask);
        s.blend = glIsEnabled(GL_BLEND);
        s.cull = glIsEnabled(GL_CULL_FACE);
        s.scissorTest = glIsEnabled(GL_SCISSOR_TEST);
        s.srgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
        s.depthTest = glIsEnabled(GL_DEPTH_TEST);
        s.clip0 = glIsEnabled(GL_CLIP_DISTANCE0);
        glGetIntegerv(GL_POLYGON_MODE, s.polygonMode.data());
        glGetFloatv(GL_COLOR_CLEAR_VALUE, s.clearColor.data());
        glGetIntegerv(GL_PACK_ALIGNMENT, &s.packAlignment);
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &s.unpackAlignment);
        glGetIntegerv(GL_BLEND_SRC_RGB, &s.blendFactors[0]);
        glGetIntegerv(GL_BLEND_DST_RGB, &s.blendFactors[1]);
        glGetIntegerv(GL_BLEND_SRC_ALPHA, &s.blendFactors[2]);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &s.blendFactors[3]);
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &s.blendEquation);
        return s;
    }
    bool operator==(const SavedHostState&) const = default;
};

// Unusual state a host may leave current when it calls draw().
swell::gl::VertexArray leaveUnusualState(const HostTarget& other, const HostScene& scene)
{
    swell::gl::VertexArray vao = swell::gl::VertexArray::create();
    scene.draw(glm::dmat4(1.0)); // its program bound
    glBindVertexArray(vao.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, other.framebuffer());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glActiveTexture(GL_TEXTURE5);
    glDepthFunc(GL_GEQUAL);
    glFrontFace(GL_CW);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glViewport(3, 4, 50, 60);
    glScissor(1, 2, 30, 40);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CLIP_DISTANCE0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glClearColor(0.3f, 0.2f, 0.1f, 0.5f);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    glBlendEquation(GL_MAX);
    return vao;
}

TEST_F(HostViews, TheGlStateAHostLeftIsTheStateItFindsAfterADraw)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    renderer.advanceTo(3.0, camera.position_m);
    HostTarget target(kHalf), other(kHalf);
    HostScene boxes({HostBox{{-2.0, 1.0, -20.0}, {2.0, 3.0, -16.0}, {1.0f, 0.0f, 0.0f}}});
    swell::DrawOptions options;
    options.geometry = &boxes;
    options.sceneWorld = true;
    clearHost(target);
    const swell::gl::VertexArray vao = leaveUnusualState(other, boxes);
    const SavedHostState before = SavedHostState::read();
    renderer.draw(swell::viewOf(camera, kHalf), target.framebuffer(), options);
    EXPECT_TRUE(SavedHostState::read() == before) << "draw() put back every piece of state it changed";
    // From under the water, with the pass that fogs the host's geometry (blending).
    swell::Camera under = camera;
    under.position_m.y = -3.0;
    renderer.advanceTo(3.0, under.position_m);
    renderer.draw(swell::viewOf(under, kHalf), target.framebuffer(), options);
    EXPECT_TRUE(SavedHostState::read() == before) << "draw() from under the water put back every piece of state";
    // And render(), which owns the frame, too.
    renderer.render(camera, 3.0, kHalf, target.framebuffer());
    EXPECT_TRUE(SavedHostState::read() == before) << "render() put back every piece of state it changed";
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glFrontFace(GL_CCW);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
    glUseProgram(0);
}

// advanceTo() runs compute passes (the spectral model's transforms, the
// frame's water queries) with programs of its own: the host's program is
// current again after it.
TEST_F(HostViews, AdvanceToLeavesTheHostsProgramCurrent)
{
    const swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    const swell::gl::Program host = swell::gl::buildProgram(
        swell::gl::ShaderSources::fromMap({{"host.comp", "layout(local_size_x = 1) in;\nvoid main() {}\n"}}),
        {{GL_COMPUTE_SHADER, "host.comp"}});
    glUseProgram(host.id());
    for (const double time_s : {3.0, 3.5}) {
        renderer.advanceTo(time_s, camera.position_m);
        GLint after = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &after);
        EXPECT_EQ(GLuint(after), host.id()) << "after advanceTo(" << time_s << ")";
    }
    glUseProgram(0);
}

// A program the host deleted while it was current lives until another is
// bound: the draw binds its own, and must not bind the dead name back (a GL
// error the fixture would report).
TEST_F(HostViews, AProgramTheHostDeletedWhileCurrentIsNotBoundBack)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    renderer.advanceTo(3.0, camera.position_m);
    HostTarget target(kHalf);
    clearHost(target);
    {
        HostScene boxes({HostBox{{-2.0, 1.0, -20.0}, {2.0, 3.0, -16.0}, {1.0f, 0.0f, 0.0f}}});
        boxes.draw(glm::dmat4(1.0)); // its program current, then deleted with it
    }
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    ASSERT_NE(current, 0) << "the deleted program is still current until another is bound";
    renderer.draw(swell::viewOf(camera, kHalf), target.framebuffer());
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    EXPECT_EQ(current, 0);
    glBindVertexArray(0);
}

// Each refusal: a swell::Error that says what, and the host's frame as it was.
TEST_F(HostViews, BadViewsFramebuffersAndCallbacksAreRefusedWithTheHostsFrameKept)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 3.0);
    HostTarget target(kHalf), noDepth(kHalf, GL_RGBA8, GL_NONE);
    clearHost(target);
    clearHost(noDepth);
    const std::vector<std::uint8_t> kept = target.pixels();
    const swell::View good = swell::viewOf(camera, kHalf);
    auto refused = [&](const swell::View& view, GLuint framebuffer, const swell::DrawOptions& options,
                       const std::string& says) {
        try {
            renderer.draw(view, framebuffer, options);
            ADD_FAILURE() << "not refused: " << says;
        } catch (const swell::Error& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
        EXPECT_TRUE(target.pixels() == kept) << says;
    };
    refused(good, target.framebuffer(), {}, "advanceTo");
    renderer.advanceTo(3.0, camera.position_m);
    swell::View view = good;
    view.viewport.z = 0;
    refused(view, target.framebuffer(), {}, "viewport is empty");
    view = good;
    view.projection = glm::dmat4(0.0);
    refused(view, target.framebuffer(), {}, "projection matrix");
    view = good;
    view.view[3][0] = std::nan("");
    refused(view, target.framebuffer(), {}, "view matrix");
    refused(good, noDepth.framebuffer(), {}, "no depth buffer");
    EXPECT_THROW(renderer.advanceTo(std::nan(""), camera.position_m), swell::Error);

    HostScene throwing({HostBox{{-2.0, 1.0, -20.0}, {2.0, 3.0, -16.0}, {1.0f, 0.0f, 0.0f}}});
    throwing.afterPass = [](const swell::PassView&) { throw std::runtime_error("the host's own failure"); };
    swell::DrawOptions options;
    options.geometry = &throwing;
    EXPECT_THROW(renderer.draw(good, target.framebuffer(), options), std::runtime_error);
    EXPECT_TRUE(target.pixels() == kept) << "a callback that throws";

    HostScene erring({HostBox{{-2.0, 1.0, -20.0}, {2.0, 3.0, -16.0}, {1.0f, 0.0f, 0.0f}}});
    erring.afterPass = [](const swell::PassView&) { glEnable(GLenum(0x7fff)); };
    options.geometry = &erring;
    // The first pass the host draws in, with the sea's waves: the contact
    // foam's (swell/view.h, PassKind::Contact).
    refused(good, target.framebuffer(), options, "GL error 0x0500 in the contact pass");
    // The debug output reported the host's error too: it was the point.
    GlTest::messages().clear();

    // An error the host left pending is not blamed on a callback, nor hidden.
    glEnable(GLenum(0x7fff));
    refused(good, target.framebuffer(), {}, "GL error 0x0500 was pending");
    GlTest::messages().clear();

    // After all that, the renderer still draws.
    renderer.draw(good, target.framebuffer());
    EXPECT_FALSE(target.pixels() == kept);
}

} // namespace
