// The example host's own geometry and shader: boxes, each a unit cube placed
// by a model matrix, flat-shaded in linear colour by the sun and a
// sky/ground ambient (GLSL of its own, not Swell's). The same boxes are
// drawn into the host's frame and, as swell::PassGeometry, into Swell's
// reflection and refraction passes with the pass's matrices and clip plane.
#pragma once

#include <swell/view.h>

#include <GL/glcorearb.h>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace host {

// A box: the unit cube [-0.5, 0.5]^3 through `model` (to absolute world, m).
struct Box {
    glm::dmat4 model{1.0};
    glm::vec3 color{1.0f}; // linear albedo
};

// An axis-aligned box from its corners (absolute world, m) in `frame`.
Box boxBetween(glm::dvec3 min_m, glm::dvec3 max_m, glm::vec3 color, const glm::dmat4& frame = glm::dmat4(1.0));

// How the boxes are lit, linear RGB.
struct Light {
    glm::vec3 towardsSun{0.0f, 1.0f, 0.0f}; // unit
    glm::vec3 sun{1.0f};                     // radiance scale of the sun on a facing surface
    glm::vec3 sky{0.3f};                     // ambient from above
    glm::vec3 ground{0.1f};                  // ambient from below
};

class BoxRenderer final : public swell::PassGeometry {
public:
    // Compiles the host's program and builds the cube; needs the host's GL
    // functions loaded. Throws std::runtime_error with the info log when
    // the GLSL does not build.
    BoxRenderer();
    ~BoxRenderer() override;
    BoxRenderer(const BoxRenderer&) = delete;
    BoxRenderer& operator=(const BoxRenderer&) = delete;

    std::vector<Box> boxes;
    Light light;

    // The boxes through viewProj (absolute world to clip), keeping
    // dot(clip, (p, 1)) >= 0 where GL_CLIP_DISTANCE0 is on.
    void draw(const glm::dmat4& viewProj, glm::dvec4 clip_m = {0.0, 0.0, 0.0, 1.0}) const;
    // Swell's reflection and refraction passes: the same boxes, the pass's view.
    void drawPass(const swell::PassView& pass) override;

private:
    GLuint program_ = 0, vertexArray_ = 0, vertices_ = 0;
    GLint viewProj_ = -1, model_ = -1, normalMatrix_ = -1, color_ = -1, clip_ = -1;
    GLint towardsSun_ = -1, sun_ = -1, sky_ = -1, ground_ = -1;
};

// Builds a program from a vertex and a fragment shader; throws
// std::runtime_error with the whole info log when either fails.
GLuint buildProgram(const char* vertexSource, const char* fragmentSource, const char* name);

} // namespace host
