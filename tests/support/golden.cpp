#include "support/golden.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace swell::test {

std::string saveTestImage(const Image& image, const std::string& name)
{
    const std::filesystem::path path = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / (name + ".png");
    writePng(image, path);
    return path.string();
}

void expectMatchesGolden(const Image& actual, const std::string& name, int maxChannel, double maxMean)
{
    const std::filesystem::path golden = std::filesystem::path(SWELL_SOURCE_DIR) / "tests/goldens" / (name + ".png");
    const char* update = std::getenv("SWELL_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writePng(actual, golden);
        std::printf("updated golden %s\n", golden.c_str());
        return;
    }
    if (!std::filesystem::exists(golden)) {
        const std::string path = saveTestImage(actual, name + ".actual");
        ADD_FAILURE() << "no golden image " << golden << "; actual written to " << path
                      << " (look at it, then run scripts/update-goldens.sh)";
        return;
    }
    const ImageDifference d = compareImages(actual, readImage(golden));
    if (!d.sameSize || d.maxChannel > maxChannel || d.meanChannel > maxMean) {
        const std::string actualPath = saveTestImage(actual, name + ".actual");
        const std::string diffPath = d.sameSize ? saveTestImage(d.diff, name + ".diff") : std::string("(sizes differ)");
        ADD_FAILURE() << "image " << name << " differs from its golden: max channel difference " << d.maxChannel
                      << " (allowed " << maxChannel << "), mean " << d.meanChannel << " (allowed " << maxMean
                      << ")\n  actual: " << actualPath << "\n  diff:   " << diffPath << "\n  golden: " << golden;
    }
}

double srgbToLinear(std::uint8_t level)
{
    const double c = level / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgbLevel(double linear)
{
    const double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return std::clamp(v, 0.0, 1.0) * 255.0;
}

} // namespace swell::test
