#include "render/render_target.h"

#include "render/programs.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/renderer.h"

#include <fmt/format.h>
#include <glm/common.hpp>

#include <cmath>

namespace swell::detail {

namespace {

gl::Texture makeTexture(glm::ivec2 size, GLenum format, int samples, GLenum filter)
{
    if (samples > 1) {
        gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D_MULTISAMPLE));
        // Fixed sample locations: the same pattern in colour and depth.
        glTextureStorage2DMultisample(t.id(), samples, format, size.x, size.y, GL_TRUE);
        return t; // multisample textures have no sampler state
    }
    gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(t.id(), 1, format, size.x, size.y);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

} // namespace

void RenderTarget::resize(glm::ivec2 size, GLenum colorFormat, int samples)
{
    if (size == size_ && colorFormat == colorFormat_ && samples == samples_)
        return;
    colorFormat_ = colorFormat;
    samples_ = samples;
    framebuffer_.reset();
    color_.reset();
    depth_.reset();
    size_ = size;
    if (size.x <= 0 || size.y <= 0) {
        size_ = {0, 0};
        return;
    }
    if (samples > 1) {
        GLint supported = 0;
        glGetIntegerv(GL_MAX_SAMPLES, &supported);
        if (samples > supported)
            throw Error(fmt::format("swell::RenderTarget::resize(): {} samples asked, the GL supports {}", samples,
                                    supported));
    }
    // Half floats for intermediate images: the sun's highlight exceeds 1.
    color_ = makeTexture(size, colorFormat, samples, GL_LINEAR);
    depth_ = makeTexture(size, GL_DEPTH_COMPONENT32F, samples, GL_NEAREST);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("swell::RenderTarget::resize(): framebuffer incomplete");
}

GLuint MainTarget::begin(glm::ivec2 drawSize, glm::ivec4 outputViewport, GLuint output, Antialiasing antialiasing,
                         bool ownTarget, GLenum colorFormat)
{
    drawSize_ = drawSize;
    outputViewport_ = outputViewport;
    output_ = output;
    antialiasing_ = antialiasing;
    const bool scaled = drawSize != glm::ivec2(outputViewport.z, outputViewport.w);
    direct_ = antialiasing == Antialiasing::Off && !scaled && !ownTarget;
    // The main pass writes display-ready (sRGB-encoded) colour in 0..1, as
    // the output holds it: 8 bits a channel lose nothing the output keeps
    // (a linear output's colour is kept in half floats).
    const bool msaa = antialiasing == Antialiasing::Msaa4;
    multisampled_.resize(msaa ? drawSize : glm::ivec2(0), colorFormat, kMsaaSamples);
    single_.resize(direct_ ? glm::ivec2(0) : drawSize, colorFormat);
    // FXAA draws straight into the output only at its size and corner (the
    // filter reads the pixel it writes by its window position).
    const bool fxaaDirect = !scaled && outputViewport.x == 0 && outputViewport.y == 0;
    const bool fxaaThenCopy = antialiasing == Antialiasing::Fxaa && !fxaaDirect;
    filtered_.resize(fxaaThenCopy ? drawSize : glm::ivec2(0), colorFormat);
    if (direct_)
        return output;
    return msaa ? multisampled_.framebuffer() : single_.framebuffer();
}

GLuint MainTarget::resolvedDepth()
{
    if (antialiasing_ == Antialiasing::Msaa4)
        glBlitNamedFramebuffer(multisampled_.framebuffer(), single_.framebuffer(), 0, 0, drawSize_.x, drawSize_.y, 0,
                               0, drawSize_.x, drawSize_.y, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    return single_.depth();
}

void MainTarget::blitToOutput(const RenderTarget& from) const
{
    // Equal sizes copy pixel for pixel; a render scale is filtered
    // bilinearly (at scale 2, exactly the mean of each 2x2 block).
    const glm::ivec4 o = outputViewport_;
    const GLenum filter = drawSize_ == glm::ivec2(o.z, o.w) ? GL_NEAREST : GL_LINEAR;
    glBlitNamedFramebuffer(from.framebuffer(), output_, 0, 0, drawSize_.x, drawSize_.y, o.x, o.y, o.x + o.z, o.y + o.w,
                           GL_COLOR_BUFFER_BIT, filter);
}

int MainTarget::present(const FxaaProgram& fxaa, GLuint emptyVao)
{
    if (direct_)
        return 0;
    int draws = 0;
    // Blits obey the scissor test and the colour mask: the passes leave the
    // former off and the latter open, but say so here too.
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (antialiasing_ == Antialiasing::Msaa4) {
        // The resolve averages each pixel's samples. It needs equal sizes and
        // formats, so it goes through single_, never straight to a window.
        glBlitNamedFramebuffer(multisampled_.framebuffer(), single_.framebuffer(), 0, 0, drawSize_.x, drawSize_.y, 0,
                               0, drawSize_.x, drawSize_.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    if (antialiasing_ == Antialiasing::Fxaa) {
        const bool viaCopy = filtered_.size().x > 0;
        glBindFramebuffer(GL_FRAMEBUFFER, viaCopy ? filtered_.framebuffer() : output_);
        glViewport(0, 0, drawSize_.x, drawSize_.y);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_FRAMEBUFFER_SRGB);
        fxaa.use();
        glBindTextureUnit(SWELL_UNIT_POST_SOURCE, single_.color());
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++draws;
        glEnable(GL_DEPTH_TEST);
        if (viaCopy)
            blitToOutput(filtered_);
    } else {
        blitToOutput(single_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, output_);
    glViewport(outputViewport_.x, outputViewport_.y, outputViewport_.z, outputViewport_.w);
    return draws;
}

} // namespace swell::detail

namespace swell {

glm::ivec2 scaledFrameSize(glm::ivec2 outputSize, double renderScale)
{
    const glm::dvec2 scaled = glm::dvec2(outputSize) * renderScale;
    return glm::max(glm::ivec2(int(std::lround(scaled.x)), int(std::lround(scaled.y))), glm::ivec2(1));
}

} // namespace swell
