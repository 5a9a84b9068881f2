#include "swell/scene/grid.h"
#include "swell/gpu/limits.h"

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
// The grid tracks the camera's height: every eightfold of height doubles the
// inner scale (the near cells), while the grid keeps its reach, so the far
// rings move little. A lower camera sees the far water at a shallower angle,
// where fixed cells shrink to specks on screen; its smaller inner scale spends
// more rings near it (out of view below it) and spaces the far rings wider,
// and the fragment shader's oceanShading() adds the waves the grid does not
// carry, so the view keeps its detail. Scale 1 serves cameras near
// kDesignHeight_m; the scales go from kMinScale to GridShape::maxScale.
constexpr double kInnerScale_m = 3.0;
constexpr double kDesignHeight_m = 6.0;
constexpr double kHeightRatioPerScale = 8.0;
constexpr double kMinScale = 1.0 / 4.0;
// The morph from scale s to 2s runs over the heights kDesignHeight_m *
// 8^(log2(s) + kMorphStart .. + kMorphEnd): 13.2 .. 47 m from scale 1 to 2,
// 1.65 .. 5.9 m from 1/2 to 1. Slow, so that a camera rising 1 cm a frame
// moves no vertex of the drawn surface by a centimetre (7 mm at most in
// test_grid_morph): the slide to the next scale's places takes over 400
// frames. Between the
// bands the grid is of one scale alone, every vertex on its lattice: from
// 5.9 to 13.2 m at scale 1 (so 6 m and 13 m), 47 to 105 m at scale 2.
constexpr double kMorphStart = 0.38;
constexpr double kMorphEnd = 0.99;
// The largest scale keeps its growth at least 2/3 of scale 1's: its finest
// lattice step (scale times scale 1's, half scale 1's innermost spacing) then
// stays within 3/4 of its innermost spacing, so neighbours never round onto
// one lattice point.
constexpr double kMinGrowthShare = 2.0 / 3.0;

// Geometric layout, ring r (1 .. n/2 - 1): its Chebyshev radius, and the
// spacing across rings (radial) and along the ring (tangential), m.
struct Ring {
    double radius_m, radial_m, tangential_m;
};
Ring ringAt(const GridShape& shape, const GridRings& rings, int ring)
{
    const double half = 0.5 * shape.cells;
    const double u = ring / half;
    const double radius = rings.innerScale_m * std::expm1(rings.growth * u);
    const double radial = rings.innerScale_m * rings.growth * std::exp(rings.growth * u) / half;
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

} // namespace

GridShape gridShapeFor(const GridSettings& grid, const CameraSettings& camera)
{
    GridShape shape;
    shape.layout = grid.layout;
    shape.cells = std::max(4, (grid.resolution - 1) & ~1);
    shape.radius_m = grid.radius_m;
    shape.skirt_m = std::max(camera.far_m * 0.9, grid.radius_m * 2.0);
    shape.innerScale_m = std::min(kInnerScale_m, 0.25 * grid.radius_m);
    if (shape.layout == GridLayout::Geometric) {
        auto growth = [&](double scale) { return std::log1p(shape.radius_m / (scale * shape.innerScale_m)); };
        while (growth(2.0 * shape.maxScale) >= kMinGrowthShare * growth(1.0) && shape.maxScale < 1024.0)
            shape.maxScale *= 2.0;
    }
    return shape;
}

GridRings gridRings(const GridShape& shape, double scale)
{
    GridRings out;
    out.innerScale_m = scale * shape.innerScale_m;
    out.growth = std::log1p(shape.radius_m / out.innerScale_m);
    // Vertices snap to a lattice of at most half their spacing at scale 1
    // (the finest step is half the innermost spacing there), and of less
    // than their spacing at every scale, so a rounded vertex never crosses
    // its neighbour's place.
    const double finestStep = scale * finestGridStep(shape);
    const int rings = shape.cells / 2;
    out.levelFirstRing.fill(rings);
    out.levelFirstRing[0] = 0;
    for (int r = rings - 1; r >= 1; --r) {
        const Ring ring = ringAt(shape, out, r);
        const int level = latticeLevel(std::min(ring.radial_m, ring.tangential_m), 2.0, finestStep);
        for (int l = 1; l <= level; ++l)
            out.levelFirstRing[size_t(l)] = r;
    }
    return out;
}

HorizonFade horizonFadeFor(const GridSettings& grid, const GridShape& shape)
{
    const double end = std::min(grid.fadeEnd_m, shape.radius_m);
    // GLSL's smoothstep is undefined when its edges meet: keep start below end.
    return {std::min(grid.fadeStart_m, end * 0.999), end};
}

double horizonFadeAt(const HorizonFade& fade, double distance_m)
{
    return 1.0 - glm::smoothstep(fade.start_m, fade.end_m, distance_m);
}

double gridLineOffset(const GridShape& shape, int i)
{
    const double half = 0.5 * shape.cells;
    const double u = (i - half) / half;
    if (shape.layout == GridLayout::Paper)
        return shape.radius_m * u * std::abs(u);
    const GridRings rings = gridRings(shape, 1.0);
    return std::copysign(rings.innerScale_m * std::expm1(rings.growth * std::abs(u)), u);
}

double finestGridStep(const GridShape& shape)
{
    if (shape.layout == GridLayout::Paper)
        return gridLineOffset(shape, shape.cells / 2 + 1);
    // Scale 1's innermost radial spacing, halved (not gridRings(): it needs this).
    const double growth = std::log1p(shape.radius_m / shape.innerScale_m);
    return 0.5 * shape.innerScale_m * growth / (0.5 * shape.cells);
}

