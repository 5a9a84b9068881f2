// Checks a screenshot of the viewer: the size asked for, and an ocean in it.
// Usage: swell_png_check FILE WIDTH HEIGHT. Exit 0 when it passes, 1 when
// not (saying why), 2 for bad arguments or an unreadable file.
//
// The panel covers the left of the window, so the ocean is judged on the
// right third: its top quarter must be mostly sky blue, its bottom quarter
// mostly dark, bluish water. A blank, black or unrendered frame fails both.
#include "swell/error.h"
#include "swell/image.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// The share of pixels in the rectangle that pass `test`.
template <class Test>
double share(const swell::Image& image, int x0, int y0, int x1, int y1, Test test)
{
    long passed = 0, total = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++total) {
            const std::uint8_t* p = image.pixel(x, y);
            passed += test(int(p[0]), int(p[1]), int(p[2])) ? 1 : 0;
        }
    return total ? double(passed) / double(total) : 0.0;
}

// Sky: bright and clearly blue (the default sky runs from about
// (150, 180, 225) at the top to (200, 215, 235) at the horizon).
bool sky(int r, int g, int b) { return b > 140 && b > r + 15 && b >= g; }

// Water: darker than any sky and bluish (the default sea is about
// (30..120, 60..150, 80..170) away from the glitter).
bool water(int r, int g, int b) { return r + g + b < 3 * 150 && b > r && b + g > 2 * r; }

} // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: swell_png_check FILE WIDTH HEIGHT\n");
        return 2;
    }
    swell::Image image;
    try {
        image = swell::readImage(argv[1]);
    } catch (const swell::Error& e) {
        std::fprintf(stderr, "swell_png_check: %s\n", e.what());
        return 2;
    }
    const int width = std::atoi(argv[2]), height = std::atoi(argv[3]);
    if (image.width != width || image.height != height) {
        std::printf("%s is %dx%d, expected %dx%d\n", argv[1], image.width, image.height, width, height);
        return 1;
    }
    const int x0 = width * 2 / 3;
    const double skyShare = share(image, x0, 0, width, height / 4, sky);
    const double waterShare = share(image, x0, height * 3 / 4, width, height, water);
    std::printf("right third: top quarter %.0f%% sky, bottom quarter %.0f%% water\n", 100.0 * skyShare,
                100.0 * waterShare);
    // Most, not all: a floating object or the glitter may cover some of it.
    const double kMostly = 0.6;
    if (skyShare < kMostly || waterShare < kMostly) {
        std::printf("%s does not show sky above water\n", argv[1]);
        return 1;
    }
    return 0;
}
