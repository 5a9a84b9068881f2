// Reading the window back and naming screenshot files.
#include "viewer/screenshot.h"

#include "swell/error.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace swell::app::viewer {

Image readDefaultFramebuffer(glm::ivec2 size)
{
    Image image;
    if (size.x <= 0 || size.y <= 0)
        return image;
    image.width = size.x;
    image.height = size.y;
    const std::size_t row = std::size_t(size.x) * 4;
    std::vector<std::uint8_t> bottomUp(row * std::size_t(size.y));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    image.rgba.resize(bottomUp.size());
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&bottomUp[std::size_t(size.y - 1 - y) * row], row, &image.rgba[std::size_t(y) * row]);
    // The window's alpha channel holds whatever the passes left there.
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        image.rgba[i] = 255;
    return image;
}

std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder)
{
    for (int n = 1; n < 1000000; ++n) {
        std::filesystem::path candidate = folder / fmt::format("swell-screenshot-{:04d}.png", n);
        std::error_code ec;
        if (!std::filesystem::exists(candidate, ec) && !ec)
            return candidate;
    }
    throw Error(fmt::format("{}: no free screenshot name left", folder.string()));
}

} // namespace swell::app::viewer
