// The renderer embedded in a host that leaves unusual GL state behind:
// docs/LIBRARY.md promises that the renderer sets all the state it depends
// on. The frame drawn after the host's state must equal the frame drawn in a
// clean context, into the same sRGB-capable framebuffer (a window's default
// framebuffer often is one; GL_FRAMEBUFFER_SRGB only acts on such targets).
#include "support/gl_test.h"

#include "swell/camera.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/renderer.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

using swell::test::GlTest;

constexpr int kWidth = 160, kHeight = 90;

// A framebuffer with an sRGB colour attachment and a depth buffer.
struct SrgbTarget {
    swell::gl::Texture color = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    swell::gl::Texture depth = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    swell::gl::Framebuffer framebuffer = swell::gl::Framebuffer::create();
    SrgbTarget()
    {
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kWidth, kHeight);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT24, kWidth, kHeight);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    }
    std::vector<std::uint8_t> pixels() const
    {
        std::vector<std::uint8_t> rgba(std::size_t(kWidth) * kHeight * 4);
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

int largestDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
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

    renderer.render(camera, time_s, {kWidth, kHeight}, target.framebuffer.id());
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

    renderer.render(camera, time_s, {kWidth, kHeight}, target.framebuffer.id());
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
    EXPECT_EQ(largestDifference(clean, hosted), 0);
    // And a frame was drawn: the sky is not black.
    int brightest = 0;
    for (std::uint8_t v : clean)
        brightest = std::max(brightest, int(v));
    EXPECT_GT(brightest, 100);
}

} // namespace
