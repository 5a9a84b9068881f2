// 8-bit RGBA images: what the renderer reads back, PNG files, and the
// comparison the golden-image tests use.
#pragma once

#include "swell/export.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace swell {

struct SWELL_API Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba; // row 0 is the top row

    std::uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    const std::uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

// Largest image readImage decodes, pixels per side. Decoding allocates 4
// bytes per pixel (64 MiB at this size) plus stb_image's working copies, and a
// tiny compressed file may declare any size; larger images are refused from
// their header, before decoding. 4096 is the largest sky face in common use.
inline constexpr int kMaxImageSide = 4096;
// Largest image file readImage reads, bytes; a 4096x4096 PNG that does not
// compress is 64 MiB.
inline constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t(64) << 20;

// Writes a PNG. Throws swell::Error when the file cannot be written.
SWELL_API void writePng(const Image& image, const std::filesystem::path& path);
// Reads a PNG (or any format stb_image knows) as RGBA. Throws swell::InputError
// naming the file when it is not a regular file, is larger than
// kMaxImageFileBytes, declares more than kMaxImageSide pixels a side, or
// cannot be decoded.
SWELL_API Image readImage(const std::filesystem::path& path);

struct SWELL_API ImageDifference {
    int maxChannel = 0;          // largest absolute difference of any channel, 0..255
    double meanChannel = 0.0;    // mean absolute difference over all RGB channels, 0..255
    bool sameSize = true;
    Image diff;                  // |a - b| per channel, amplified 4x for visibility, alpha 255
};
SWELL_API ImageDifference compareImages(const Image& a, const Image& b);

} // namespace swell
