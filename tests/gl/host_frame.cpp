#include "host_frame.h"

#include "swell/gl/shader.h"

#include <array>

namespace swell::test {

HostTarget::HostTarget(glm::ivec2 size, GLenum colorFormat, GLenum depthFormat)
    : size_(size), color_(gl::Texture::create(GLenum(GL_TEXTURE_2D))), framebuffer_(gl::Framebuffer::create())
{
    glTextureStorage2D(color_.id(), 1, colorFormat, size.x, size.y);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    if (depthFormat != GL_NONE) {
        depth_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(depth_.id(), 1, depthFormat, size.x, size.y);
        glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    }
}

std::vector<std::uint8_t> HostTarget::pixels() const
{
    std::vector<std::uint8_t> rgba(std::size_t(size_.x) * std::size_t(size_.y) * 4);
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return rgba;
}

std::vector<float> HostTarget::depths() const
{
    std::vector<float> depth(std::size_t(size_.x) * std::size_t(size_.y));
    glFinish();
    glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
    return depth;
}

std::vector<float> HostTarget::floatPixels() const
{
    std::vector<float> rgba(std::size_t(size_.x) * std::size_t(size_.y) * 4);
    glFinish();
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    return rgba;
}

namespace {

const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color;
uniform mat4 viewProj;
uniform vec4 clip;
out vec3 vColor;
out float gl_ClipDistance[1];
void main()
{
    gl_ClipDistance[0] = dot(clip, vec4(position, 1.0));
    gl_Position = viewProj * vec4(position, 1.0);
    vColor = color;
}
)";

const char* kFragment = R"(#version 450 core
in vec3 vColor;
out vec4 fragColor;
void main() { fragColor = vec4(vColor, 1.0); }
)";

GLuint compile(GLenum stage, const char* source)
{
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    return shader;
}

} // namespace

HostScene::HostScene(std::vector<HostBox> boxes)
{
    // The host's own program, compiled with plain GL calls (not Swell's helpers).
    program_ = gl::Program::create();
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertex), fs = compile(GL_FRAGMENT_SHADER, kFragment);
    glAttachShader(program_.id(), vs);
    glAttachShader(program_.id(), fs);
    glLinkProgram(program_.id());
    glDeleteShader(vs);
    glDeleteShader(fs);
    viewProj_ = glGetUniformLocation(program_.id(), "viewProj");
    clip_ = glGetUniformLocation(program_.id(), "clip");
    std::vector<float> data;
    for (const HostBox& b : boxes) {
        const glm::dvec3 lo = b.min_m, hi = b.max_m;
        auto corner = [&](int i) { return glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
        // Two triangles per face, corners by bit (x 1, y 2, z 4).
        const std::array<std::array<int, 4>, 6> faces = {{{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                                          {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}}};
        for (const auto& f : faces)
            for (int k : {0, 1, 2, 0, 2, 3}) {
                const glm::dvec3 p = corner(f[std::size_t(k)]);
                data.insert(data.end(), {float(p.x), float(p.y), float(p.z), b.color.r, b.color.g, b.color.b});
            }
    }
    vertexCount_ = int(data.size() / 6);
    vertices_ = gl::Buffer::create();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(data.size() * sizeof(float)), data.data(), 0);
    vao_ = gl::VertexArray::create();
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, 6 * sizeof(float));
    for (GLuint a : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }
}

void HostScene::draw(const glm::dmat4& viewProj, glm::dvec4 clip) const
{
    glUseProgram(program_.id());
    const glm::mat4 m(viewProj);
    glUniformMatrix4fv(viewProj_, 1, GL_FALSE, &m[0][0]);
    const glm::vec4 c(clip);
    glUniform4fv(clip_, 1, &c[0]);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
    // What a host might leave behind: its program and vertex array bound.
}

void HostScene::drawPass(const PassView& pass)
{
    passes.push_back(pass.pass);
    draw(pass.projection * pass.view, pass.clipPlane_m);
    if (afterPass)
        afterPass(pass);
}

void drawHostFrame(const HostTarget& target, const HostScene& scene, const View& view, glm::vec4 clear)
{
    const bool reversed = view.depth == DepthMode::Reversed;
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.size().x, target.size().y);
    glClipControl(GL_LOWER_LEFT, view.depth == DepthMode::Standard ? GL_NEGATIVE_ONE_TO_ONE : GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glDepthMask(GL_TRUE);
    glClearColor(clear.r, clear.g, clear.b, clear.a);
    glClearDepth(reversed ? 0.0 : 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene.draw(view.projection * view.view);
}

} // namespace swell::test
