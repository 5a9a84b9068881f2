// Checks a screenshot of the viewer: the size asked for, and an ocean in it.
// Usage: swell_png_check FILE WIDTH HEIGHT. Exit 0 when it passes, 1 when
// not (saying why), 2 for bad arguments or an unreadable file.
//
// The panel covers the left of the window, so the ocean is judged on the
// right third: its top quarter must be mostly sky blue, its bottom quarter
// mostly dark, bluish water. A blank, black or unrendered frame fails both.
#include "sky_above_water.h"
#include "swell/error.h"
#include "swell/image.h"

#include <cstdio>
#include <cstdlib>
#include <string>


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
    const swell::test::SkyAboveWater seen = swell::test::skyAboveWater(image);
    std::printf("right third: top quarter %.0f%% sky, bottom quarter %.0f%% water\n", 100.0 * seen.sky,
                100.0 * seen.water);
    if (!seen.shown()) {
        std::printf("%s does not show sky above water\n", argv[1]);
        return 1;
    }
    return 0;
}
