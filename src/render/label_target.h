// The label pass's target (swell/dataset/labels.h): range and normal in 32-bit
// floats, class and instance in 16-bit unsigned integers, and depth; one
// sample per pixel, so no label is ever a blend of two.
#pragma once

#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace swell::detail {

class LabelTarget {
public:
    // Recreates the textures when the size changes.
    void resize(glm::ivec2 size);
    GLuint framebuffer() const { return framebuffer_.id(); }
    // Clears to: range +infinity, normal 0, class and instance 0, depth `depth`.
    void clear(float depth) const;
    // Reads the target back, rows top first.
    void read(std::vector<float>& range_m, std::vector<glm::vec3>& normal, std::vector<std::uint16_t>& semantic,
              std::vector<std::uint16_t>& instance) const;
    // Reads the instance image alone, rows top first.
    void readInstance(std::vector<std::uint16_t>& instance) const;

private:
    // Class and instance interleaved, rows top first.
    std::vector<std::uint16_t> readClassInstance() const;

    glm::ivec2 size_{0, 0};
    gl::Framebuffer framebuffer_;
    gl::Texture rangeNormal_, classInstance_, depth_;
};

} // namespace swell::detail
