#include "swell/grid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

GridShape gridShapeFor(const GridSettings& grid, const CameraSettings& camera)
{
    GridShape shape;
    shape.cells = std::max(4, (grid.resolution - 1) & ~1);
    shape.radius_m = grid.radius_m;
    shape.skirt_m = std::max(camera.far_m * 0.9, grid.radius_m * 2.0);
    return shape;
}

HorizonFade horizonFadeFor(const GridSettings& grid, const GridShape& shape)
{
    const double end = std::min(grid.fadeEnd_m, shape.radius_m);
    // GLSL's smoothstep is undefined when its edges meet: keep start below end.
    return {std::min(grid.fadeStart_m, end * 0.999), end};
}

namespace {
double smoothstep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
} // namespace

double horizonFadeAt(const HorizonFade& fade, double distance_m)
{
    return 1.0 - smoothstep(fade.start_m, fade.end_m, distance_m);
}

double waveLodWeight(double wavelength_m, double cellSize_m)
{
    return smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * cellSize_m, SWELL_FULL_CELLS_PER_WAVELENGTH * cellSize_m,
                      wavelength_m);
}

double gridLineOffset(const GridShape& shape, int i)
{
    const double half = 0.5 * shape.cells;
    const double u = (i - half) / half;
    return shape.radius_m * u * std::abs(u);
}

double finestGridStep(const GridShape& shape)
{
    const double u = 2.0 / shape.cells;
    return shape.radius_m * u * u;
}

GridPlacement placeGrid(const GridShape& shape, glm::dvec2 camera_m)
{
    GridPlacement p;
    p.finestStep_m = finestGridStep(shape);
    p.center_m = glm::floor(camera_m / p.finestStep_m + 0.5) * p.finestStep_m;
    for (int level = 0; level < SWELL_GRID_LEVELS; ++level) {
        const double step = p.finestStep_m * std::ldexp(1.0, level);
        p.snapOffsets[size_t(level)] = p.center_m - glm::floor(p.center_m / step) * step;
    }
    return p;
}

double snappedGridLine(const GridShape& shape, const GridPlacement& placement, int i, int axis, double& spacing_m)
{
    const double s = gridLineOffset(shape, i);
    if (i == 0 || i == shape.cells) {
        spacing_m = shape.skirt_m;
        return s < 0.0 ? -shape.skirt_m : shape.skirt_m;
    }
    spacing_m = std::min(gridLineOffset(shape, i + 1) - s, s - gridLineOffset(shape, i - 1));
    const double step0 = placement.finestStep_m;
    const int level = std::clamp(int(std::floor(std::log2(std::max(spacing_m, step0) / step0))), 0, SWELL_GRID_LEVELS - 1);
    const double step = step0 * std::ldexp(1.0, level);
    const double offset = placement.snapOffsets[size_t(level)][axis];
    return step * std::floor((offset + s) / step + 0.5) - offset;
}

} // namespace swell
