#include "dataset_coco.h"

#include "swell/dataset/labels.h"
#include "swell/dataset/sweep.h"
#include "swell/error.h"
#include "swell/gpu/label_classes.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace swell::app {

namespace fs = std::filesystem;

std::string readFileBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(fmt::format("cannot read {}", path.string()));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

namespace {

// A uint16 (H, W) array from an .npy file this program wrote.
std::vector<std::uint16_t> readInstances(const fs::path& path, int width, int height)
{
    const std::string bytes = readFileBytes(path);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0)
        throw Error(fmt::format("{} is not an .npy file", path.string()));
    const std::size_t header = 10 + std::size_t(std::uint8_t(bytes[8])) + 256 * std::size_t(std::uint8_t(bytes[9]));
    if (bytes.size() != header + 2 * pixels)
        throw Error(fmt::format("{} does not hold {}x{} uint16 values", path.string(), width, height));
    std::vector<std::uint16_t> values(pixels);
    std::memcpy(values.data(), bytes.data() + header, 2 * pixels);
    return values;
}

// COCO's uncompressed RLE of one instance's mask: run lengths alternating
// from "not in it", over the pixels in column-major order.
Json runLengths(const std::vector<std::uint16_t>& instances, int width, int height, std::uint16_t instance)
{
    Json counts = Json::array();
    bool inside = false;
    long long run = 0;
    for (int x = 0; x < width; ++x)
        for (int y = 0; y < height; ++y) {
            const bool here = instances[std::size_t(y) * std::size_t(width) + std::size_t(x)] == instance;
            if (here != inside) {
                counts.push_back(run);
                run = 0;
                inside = here;
            }
            ++run;
        }
    counts.push_back(run);
    return {{"counts", counts}, {"size", {height, width}}};
}

// One frame's image and its objects' annotations, from its JSON and instance mask.
void addFrame(const fs::path& png, long long imageId, Json image, Json& images, Json& annotations, long long& nextId)
{
    const std::vector<fs::path> files = labelFilePaths(png);
    Json frame;
    try {
        frame = Json::parse(readFileBytes(files.back()));
    } catch (const Json::exception& e) {
        throw Error(fmt::format("{}: {}", files.back().string(), e.what()));
    }
    const int width = frame["size"][0], height = frame["size"][1];
    image["width"] = width;
    image["height"] = height;
    images.push_back(std::move(image));
    if (frame["objects"].empty())
        return;
    const std::vector<std::uint16_t> instances = readInstances(files[3], width, height);
    for (const Json& o : frame["objects"]) {
        if (o["visible_pixels"].get<long long>() == 0)
            continue;
        const int x0 = o["box_px"][0], y0 = o["box_px"][1], x1 = o["box_px"][2], y1 = o["box_px"][3];
        annotations.push_back({{"id", nextId++},
                               {"image_id", imageId},
                               {"category_id", o["class_id"]},
                               {"instance", o["instance"]},
                               {"bbox", {x0, y0, x1 - x0, y1 - y0}},
                               {"area", o["visible_pixels"]},
                               {"iscrowd", 0},
                               {"segmentation", runLengths(instances, width, height, o["instance"].get<std::uint16_t>())}});
    }
}

} // namespace

Json cocoJson(const fs::path& out, const Sweep& sweep, const std::vector<std::string>& classes)
{
    Json images = Json::array(), annotations = Json::array(), categories = Json::array();
    for (std::size_t c = SWELL_LABEL_FIRST_OBJECT_CLASS; c < classes.size(); ++c)
        categories.push_back({{"id", c}, {"name", classes[c]}, {"supercategory", "object"}});
    long long nextId = 1;
    const int frames = sweep.clip ? sweep.clip->frames : 1;
    for (int i = 0; i < sweep.count; ++i)
        for (int k = 0; k < frames; ++k) {
            const long long id = (long long)i * frames + k;
            const std::string name =
                sweep.clip ? fmt::format("samples/{:06d}_{:05d}.png", i, k) : fmt::format("samples/{:06d}.png", i);
            Json image = {{"id", id}, {"file_name", name}};
            if (sweep.clip) {
                image["sample"] = i;
                image["frame"] = k;
            }
            addFrame(out / name, id, std::move(image), images, annotations, nextId);
        }
    return {{"info", {{"description", "rendered by swell dataset"}}},
            {"images", images},
            {"annotations", annotations},
            {"categories", categories}};
}

} // namespace swell::app
