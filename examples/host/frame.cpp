#include "frame.h"

#include "boxes.h"
#include "gl_functions.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <stdexcept>

namespace host {

Target::Target(glm::ivec2 size, GLenum colorFormat) : size_(size)
{
    glCreateTextures(GL_TEXTURE_2D, 1, &color_);
    glTextureStorage2D(color_, 1, colorFormat, size.x, size.y);
    glTextureParameteri(color_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(color_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
    glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, color_, 0);
    glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("host::Target: the framebuffer is incomplete");
}

Target::~Target()
{
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &depth_);
    glDeleteTextures(1, &color_);
}

std::vector<std::uint8_t> Target::pixels() const
{
    std::vector<std::uint8_t> rgba(std::size_t(size_.x) * std::size_t(size_.y) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color_, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return rgba;
}

glm::dmat4 reversedInfiniteProjection(double fovY_deg, double aspect, double near_m)
{
    const double f = 1.0 / std::tan(glm::radians(fovY_deg) * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0;
    p[3][2] = near_m;
    return p;
}

void beginFrame(const Target& target, const float clear[4], bool reversedZ)
{
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.size().x, target.size().y);
    glClipControl(GL_LOWER_LEFT, reversedZ ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversedZ ? GL_GREATER : GL_LESS);
    glDepthMask(GL_TRUE);
    const float farDepth = reversedZ ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, clear);
    glClearNamedFramebufferfv(target.framebuffer(), GL_DEPTH, 0, &farDepth);
}

namespace {

// One triangle that covers the screen, from the vertex index alone.
const char* kVertex = R"(#version 450 core
out vec2 vUv;
void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* kFragment = R"(#version 450 core
in vec2 vUv;
layout(binding = 0) uniform sampler2D hdr;
uniform float exposure;
out vec4 fragColor;
// Narkowicz 2015, "ACES Filmic Tone Mapping Curve".
vec3 aces(vec3 x) { return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
vec3 srgb(vec3 c) { return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c)); }
void main()
{
    vec3 linear = texture(hdr, vUv).rgb * exposure;
    fragColor = vec4(srgb(aces(max(linear, 0.0))), 1.0);
}
)";

} // namespace

ToneMapper::ToneMapper()
{
    program_ = buildProgram(kVertex, kFragment, "tone_map");
    exposure_ = glGetUniformLocation(program_, "exposure");
    glCreateVertexArrays(1, &vertexArray_);
}

ToneMapper::~ToneMapper()
{
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteProgram(program_);
}

void ToneMapper::apply(GLuint hdr, GLuint framebuffer, glm::ivec2 size, float exposure) const
{
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program_);
    glUniform1f(exposure_, exposure);
    glBindTextureUnit(0, hdr);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace host