GridScale gridScaleFor(const GridShape& shape, double cameraHeight_m)
{
    if (shape.layout == GridLayout::Paper || !(cameraHeight_m > 0.0))
        return {1.0, 0.0};
    // Heights in scale steps: scale 2^n serves t in (n - 1 + kMorphEnd, n + kMorphEnd].
    const double t = std::log(cameraHeight_m / kDesignHeight_m) / std::log(kHeightRatioPerScale);
    const double n = std::ceil(t - kMorphEnd);
    GridScale out;
    out.scale = std::clamp(std::exp2(n), kMinScale, shape.maxScale);
    if (out.scale >= shape.maxScale)
        return out;
    // Linear in height, so a camera rising at a steady speed morphs at one.
    const double n0 = std::log2(out.scale);
    const double start_m = kDesignHeight_m * std::pow(kHeightRatioPerScale, n0 + kMorphStart);
    const double end_m = kDesignHeight_m * std::pow(kHeightRatioPerScale, n0 + kMorphEnd);
    out.morph = std::clamp((cameraHeight_m - start_m) / (end_m - start_m), 0.0, 1.0);
    return out;
}

namespace {

// The grid's centre for a camera at a scale: the camera's x,z snapped to
// that scale's finest step; and the centre modulo each level's step.
glm::dvec2 snappedCenter(glm::dvec2 camera_m, double finestStep_m, std::array<glm::dvec2, SWELL_GRID_LEVELS>& snapOffsets)
{
    const glm::dvec2 center = glm::floor(camera_m / finestStep_m + 0.5) * finestStep_m;
    for (int level = 0; level < SWELL_GRID_LEVELS; ++level) {
        const double step = finestStep_m * std::ldexp(1.0, level);
        snapOffsets[size_t(level)] = center - glm::floor(center / step) * step;
    }
    return center;
}

} // namespace

GridPlacement placeGrid(const GridShape& shape, glm::dvec3 camera_m)
{
    GridPlacement p;
    const GridScale scale = gridScaleFor(shape, std::abs(camera_m.y));
    p.scale = scale.scale;
    p.morph = scale.morph;
    p.finestStep_m = p.scale * finestGridStep(shape);
    const glm::dvec2 camera(camera_m.x, camera_m.z);
    p.center_m = snappedCenter(camera, p.finestStep_m, p.snapOffsets);
    // The coarser scale exactly as placeGrid() will place it once the camera
    // has risen into it, so the morph ends where that grid begins.
    p.coarseCenterShift_m = snappedCenter(camera, 2.0 * p.finestStep_m, p.coarseSnapOffsets) - p.center_m;
    if (shape.layout == GridLayout::Geometric) {
        p.rings = gridRings(shape, p.scale);
        p.coarseRings = gridRings(shape, 2.0 * p.scale);
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

// The geometric layout's vertex d (from the centre) of ring `ring`, at this
// placement's scale or (coarse) at the next coarser one, snapped.
GridPoint geometricPoint(const GridShape& shape, const GridPlacement& placement, glm::ivec2 d, int ring, bool coarse)
{
    GridPoint p;
    const GridRings& rings = coarse ? placement.coarseRings : placement.rings;
    const Ring r = ringAt(shape, rings, ring);
    int level = 0;
    while (level + 1 < SWELL_GRID_LEVELS && ring >= rings.levelFirstRing[size_t(level + 1)])
        ++level;
    // The coarser scale's level l is this scale's level l + 1 lattice.
    const double step = placement.finestStep_m * std::ldexp(1.0, coarse ? level + 1 : level);
    const glm::dvec2 nominal = glm::dvec2(d) * r.tangential_m;
    const glm::dvec2 offset = coarse ? placement.coarseSnapOffsets[size_t(level)] : placement.snapOffsets[size_t(level)];
    p.offset_m = {snapToLattice(nominal.x, step, offset.x, p.snapMargin), snapToLattice(nominal.y, step, offset.y, p.snapMargin)};
    p.nominal_m = nominal;
    if (coarse) {
        p.offset_m += placement.coarseCenterShift_m;
        p.nominal_m += placement.coarseCenterShift_m;
    }
    p.latticeStep_m = glm::dvec2(step);
    p.cellSize_m = std::max(r.radial_m, r.tangential_m);
    return p;
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
        p.nominal_m = {gridLineOffset(shape, i), gridLineOffset(shape, j)};
        if (i == 0 || i == shape.cells)
            p.nominal_m.x = p.offset_m.x;
        if (j == 0 || j == shape.cells)
            p.nominal_m.y = p.offset_m.y;
        p.cellSize_m = std::max(spacing.x, spacing.y);
        p.skirt = ring == half;
        return p;
    }
    if (ring == half) {
        // The skirt: the outermost ring, far beyond the fog.
        p.skirt = true;
        p.cellSize_m = shape.skirt_m;
        p.offset_m = glm::dvec2(d) * (shape.skirt_m / half);
        p.nominal_m = p.offset_m;
        return p;
    }
    p = geometricPoint(shape, placement, d, ring, false);
    if (placement.morph > 0.0) {
        // Geomorphing: slide toward the coarser scale's vertex, taking its
        // cell size (and so its wave filter) along.
        const GridPoint coarse = geometricPoint(shape, placement, d, ring, true);
        p.offset_m = glm::mix(p.offset_m, coarse.offset_m, placement.morph);
        p.nominal_m = glm::mix(p.nominal_m, coarse.nominal_m, placement.morph);
        p.cellSize_m = glm::mix(p.cellSize_m, coarse.cellSize_m, placement.morph);
        p.latticeStep_m = coarse.latticeStep_m;
        p.snapMargin = std::min(p.snapMargin, coarse.snapMargin);
    }
    return p;
}

} // namespace swell
