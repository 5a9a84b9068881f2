#include "swell/grid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

namespace {

// Geometric layout. Within about innerScale of the centre the spacing is
// nearly even: a camera looks down on that water, so cells should be the same
// size there. Beyond it, spacing grows in proportion to distance, which keeps
// a grazing view's triangles from shrinking to specks towards the horizon.
// Rings are squares, not the paper's straight lines, so no cell is a sliver.
// The grid tracks the camera's height: scale 1 serves cameras up to
// kDesignHeight_m * sqrt(2), and each doubling of height doubles the grid.
constexpr double kInnerScale_m = 3.0;
constexpr double kDesignHeight_m = 6.0;

// Geometric layout, ring r (1 .. n/2 - 1) at scale 1: its Chebyshev radius,
// and the spacing across rings (radial) and along the ring (tangential), m.
struct Ring {
    double radius_m, radial_m, tangential_m;
};
Ring ringAt(const GridShape& shape, int ring)
{
    const double half = 0.5 * shape.cells;
    const double u = ring / half;
    const double radius = shape.innerScale_m * std::expm1(shape.growth * u);
    const double radial = shape.innerScale_m * shape.growth * std::exp(shape.growth * u) / half;
    return {radius, radial, ring == 0 ? radial : radius / ring};
}

// The lattice level of a spacing: the largest power-of-two multiple of the
// finest step not above spacing / divisor.
int latticeLevel(double spacing_m, double divisor, double finestStep_m)
{
    const double ratio = std::max(spacing_m / divisor, finestStep_m) / finestStep_m;
    return std::clamp(int(std::floor(std::log2(ratio))), 0, SWELL_GRID_LEVELS - 1);
}

// Rounds a position (relative to the grid centre) to its level's world-fixed
// lattice; margin receives how far from a tie the rounding was, in steps.
double snapToLattice(double s, double step, double offset, double& margin)
{
    const double t = (offset + s) / step + 0.5;
    margin = std::min(margin, std::min(t - std::floor(t), std::ceil(t) - t));
    return step * std::floor(t) - offset;
}

double smoothstep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

} // namespace

GridShape gridShapeFor(const GridSettings& grid, const CameraSettings& camera)
{
    GridShape shape;
    shape.layout = grid.layout;
    shape.cells = std::max(4, (grid.resolution - 1) & ~1);
    shape.radius_m = grid.radius_m;
    shape.skirt_m = std::max(camera.far_m * 0.9, grid.radius_m * 2.0);
    shape.innerScale_m = std::min(kInnerScale_m, 0.25 * grid.radius_m);
    shape.growth = std::log1p(shape.radius_m / shape.innerScale_m);
    if (shape.layout == GridLayout::Geometric) {
        while (shape.maxScale * 2.0 * shape.radius_m <= 0.5 * shape.skirt_m && shape.maxScale < 1024.0)
            shape.maxScale *= 2.0;
        // Vertices snap to a lattice of at most half their spacing, so a
        // rounded vertex never crosses its neighbour's place.
        const double step0 = finestGridStep(shape);
        const int rings = shape.cells / 2;
        shape.levelFirstRing.fill(rings);
        shape.levelFirstRing[0] = 0;
        for (int r = rings - 1; r >= 1; --r) {
            const Ring ring = ringAt(shape, r);
            const int level = latticeLevel(std::min(ring.radial_m, ring.tangential_m), 2.0, step0);
            for (int l = 1; l <= level; ++l)
                shape.levelFirstRing[size_t(l)] = r;
        }
    }
    return shape;
}

HorizonFade horizonFadeFor(const GridSettings& grid, const GridShape& shape)
{
    const double end = std::min(grid.fadeEnd_m, shape.radius_m);
    // GLSL's smoothstep is undefined when its edges meet: keep start below end.
    return {std::min(grid.fadeStart_m, end * 0.999), end};
}

double horizonFadeAt(const HorizonFade& fade, double distance_m)
{
    return 1.0 - smoothstep(fade.start_m, fade.end_m, distance_m);
}

double gridLineOffset(const GridShape& shape, int i)
{
    const double half = 0.5 * shape.cells;
    const double u = (i - half) / half;
    if (shape.layout == GridLayout::Paper)
        return shape.radius_m * u * std::abs(u);
    return std::copysign(shape.innerScale_m * std::expm1(shape.growth * std::abs(u)), u);
}

