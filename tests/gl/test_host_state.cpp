// The renderer embedded in a host that leaves unusual GL state behind:
// docs/LIBRARY.md promises that the renderer sets all the state it depends
// on. The frame drawn after the host's state must equal the frame drawn in a
// clean context, into the same sRGB-capable framebuffer (a window's default
// framebuffer often is one; GL_FRAMEBUFFER_SRGB only acts on such targets);
// and every piece of GL 4.5 state that changes a fragment, an upload or a
// read-back, left at a hostile value, must change nothing of render()'s,
// draw()'s, renderLabels()' or advanceTo()'s work, and be there afterwards.
#include "support/gl_test.h"

#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using swell::test::GlTest;

constexpr int kHostStateWidth = 160, kHostStateHeight = 90;

// A framebuffer with an sRGB colour attachment and a depth and stencil
// buffer (a stencil test a host leaves on acts only where there is one).
struct SrgbTarget {
    swell::gl::Texture color = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    swell::gl::Texture depth = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    swell::gl::Framebuffer framebuffer = swell::gl::Framebuffer::create();
    SrgbTarget()
    {
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kHostStateWidth, kHostStateHeight);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH24_STENCIL8, kHostStateWidth, kHostStateHeight);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth.id(), 0);
    }
    std::vector<std::uint8_t> pixels() const
    {
        std::vector<std::uint8_t> rgba(std::size_t(kHostStateWidth) * kHostStateHeight * 4);
        glFinish();
        glGetTextureImage(color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        return rgba;
    }
};

// A program of the host's own, left bound.
swell::gl::Program hostProgram()
{
    const auto sources = swell::gl::ShaderSources::fromMap({
        {"host.vert", "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n"},
        {"host.frag", "out vec4 colour; void main() { colour = vec4(1.0, 0.0, 1.0, 1.0); }\n"},
    });
    return swell::gl::buildProgram(sources, {{GL_VERTEX_SHADER, "host.vert"}, {GL_FRAGMENT_SHADER, "host.frag"}});
}

int hostStateLargestDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
{
    int largest = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        largest = std::max(largest, std::abs(int(a[i]) - int(b[i])));
    return largest;
}

class HostState : public GlTest {};

TEST_F(HostState, FrameIsTheSameAfterAHostLeftSrgbBlendingScissorAndItsProgram)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const double time_s = 3.0;
    const swell::Camera camera = swell::cameraAt(scene.camera, time_s);
    SrgbTarget target;

    renderer.render(camera, time_s, {kHostStateWidth, kHostStateHeight}, target.framebuffer.id());
    const std::vector<std::uint8_t> clean = target.pixels();

    // What a host (a UI library, a game's own passes) might leave behind.
    const swell::gl::Program program = hostProgram();
    const swell::gl::VertexArray vao = swell::gl::VertexArray::create();
    glUseProgram(program.id());
    glBindVertexArray(vao.id());
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_ADD);
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 10, 20, 20);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glDepthFunc(GL_NEVER);
    glDepthMask(GL_FALSE);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);

    renderer.render(camera, time_s, {kHostStateWidth, kHostStateHeight}, target.framebuffer.id());
    glUseProgram(0);
    glBindVertexArray(0);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const std::vector<std::uint8_t> hosted = target.pixels();

    // The same frame in the same context: the same pixels, exactly.
    EXPECT_EQ(hostStateLargestDifference(clean, hosted), 0);
    // And a frame was drawn: the sky is not black.
    int brightest = 0;
    for (std::uint8_t v : clean)
        brightest = std::max(brightest, int(v));
    EXPECT_GT(brightest, 100);
}

