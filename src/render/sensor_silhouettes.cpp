#include "render/sensor_silhouettes.h"

#include <glm/geometric.hpp>

namespace swell::detail {

namespace {

// Whether image `c` shows the ray through normalised place u (x right, y
// down): inside the lens's fold, and landing inside the image.
bool shows(const LensDistortion& lens, const CameraCalibration& c, glm::dvec2 u)
{
    if (!insideFold(lens, u))
        return false;
    const glm::dvec2 d = distort(lens, u);
    const double x = c.fx_px * d.x + c.cx_px, y = c.fy_px * d.y + c.cy_px;
    return x >= 0.0 && y >= 0.0 && x < c.size.x && y < c.size.y;
}

} // namespace

void distortSilhouettes(const FrameLabels& wide, const LensDistortion& lens, const CameraCalibration& c,
                        double pinholeFocal_px, const std::vector<std::size_t>& from, FrameLabels& out)
{
    const std::size_t widePixels = std::size_t(wide.size.x) * std::size_t(wide.size.y);
    const std::size_t pixels = from.size();
    out.amodal.assign(out.objects.size() * pixels, 0);
    for (std::size_t k = 0; k < out.objects.size() && (k + 1) * widePixels <= wide.amodal.size(); ++k) {
        const std::uint8_t* mask = wide.amodal.data() + k * widePixels;
        for (std::size_t i = 0; i < pixels; ++i)
            out.amodal[k * pixels + i] = mask[from[i]];
        long long shown = 0;
        for (int y = 0; y < wide.size.y; ++y)
            for (int x = 0; x < wide.size.x; ++x)
                if (mask[std::size_t(y) * std::size_t(wide.size.x) + std::size_t(x)] != 0) {
                    const glm::dvec2 u = (glm::dvec2(x + 0.5, y + 0.5) - 0.5 * glm::dvec2(wide.size)) / pinholeFocal_px;
                    shown += shows(lens, c, u);
                }
        ObjectLabel& o = out.objects[k];
        o.truncation = o.silhouettePixels > 0 ? 1.0 - double(shown) / double(o.silhouettePixels) : 1.0;
    }
}

} // namespace swell::detail
