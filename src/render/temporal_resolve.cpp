#include "render/temporal_resolve.h"

#include "gl/uniform_location.h"

#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/temporal.h"

#include <glm/matrix.hpp>

namespace swell::detail {

double radicalInverse(std::uint32_t i, std::uint32_t base)
{
    double inverse = 1.0 / double(base), scale = inverse, value = 0.0;
    for (; i > 0; i /= base, scale *= inverse)
        value += double(i % base) * scale;
    return value;
}

glm::dvec2 temporalJitter_px(std::uint64_t frame)
{
    const auto index = std::uint32_t(frame % SWELL_TEMPORAL_JITTER_PHASES) + 1;
    return glm::dvec2(radicalInverse(index, 2), radicalInverse(index, 3)) - 0.5;
}

glm::dmat4 jitteredProjection(const glm::dmat4& projection, glm::dvec2 jitter_px, glm::ivec2 size)
{
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * jitter_px.x / double(size.x);
    shift[3][1] = 2.0 * jitter_px.y / double(size.y);
    return shift * projection;
}

namespace {

GLint uniform(const gl::Program& program, const char* name, const char* file = "temporal_resolve.frag")
{
    return gl::requiredUniform(program, name, file);
}

} // namespace

TemporalResolveProgram::TemporalResolveProgram(gl::Program built)
    : program(std::move(built)), reprojection(uniform(program, "reprojection")), jitter(uniform(program, "jitter_px")),
      depthToNdc(uniform(program, "depthToNdc")), historyValid(uniform(program, "historyValid")),
      waterMaxWeight(uniform(program, "waterMaxWeight"))
{
}

TemporalPrograms::TemporalPrograms(gl::Program neighbourhood, gl::Program resolveHalfOrLess,
                                   gl::Program resolveAboveHalf, gl::Program present)
    : neighbourhood_(std::move(neighbourhood)), halfOrLess_(std::move(resolveHalfOrLess)),
      aboveHalf_(std::move(resolveAboveHalf)), present_(std::move(present)),
      presentOrigin_(uniform(present_, "presentOrigin", "temporal_present.frag"))
{
}

namespace {

// Whether a blit of the resolve's 8-bit copy fills `output` as the
// full-screen pass would: one colour buffer, single-sampled (a blit into a
// multisampled buffer needs the same format on both sides), of 8-bit
// normalized channels (a float buffer would lose the history's precision).
// Asked each frame: a host may attach other buffers to the same framebuffer.
bool outputTakesTheBlit(GLuint output)
{
    GLint sampleBuffers = 0;
    glGetNamedFramebufferParameteriv(output, GL_SAMPLE_BUFFERS, &sampleBuffers);
    if (sampleBuffers != 0)
        return false;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, output);
    GLint first = GL_NONE, second = GL_NONE;
    glGetIntegerv(GL_DRAW_BUFFER0, &first);
    glGetIntegerv(GL_DRAW_BUFFER1, &second);
    if (first == GL_NONE || second != GL_NONE)
        return false;
    // A default framebuffer's buffers are named by their left halves.
    const GLenum attachment = first == GL_BACK ? GL_BACK_LEFT : first == GL_FRONT ? GL_FRONT_LEFT : GLenum(first);
    GLint red = 0, green = 0, blue = 0, type = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(output, attachment, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &red);
    glGetNamedFramebufferAttachmentParameteriv(output, attachment, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, &green);
    glGetNamedFramebufferAttachmentParameteriv(output, attachment, GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE, &blue);
    glGetNamedFramebufferAttachmentParameteriv(output, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    return red == 8 && green == 8 && blue == 8 && type == GL_UNSIGNED_NORMALIZED;
}

} // namespace

void TemporalResolve::resize(glm::ivec2 size)
{
    if (size == size_)
        return;
    size_ = size;
    previous_.reset();
    for (Target& t : history_) {
        t.framebuffer.reset();
        t.texture = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        // Half floats: a blend that moves a pixel by a tenth of the difference
        // each frame would stall on 8 bits short of what it converges to.
        glTextureStorage2D(t.texture.id(), 1, GL_RGBA16F, size.x, size.y);
        glTextureParameteri(t.texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(t.texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t.texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    display_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(display_.id(), 1, GL_RGBA8, size.x, size.y);
    displayFramebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(displayFramebuffer_.id(), GL_COLOR_ATTACHMENT0, display_.id(), 0);
    if (glCheckNamedFramebufferStatus(displayFramebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("the temporal resolve's display: framebuffer incomplete");
    for (Target& t : history_) {
        t.framebuffer = gl::Framebuffer::create();
        glNamedFramebufferTexture(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, t.texture.id(), 0);
        glNamedFramebufferTexture(t.framebuffer.id(), GL_COLOR_ATTACHMENT1, display_.id(), 0);
        const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(t.framebuffer.id(), 2, outputs);
        if (glCheckNamedFramebufferStatus(t.framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("the temporal resolve's history: framebuffer incomplete");
    }
}

void TemporalResolve::resizeBoxes(glm::ivec2 drawnSize)
{
    if (drawnSize == drawnSize_)
        return;
    drawnSize_ = drawnSize;
    boxes_.reset();
    // Full floats: the box and the depth the reprojection unprojects are
    // read as the resolve computed them before they were gathered here.
    for (gl::Texture* t : {&boxCentre_, &boxExtent_}) {
        *t = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(t->id(), 1, GL_RGBA32F, drawnSize.x, drawnSize.y);
        glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    boxes_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(boxes_.id(), GL_COLOR_ATTACHMENT0, boxCentre_.id(), 0);
    glNamedFramebufferTexture(boxes_.id(), GL_COLOR_ATTACHMENT1, boxExtent_.id(), 0);
    const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(boxes_.id(), 2, outputs);
    if (glCheckNamedFramebufferStatus(boxes_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("the temporal resolve's clip boxes: framebuffer incomplete");
}

int TemporalResolve::resolve(const TemporalPrograms& programs, GLuint emptyVao, GLuint frameColor, GLuint frameDepth,
                             glm::ivec2 drawnSize, glm::ivec4 outputViewport, GLuint output,
                             const glm::dmat4& viewProj, glm::dvec2 depthToNdc, double time_s)
{
    const glm::ivec2 outputSize(outputViewport.z, outputViewport.w);
    const glm::ivec2 corner(outputViewport.x, outputViewport.y);
    resize(outputSize);
    resizeBoxes(drawnSize);
    const glm::dvec2 jitter = jitterEnabled_ ? jitter_px() : glm::dvec2(0.0);
    // This frame's clip space to the last one's, in double: both matrices
    // carry the eye's absolute position, which single precision would lose.
    const glm::dmat4 reprojection = previous_ ? *previous_ * glm::inverse(viewProj) : glm::dmat4(1.0);
    const Target& read = history_[current_];
    const Target& write = history_[1 - current_];
    const TemporalResolveProgram& program =
        2 * drawnSize.x <= outputSize.x && 2 * drawnSize.y <= outputSize.y ? programs.halfOrLess_ : programs.aboveHalf_;
    const GLuint resolve = program.program.id();
    const glm::mat4 reprojectionF(reprojection);
    glProgramUniformMatrix4fv(resolve, program.reprojection, 1, GL_FALSE, &reprojectionF[0][0]);
    glProgramUniform2f(resolve, program.jitter, float(jitter.x), float(jitter.y));
    glProgramUniform2f(resolve, program.depthToNdc, float(depthToNdc.x), float(depthToNdc.y));
    glProgramUniform1f(resolve, program.historyValid, previous_ ? 1.0f : 0.0f);
    const bool wavesMoved = previous_ && time_s != previousTime_s_;
    glProgramUniform1f(resolve, program.waterMaxWeight,
                       float(wavesMoved ? SWELL_TEMPORAL_WATER_MAX_WEIGHT : SWELL_TEMPORAL_MAX_WEIGHT));

    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindVertexArray(emptyVao);
    glBindTextureUnit(SWELL_UNIT_POST_SOURCE, frameColor);
    // Each drawn pixel's clip box, at the drawn size.
    glViewport(0, 0, drawnSize.x, drawnSize.y);
    glBindFramebuffer(GL_FRAMEBUFFER, boxes_.id());
    glUseProgram(programs.neighbourhood_.id());
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_DEPTH, frameDepth);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_DEPTH, 0);
    // The history resolved at the output's size.
    glViewport(0, 0, outputSize.x, outputSize.y);
    glBindFramebuffer(GL_FRAMEBUFFER, write.framebuffer.id());
    glUseProgram(resolve);
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_BOX_CENTRE, boxCentre_.id());
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_BOX_EXTENT, boxExtent_.id());
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_HISTORY, read.texture.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_BOX_CENTRE, 0);
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_BOX_EXTENT, 0);
    // The result into the output, opaque: where it suits, a blit of the
    // 8-bit copy the resolve wrote beside the history, which on llvmpipe
    // costs next to nothing where a full-screen pass reading the history
    // costs one pass over every output pixel (docs/design/performance-log.md).
    int drawCalls = 2;
    if (outputTakesTheBlit(output)) {
        glBlitNamedFramebuffer(displayFramebuffer_.id(), output, 0, 0, outputSize.x, outputSize.y, corner.x, corner.y,
                               corner.x + outputSize.x, corner.y + outputSize.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, output);
        glViewport(corner.x, corner.y, outputSize.x, outputSize.y);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, output);
        glViewport(corner.x, corner.y, outputSize.x, outputSize.y);
        glProgramUniform2i(programs.present_.id(), programs.presentOrigin_, corner.x, corner.y);
        glUseProgram(programs.present_.id());
        glBindTextureUnit(SWELL_UNIT_TEMPORAL_HISTORY, write.texture.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++drawCalls;
    }
    glBindTextureUnit(SWELL_UNIT_TEMPORAL_HISTORY, 0);
    glEnable(GL_DEPTH_TEST);
    current_ = 1 - current_;
    previous_ = viewProj;
    previousTime_s_ = time_s;
    ++frame_;
    return drawCalls;
}

} // namespace swell::detail