// Every piece of GL 4.5 state that would change Swell's fragments, uploads
// or read-backs, left at a hostile value, as engines and UI libraries leave
// it; the objects it binds live as long as this.
class HostileState {
public:
    HostileState()
    {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_NEVER, 0, 0xff);
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_XOR);
        glDepthRange(0.2, 0.9);
        for (GLenum offset : {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT})
            glEnable(offset);
        glPolygonOffset(4.0f, 64.0f);
        glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
        glEnable(GL_DEPTH_CLAMP);
        glEnable(GL_PRIMITIVE_RESTART);
        glPrimitiveRestartIndex(0);
        glDisable(GL_MULTISAMPLE);
        for (GLenum sample : {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK,
                              GL_SAMPLE_SHADING})
            glEnable(sample);
        glSampleCoverage(0.3f, GL_TRUE);
        glSampleMaski(0, 0x1u);
        glMinSampleShading(1.0f);
        glEnable(GL_LINE_SMOOTH);
        glEnable(GL_POLYGON_SMOOTH);
        glDisable(GL_DITHER);
        for (int i = 1; i < 8; ++i)
            glEnable(GLenum(GL_CLIP_DISTANCE0 + i));
        glEnable(GL_PROGRAM_POINT_SIZE);
        // A sampler object on every unit: nearest, mirrored, its mip level biased.
        glCreateSamplers(1, &sampler_);
        glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glSamplerParameteri(sampler_, wrap, GL_MIRRORED_REPEAT);
        glSamplerParameterf(sampler_, GL_TEXTURE_LOD_BIAS, 4.0f);
        for (GLuint unit = 0; unit < 32; ++unit)
            glBindSampler(unit, sampler_);
        glActiveTexture(GL_TEXTURE5);
        // Pixel buffers and pixel-store parameters: uploads and read-backs
        // would go through them.
        glCreateBuffers(3, buffers_.data());
        for (GLuint b : buffers_)
            glNamedBufferData(b, 64, nullptr, GL_STATIC_DRAW);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers_[0]);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[1]);
        glBindBuffer(GL_UNIFORM_BUFFER, buffers_[2]);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
        glPixelStorei(GL_PACK_ROW_LENGTH, 5);
        glPixelStorei(GL_PACK_SKIP_ROWS, 2);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    }
    ~HostileState()
    {
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_COLOR_LOGIC_OP);
        glDepthRange(0.0, 1.0);
        for (GLenum offset : {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT})
            glDisable(offset);
        glPolygonOffset(0.0f, 0.0f);
        glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_PRIMITIVE_RESTART);
        glEnable(GL_MULTISAMPLE);
        for (GLenum sample : {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK,
                              GL_SAMPLE_SHADING})
            glDisable(sample);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_POLYGON_SMOOTH);
        glEnable(GL_DITHER);
        for (int i = 1; i < 8; ++i)
            glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
        glDisable(GL_PROGRAM_POINT_SIZE);
        glBindSamplers(0, 32, nullptr);
        glDeleteSamplers(1, &sampler_);
        glActiveTexture(GL_TEXTURE0);
        glDeleteBuffers(3, buffers_.data());
        for (GLenum p : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
                         GL_PACK_SWAP_BYTES})
            glPixelStorei(p, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }
    HostileState(const HostileState&) = delete;
    HostileState& operator=(const HostileState&) = delete;

    // Whether all of it is still there (Swell put it back).
    void expectIntact() const
    {
        EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_TRUE(glIsEnabled(GL_COLOR_LOGIC_OP));
        EXPECT_TRUE(glIsEnabled(GL_POLYGON_OFFSET_FILL));
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_CLAMP));
        EXPECT_TRUE(glIsEnabled(GL_PRIMITIVE_RESTART));
        EXPECT_FALSE(glIsEnabled(GL_MULTISAMPLE));
        EXPECT_TRUE(glIsEnabled(GL_SAMPLE_SHADING));
        EXPECT_FALSE(glIsEnabled(GL_DITHER));
        EXPECT_TRUE(glIsEnabled(GL_CLIP_DISTANCE7));
        EXPECT_TRUE(glIsEnabled(GL_PROGRAM_POINT_SIZE));
        std::array<GLdouble, 2> range{};
        glGetDoublev(GL_DEPTH_RANGE, range.data());
        EXPECT_NEAR(range[0], 0.2, 1e-6); // kept in single precision
        EXPECT_NEAR(range[1], 0.9, 1e-6);
        EXPECT_EQ(integer(GL_PROVOKING_VERTEX), GL_FIRST_VERTEX_CONVENTION);
        EXPECT_EQ(integer(GL_LOGIC_OP_MODE), GL_XOR);
        EXPECT_EQ(integer(GL_ACTIVE_TEXTURE), GL_TEXTURE5);
        for (GLuint unit = 0; unit < 32; ++unit) {
            glActiveTexture(GL_TEXTURE0 + unit);
            EXPECT_EQ(GLuint(integer(GL_SAMPLER_BINDING)), sampler_) << "unit " << unit;
        }
        glActiveTexture(GL_TEXTURE5);
        EXPECT_EQ(GLuint(integer(GL_PIXEL_PACK_BUFFER_BINDING)), buffers_[0]);
        EXPECT_EQ(GLuint(integer(GL_PIXEL_UNPACK_BUFFER_BINDING)), buffers_[1]);
        EXPECT_EQ(GLuint(integer(GL_UNIFORM_BUFFER_BINDING)), buffers_[2]);
        EXPECT_EQ(integer(GL_UNPACK_ROW_LENGTH), 7);
        EXPECT_EQ(integer(GL_UNPACK_ALIGNMENT), 8);
        EXPECT_EQ(integer(GL_PACK_SKIP_ROWS), 2);
    }

