// Golden-image comparison. Goldens live in tests/goldens/NAME.png. On a
// mismatch the actual and diff images are written under the build tree and
// their paths printed. scripts/update-goldens.sh (SWELL_UPDATE_GOLDENS=1)
// rewrites goldens deliberately; nothing else ever does.
#pragma once

#include "swell/image.h"

#include <cstdint>
#include <string>

namespace swell::test {

// Fails the current test when any channel differs by more than maxChannel
// (0..255) or the mean channel difference exceeds maxMean.
void expectMatchesGolden(const Image& actual, const std::string& name, int maxChannel, double maxMean);

// Writes an image for a person to look at: <build>/test-output/NAME.png. Returns the path.
std::string saveTestImage(const Image& image, const std::string& name);

// The sRGB transfer function (IEC 61966-2-1) the renderer's output applies:
// an 8-bit level to linear 0..1, and linear to a level 0..255 (unrounded).
double srgbToLinear(std::uint8_t level);
double srgbLevel(double linear);

} // namespace swell::test