double finestGridStep(const GridShape& shape)
{
    if (shape.layout == GridLayout::Paper)
        return gridLineOffset(shape, shape.cells / 2 + 1);
    return 0.5 * ringAt(shape, 0).radial_m;
}

double gridScaleFor(const GridShape& shape, double cameraHeight_m)
{
    if (shape.layout == GridLayout::Paper || !(cameraHeight_m > kDesignHeight_m))
        return 1.0;
    const double octaves = std::round(std::log2(cameraHeight_m / kDesignHeight_m));
    return std::min(std::exp2(octaves), shape.maxScale);
}

GridPlacement placeGrid(const GridShape& shape, glm::dvec3 camera_m)
{
    GridPlacement p;
    p.scale = gridScaleFor(shape, std::abs(camera_m.y));
    p.finestStep_m = p.scale * finestGridStep(shape);
    const glm::dvec2 camera(camera_m.x, camera_m.z);
    p.center_m = glm::floor(camera / p.finestStep_m + 0.5) * p.finestStep_m;
    for (int level = 0; level < SWELL_GRID_LEVELS; ++level) {
        const double step = p.finestStep_m * std::ldexp(1.0, level);
        p.snapOffsets[size_t(level)] = p.center_m - glm::floor(p.center_m / step) * step;
    }
    return p;
}

namespace {

// The paper's layout: line i along axis, snapped; the line's spacing and step.
double paperLine(const GridShape& shape, const GridPlacement& placement, int i, int axis, double& spacing_m,
                 double& step_m, double& margin)
{
    const double s = gridLineOffset(shape, i);
    spacing_m = std::min(gridLineOffset(shape, i + 1) - s, s - gridLineOffset(shape, i - 1));
    const int level = latticeLevel(spacing_m, 1.0, placement.finestStep_m);
    step_m = placement.finestStep_m * std::ldexp(1.0, level);
    return snapToLattice(s, step_m, placement.snapOffsets[size_t(level)][axis], margin);
}

} // namespace

GridPoint gridPoint(const GridShape& shape, const GridPlacement& placement, int i, int j)
{
    GridPoint p;
    const int half = shape.cells / 2;
    const glm::ivec2 d(i - half, j - half);
    const int ring = std::max(std::abs(d.x), std::abs(d.y));
    if (shape.layout == GridLayout::Paper) {
        // Each axis on its own line; lines 0 and n are the skirt, far beyond the fog.
        auto axis = [&](int line, int a, double& spacing, double& step) {
            if (line == 0 || line == shape.cells) {
                spacing = shape.skirt_m;
                return line == 0 ? -shape.skirt_m : shape.skirt_m;
            }
            return paperLine(shape, placement, line, a, spacing, step, p.snapMargin);
        };
        glm::dvec2 spacing;
        p.offset_m = {axis(i, 0, spacing.x, p.latticeStep_m.x), axis(j, 1, spacing.y, p.latticeStep_m.y)};
        p.cellSize_m = std::max(spacing.x, spacing.y);
        p.skirt = ring == half;
        return p;
    }
    if (ring == half) {
        // The skirt: the outermost ring, far beyond the fog.
        p.skirt = true;
        p.cellSize_m = shape.skirt_m;
        p.offset_m = glm::dvec2(d) * (shape.skirt_m / half);
        return p;
    }
    const Ring r = ringAt(shape, ring);
    int level = 0;
    while (level + 1 < SWELL_GRID_LEVELS && ring >= shape.levelFirstRing[size_t(level + 1)])
        ++level;
    const double step = placement.finestStep_m * std::ldexp(1.0, level);
    const glm::dvec2 nominal = glm::dvec2(d) * (placement.scale * r.tangential_m);
    const glm::dvec2 offset = placement.snapOffsets[size_t(level)];
    p.offset_m = {snapToLattice(nominal.x, step, offset.x, p.snapMargin), snapToLattice(nominal.y, step, offset.y, p.snapMargin)};
    p.latticeStep_m = glm::dvec2(step);
    p.cellSize_m = placement.scale * std::max(r.radial_m, r.tangential_m);
    return p;
}

} // namespace swell