private:
    static GLint integer(GLenum name)
    {
        GLint value = 0;
        glGetIntegerv(name, &value);
        return value;
    }
    GLuint sampler_ = 0;
    std::array<GLuint, 3> buffers_{};
};

// A frame, its labels and its objects' transforms, drawn by a fresh
// renderer (its first advanceTo() uploads what the scene needs).
struct Work {
    std::vector<std::uint8_t> frame, frameThrough, image;
    std::vector<float> range;
    std::vector<std::uint16_t> instance;
};

// draw() straight into `target` and through the view's own target into
// `through`, renderImage() and renderLabels().
Work work(const swell::Scene& scene, const SrgbTarget& target, const SrgbTarget& through, bool hostile)
{
    swell::Renderer renderer(scene);
    const double time_s = 3.0;
    const swell::Camera camera = swell::cameraAt(scene.camera, time_s);
    Work w;
    // The host's frame cleared, as a host clears before its scene.
    for (const SrgbTarget* t : {&target, &through}) {
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(t->framebuffer.id(), GL_COLOR, 0, black);
        glClearNamedFramebufferfi(t->framebuffer.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    }
    {
        std::unique_ptr<HostileState> state = hostile ? std::make_unique<HostileState>() : nullptr;
        renderer.advanceTo(time_s, camera.position_m);
        const swell::View view = swell::viewOf(camera, {kHostStateWidth, kHostStateHeight});
        renderer.draw(view, target.framebuffer.id(), {.sceneWorld = true});
        renderer.draw(view, through.framebuffer.id(),
                      {.sceneWorld = true, .renderScale = 0.5, .antialiasing = swell::Antialiasing::Msaa4});
        const swell::Image image = renderer.renderImage(camera, time_s, {kHostStateWidth, kHostStateHeight});
        const swell::FrameLabels labels = renderer.renderLabels(camera, {kHostStateWidth, kHostStateHeight});
        if (state)
            state->expectIntact();
        w.image = image.rgba;
        w.range = labels.range_m;
        w.instance = labels.instance;
    }
    w.frame = target.pixels();
    w.frameThrough = through.pixels();
    return w;
}

TEST_F(HostState, EveryPieceOfHostileStateLeavesTheWorkAsInACleanContextAndIsPutBack)
{
    for (const char* preset : {"default", "storm"}) {
        const swell::Scene scene = std::string(preset) == "default"
            ? swell::defaultScene()
            : swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
        SrgbTarget cleanTargets[2], hostileTargets[2];
        const Work clean = work(scene, cleanTargets[0], cleanTargets[1], false);
        const Work hostile = work(scene, hostileTargets[0], hostileTargets[1], true);
        // Frames were drawn: the sky lies over most of the frame.
        EXPECT_GT(std::count_if(clean.frame.begin(), clean.frame.end(), [](std::uint8_t v) { return v > 60; }),
                  long(clean.frame.size() / 4));
        EXPECT_EQ(hostStateLargestDifference(clean.frame, hostile.frame), 0) << preset << ": draw()";
        EXPECT_EQ(hostStateLargestDifference(clean.frameThrough, hostile.frameThrough), 0)
            << preset << ": draw() through the view's target";
        EXPECT_EQ(hostStateLargestDifference(clean.image, hostile.image), 0) << preset << ": renderImage()";
        EXPECT_TRUE(clean.range == hostile.range) << preset << ": renderLabels()' ranges";
        EXPECT_TRUE(clean.instance == hostile.instance) << preset << ": renderLabels()' instances";
    }
}

} // namespace
