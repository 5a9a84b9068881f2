#include "swell/image.h"

#include "assets/grey_image.h"
#include "core/input_file.h"
#include "swell/error.h"

#include <fmt/format.h>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace swell {

void writePng(const Image& image, const std::filesystem::path& path)
{
    if (image.width <= 0 || image.height <= 0)
        throw Error("swell::writePng(): cannot write an empty image to " + path.string());
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        throw Error(fmt::format("swell::writePng(): {}x{} pixels need {} bytes of RGBA, the image holds {}", image.width,
                                image.height, std::size_t(image.width) * std::size_t(image.height) * 4,
                                image.rgba.size()));
    if (path.has_parent_path()) {
        std::error_code error;
        std::filesystem::create_directories(path.parent_path(), error);
        if (error)
            throw Error(fmt::format("swell::writePng(): cannot write {}: cannot create its folder {}: {}", path.string(),
                                    path.parent_path().string(), error.message()));
    }
    errno = 0;
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
        throw Error(fmt::format("swell::writePng(): cannot write {}{}", path.string(),
                                errno ? ": " + std::string(std::strerror(errno)) : std::string()));
}

namespace {

// An image file's bytes, read within the limits of swell/image.h, its
// header checked before anything is decoded: a small file may declare a
// huge picture, and decoding allocates for what it declares.
struct CheckedImageFile {
    std::string bytes;
    int width = 0, height = 0, channels = 0;

    const stbi_uc* data() const { return reinterpret_cast<const stbi_uc*>(bytes.data()); }
    int size() const { return int(bytes.size()); }
};

CheckedImageFile readCheckedImageFile(const std::filesystem::path& path)
{
    CheckedImageFile file{detail::readInputFile(path, kMaxImageFileBytes, "image")};
    if (file.bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        throw InputError({path.string()}, "the image is too large to decode");
    if (!stbi_info_from_memory(file.data(), file.size(), &file.width, &file.height, &file.channels))
        throw InputError({path.string()}, std::string("cannot read image: ") + stbi_failure_reason());
    if (file.width > kMaxImageSide || file.height > kMaxImageSide)
        throw InputError({path.string()}, fmt::format("the image is {}x{} pixels; images are at most {}x{}", file.width,
                                                      file.height, kMaxImageSide, kMaxImageSide));
    return file;
}

} // namespace

Image readImage(const std::filesystem::path& path)
{
    const CheckedImageFile file = readCheckedImageFile(path);
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(file.data(), file.size(), &w, &h, &channels, 4);
    if (!pixels)
        throw InputError({path.string()}, std::string("cannot read image: ") + stbi_failure_reason());
    Image image{w, h, std::vector<std::uint8_t>(pixels, pixels + size_t(w) * size_t(h) * 4)};
    stbi_image_free(pixels);
    return image;
}

namespace detail {

GreyImage readGreyImage(const std::filesystem::path& path)
{
    const CheckedImageFile file = readCheckedImageFile(path);
    if (file.channels > 2)
        throw InputError({path.string()}, fmt::format("the image has colour ({} channels); a heightmap is a grey "
                                                      "image, 8 or 16 bits a pixel",
                                                      file.channels));
    int w = 0, h = 0, channels = 0;
    GreyImage image;
    if (stbi_is_16_bit_from_memory(file.data(), file.size())) {
        stbi_us* pixels = stbi_load_16_from_memory(file.data(), file.size(), &w, &h, &channels, 1);
        if (!pixels)
            throw InputError({path.string()}, std::string("cannot read image: ") + stbi_failure_reason());
        image = {w, h, std::vector<std::uint16_t>(pixels, pixels + size_t(w) * size_t(h))};
        stbi_image_free(pixels);
        return image;
    }
    stbi_uc* pixels = stbi_load_from_memory(file.data(), file.size(), &w, &h, &channels, 1);
    if (!pixels)
        throw InputError({path.string()}, std::string("cannot read image: ") + stbi_failure_reason());
    image = {w, h, std::vector<std::uint16_t>(size_t(w) * size_t(h))};
    for (std::size_t i = 0; i < image.values.size(); ++i)
        image.values[i] = std::uint16_t(pixels[i] * 257u); // 255 -> 65535: white stays white
    stbi_image_free(pixels);
    return image;
}

} // namespace detail

ImageDifference compareImages(const Image& a, const Image& b)
{
    ImageDifference d;
    if (a.width != b.width || a.height != b.height) {
        d.sameSize = false;
        d.maxChannel = 255;
        d.meanChannel = 255.0;
        return d;
    }
    d.diff = Image{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size(), 255)};
    double sum = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            const int delta = std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
            d.maxChannel = std::max(d.maxChannel, delta);
            sum += delta;
            d.diff.rgba[i + c] = std::uint8_t(std::min(255, delta * 4));
        }
    d.meanChannel = a.rgba.empty() ? 0.0 : sum / double(a.rgba.size() / 4 * 3);
    return d;
}

} // namespace swell
