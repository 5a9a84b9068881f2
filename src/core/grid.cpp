#include "swell/grid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

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
