// The wake on the GPU: each frame's swell::detail::WakeFrame uploaded as an
// RGBA32F texture (height, slopes, foam per cell) on SWELL_UNIT_WAKE, and
// the Wake uniform block (shaders/wake.glsl) saying where its cells lie
// relative to the render origin.
#pragma once

#include "objects/wake_frame.h"
#include "render/gpu/blocks.h"
#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell::detail {


class WakeTexture {
public:
    // Uploads `frame` (null: no wake): once per simulated time. Needs a
    // current GL context.
    void upload(const WakeFrame* frame);
    // Says where the uploaded frame's cells lie for a view drawn about
    // `origin` (absolute, m): once per view.
    void place(glm::dvec3 origin);
    // Binds the texture and the uniform block for the water programs.
    void bind() const;

private:
    gl::Texture texture_;
    gl::Buffer uniforms_;
    int cells_ = 0; // the texture's size, per side
    // The uploaded frame's placement (absent: no wake).
    bool hasWake_ = false;
    glm::dvec2 corner_m_{0.0};
    double cellSize_m_ = 1.0;
};

} // namespace swell::detail
