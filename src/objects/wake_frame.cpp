// The wake as a frame draws it (wake_frame.h).
#include "objects/wake_frame.h"


namespace swell::detail {

double WakeFrame::heightAt(glm::dvec2 world_m) const
{
    if (cells <= 0)
        return 0.0;
    // As wakeHeight() in shaders/wake.glsl.
    return bilinearOverCells((world_m - corner_m()) / cellSize_m, cells,
                             [&](int i, int j) { return texels[std::size_t(i) + std::size_t(j) * cells].x; });
}

} // namespace swell::detail
