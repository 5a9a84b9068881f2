// Grey images at their own depth (8 or 16 bits a pixel): heightmaps
// (swell/scene/seabed.h). Read by the same loader as every other image
// (assets/image.cpp, swell/image.h), with its limits.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace swell::detail {

struct GreyImage {
    int width = 0, height = 0;
    // Row 0 is the top row. 8-bit images are widened to 16 bits (x 257), so
    // 0 is black and 65535 white whatever the file's depth.
    std::vector<std::uint16_t> values;
};

// Reads a grey PNG (or any grey format stb_image knows; an alpha channel is
// ignored). Throws swell::InputError naming the file when readImage would
// refuse it (swell/image.h: not a regular file, too large, more than
// kMaxImageSide pixels a side, not an image) or when it has colour channels.
GreyImage readGreyImage(const std::filesystem::path& path);

} // namespace swell::detail
