// Does a frame of the default scene show sky above water? The check shared
// by the viewer test (on its screenshot) and the window life test (on the
// restored window's frame).
#pragma once

#include "swell/image.h"

#include <cstdint>

namespace swell::test {

// Sky: bright and clearly blue (the default sky runs from about
// (150, 180, 225) at the top to (200, 215, 235) at the horizon).
inline bool skyColour(int r, int g, int b) { return b > 140 && b > r + 15 && b >= g; }

// Water: darker than any sky and bluish (the default sea is about
// (30..120, 60..150, 80..170) away from the glitter).
inline bool waterColour(int r, int g, int b) { return r + g + b < 3 * 150 && b > r && b + g > 2 * r; }

// The share of pixels in the rectangle that pass `test`.
template <class Test>
double share(const Image& image, int x0, int y0, int x1, int y1, Test test)
{
    long passed = 0, total = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++total) {
            const std::uint8_t* p = image.pixel(x, y);
            passed += test(int(p[0]), int(p[1]), int(p[2])) ? 1 : 0;
        }
    return total ? double(passed) / double(total) : 0.0;
}

// On the right third of the frame (the default scene's island is on the
// left): the share of the top quarter that is sky and of the bottom quarter
// that is water. Most, not all (kMostly): a floating object or the glitter
// may cover some of it.
struct SkyAboveWater {
    double sky = 0.0, water = 0.0;
    static constexpr double kMostly = 0.6;
    bool shown() const { return sky >= kMostly && water >= kMostly; }
};
inline SkyAboveWater skyAboveWater(const Image& image)
{
    const int x0 = image.width * 2 / 3;
    return {share(image, x0, 0, image.width, image.height / 4, skyColour),
            share(image, x0, image.height * 3 / 4, image.width, image.height, waterColour)};
}

} // namespace swell::test
