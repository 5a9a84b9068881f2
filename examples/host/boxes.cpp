#include "boxes.h"

#include "gl_functions.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace host {

namespace {

// World positions are absolute; the example's world spans a few hundred
// metres around the origin, where float keeps millimetres.
const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 viewProj;
uniform mat4 model;
uniform mat3 normalMatrix;
uniform vec4 clip;
out vec3 vNormal;
out float gl_ClipDistance[1];
void main()
{
    vec4 world = model * vec4(position, 1.0);
    gl_ClipDistance[0] = dot(clip, world);
    gl_Position = viewProj * world;
    vNormal = normalMatrix * normal;
}
)";

// Lambert from the sun plus a hemisphere ambient; linear radiance out (the
// host's target is linear; Swell's passes expect linear colour).
const char* kFragment = R"(#version 450 core
in vec3 vNormal;
uniform vec3 color;
uniform vec3 towardsSun;
uniform vec3 sun;
uniform vec3 sky;
uniform vec3 ground;
out vec4 fragColor;
void main()
{
    vec3 n = normalize(vNormal);
    vec3 ambient = mix(ground, sky, 0.5 + 0.5 * n.y);
    fragColor = vec4(color * (ambient + sun * max(dot(n, towardsSun), 0.0)), 1.0);
}
)";

GLuint compile(GLenum stage, const char* source, const char* name)
{
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log(4096, '\0');
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string(name) + (stage == GL_VERTEX_SHADER ? ".vert" : ".frag") +
                                 ": does not compile:\n" + log.c_str());
    }
    return shader;
}

} // namespace

GLuint buildProgram(const char* vertexSource, const char* fragmentSource, const char* name)
{
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexSource, name);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentSource, name);
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log(4096, '\0');
        glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        glDeleteProgram(program);
        throw std::runtime_error(std::string(name) + ": does not link:\n" + log.c_str());
    }
    return program;
}

Box boxBetween(glm::dvec3 min_m, glm::dvec3 max_m, glm::vec3 color, const glm::dmat4& frame)
{
    const glm::dmat4 placed = glm::scale(glm::translate(glm::dmat4(1.0), 0.5 * (min_m + max_m)), max_m - min_m);
    return {frame * placed, color};
}

BoxRenderer::BoxRenderer()
{
    program_ = buildProgram(kVertex, kFragment, "boxes");
    for (auto [location, name] : {std::pair{&viewProj_, "viewProj"}, {&model_, "model"},
                                  {&normalMatrix_, "normalMatrix"}, {&color_, "color"}, {&clip_, "clip"},
                                  {&towardsSun_, "towardsSun"}, {&sun_, "sun"}, {&sky_, "sky"}, {&ground_, "ground"}})
        *location = glGetUniformLocation(program_, name);

    // The unit cube: six faces of two counter-clockwise triangles seen from
    // outside, each vertex with its face's normal.
    std::vector<float> data;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-0.5f, 0.5f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side * 2.0f;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (side < 0.0f)
                std::swap(u, v);
            const glm::vec3 c = n * 0.5f;
            const std::array<glm::vec3, 4> q{c - 0.5f * u - 0.5f * v, c + 0.5f * u - 0.5f * v,
                                             c + 0.5f * u + 0.5f * v, c - 0.5f * u + 0.5f * v};
            for (int k : {0, 1, 2, 0, 2, 3})
                data.insert(data.end(), {q[std::size_t(k)].x, q[std::size_t(k)].y, q[std::size_t(k)].z, n.x, n.y, n.z});
        }
    glCreateBuffers(1, &vertices_);
    glNamedBufferStorage(vertices_, GLsizeiptr(data.size() * sizeof(float)), data.data(), 0);
    glCreateVertexArrays(1, &vertexArray_);
    glVertexArrayVertexBuffer(vertexArray_, 0, vertices_, 0, 6 * sizeof(float));
    for (GLuint a : {0u, 1u}) {
        glEnableVertexArrayAttrib(vertexArray_, a);
        glVertexArrayAttribFormat(vertexArray_, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
        glVertexArrayAttribBinding(vertexArray_, a, 0);
    }
}

BoxRenderer::~BoxRenderer()
{
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &vertices_);
    glDeleteProgram(program_);
}

void BoxRenderer::draw(const glm::dmat4& viewProj, glm::dvec4 clip_m) const
{
    glUseProgram(program_);
    const glm::mat4 vp(viewProj);
    glUniformMatrix4fv(viewProj_, 1, GL_FALSE, &vp[0][0]);
    const glm::vec4 clip(clip_m);
    glUniform4fv(clip_, 1, &clip[0]);
    glUniform3fv(towardsSun_, 1, &light.towardsSun[0]);
    glUniform3fv(sun_, 1, &light.sun[0]);
    glUniform3fv(sky_, 1, &light.sky[0]);
    glUniform3fv(ground_, 1, &light.ground[0]);
    glBindVertexArray(vertexArray_);
    for (const Box& box : boxes) {
        const glm::mat4 model(box.model);
        const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(box.model))));
        glUniformMatrix4fv(model_, 1, GL_FALSE, &model[0][0]);
        glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, &normalMatrix[0][0]);
        glUniform3fv(color_, 1, &box.color[0]);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }
}

void BoxRenderer::drawPass(const swell::PassView& pass)
{
    // Swell has bound its pass's framebuffer and set its viewport, depth
    // test and clip distance; the host only draws.
    draw(pass.projection * pass.view, pass.clipPlane_m);
}

} // namespace host
