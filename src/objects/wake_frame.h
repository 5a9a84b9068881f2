// The wake as one frame draws it: per cell of the wake field's grid, the
// height, its slopes and the foam, blended between the two wake steps that
// bracket the frame's time. The renderer uploads exactly these numbers, and
// swell::DrawnSurface interpolates them with the same bilinear weights as
// shaders/wake.glsl, so the CPU's drawn surface is the GPU's.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace swell::detail {

// Bilinear interpolation between cell centres at grid coordinates g (cell
// (i, j)'s centre at g = (i, j)) of a cells x cells grid, with value(i, j)
// giving a cell's value and cells outside the grid flat (0): the weights
// shaders/wake.glsl uses.
template <typename Value>
double bilinearOverCells(glm::dvec2 g, int cells, const Value& value)
{
    const glm::dvec2 base = glm::floor(g);
    const glm::dvec2 f = g - base;
    const int i = int(base.x), j = int(base.y);
    auto at = [&](int x, int y) { return x < 0 || y < 0 || x >= cells || y >= cells ? 0.0 : double(value(x, y)); };
    return (1.0 - f.y) * ((1.0 - f.x) * at(i, j) + f.x * at(i + 1, j)) +
           f.y * ((1.0 - f.x) * at(i, j + 1) + f.x * at(i + 1, j + 1));
}

struct WakeFrame {
    int cells = 0;                  // per side
    double cellSize_m = 1.0;
    glm::ivec2 cornerCell{0};       // cell (0, 0) is centred at cornerCell * cellSize_m (world x, z)
    // Per cell, row-major (i + j * cells, i along x): height, m; its slopes
    // d/dx and d/dz (central differences); foam, 0..1.
    std::vector<glm::vec4> texels;
    // The largest |height| of its cells, m: how far it raises or lowers the
    // water (the grid's culling pads by it). Found where the frame is made,
    // on the bodies' worker when they step ahead (objects/scene_bodies.h).
    double reach_m = 0.0;

    // World x, z of cell (0, 0)'s centre, m.
    glm::dvec2 corner_m() const { return glm::dvec2(cornerCell) * cellSize_m; }
    // The height at a world point, m: bilinear between cell centres, as
    // shaders/wake.glsl weighs them; 0 outside the grid.
    double heightAt(glm::dvec2 world_m) const;
};

} // namespace swell::detail
