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

// The values of an .npy file this program wrote, `count` of `itemBytes` each.
std::string npyValues(const fs::path& path, std::size_t count, std::size_t itemBytes, const char* what)
{
    const std::string bytes = readFileBytes(path);
    if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0)
        throw Error(fmt::format("{} is not an .npy file", path.string()));
    const std::size_t header = 10 + std::size_t(std::uint8_t(bytes[8])) + 256 * std::size_t(std::uint8_t(bytes[9]));
    if (bytes.size() != header + itemBytes * count)
        throw Error(fmt::format("{} does not hold {}", path.string(), what));
    return bytes.substr(header);
}

// A uint16 (H, W) array from an .npy file this program wrote.
std::vector<std::uint16_t> readInstances(const fs::path& path, int width, int height)
{
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::string values = npyValues(path, pixels, 2, fmt::format("{}x{} uint16 values", width, height).c_str());
    std::vector<std::uint16_t> instances(pixels);
    std::memcpy(instances.data(), values.data(), 2 * pixels);
    return instances;
}

// COCO's uncompressed RLE of a mask (inMask(i): whether pixel i, rows top
// first, is in it): run lengths alternating from "not in it", over the
// pixels in column-major order.
template <typename InMask>
Json runLengths(int width, int height, InMask inMask)
{
    Json counts = Json::array();
    bool inside = false;
    long long run = 0;
    for (int x = 0; x < width; ++x)
        for (int y = 0; y < height; ++y) {
            const bool here = inMask(std::size_t(y) * std::size_t(width) + std::size_t(x));
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
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    // Each object's amodal mask (label_files.h: .amodal.npy, (N, H, W), the JSON's order).
    const std::string amodal = npyValues(files[6], frame["objects"].size() * pixels, 1, "a mask per object of the JSON");
    for (std::size_t k = 0; k < frame["objects"].size(); ++k) {
        const Json& o = frame["objects"][k];
        if (o["visible_pixels"].get<long long>() == 0)
            continue;
        const std::uint16_t id = o["instance"].get<std::uint16_t>();
        const auto visible = [&](std::size_t p) { return instances[p] == id; };
        const auto hiddenOrNot = [&](std::size_t p) { return amodal[k * pixels + p] != 0; };
        const int x0 = o["box_px"][0], y0 = o["box_px"][1], x1 = o["box_px"][2], y1 = o["box_px"][3];
        annotations.push_back({{"id", nextId++},
                               {"image_id", imageId},
                               {"category_id", o["class_id"]},
                               {"instance", o["instance"]},
                               {"bbox", {x0, y0, x1 - x0, y1 - y0}},
                               {"area", o["visible_pixels"]},
                               {"iscrowd", 0},
                               {"segmentation", runLengths(width, height, visible)},
                               {"amodal_segmentation", runLengths(width, height, hiddenOrNot)},
                               {"amodal_area", o["amodal_pixels"]},
                               {"occlusion", o["occlusion"]},
                               {"truncation", o["truncation"]}});
    }
}

} // namespace

Json cocoJson(const fs::path& out, const Sweep& sweep, const std::vector<std::string>& classes,
              const std::vector<std::string>& cameras)
{
    Json images = Json::array(), annotations = Json::array(), categories = Json::array();
    for (std::size_t c = SWELL_LABEL_FIRST_OBJECT_CLASS; c < classes.size(); ++c)
        categories.push_back({{"id", c}, {"name", classes[c]}, {"supercategory", "object"}});
    long long nextId = 1;
    const int frames = sweep.clip ? sweep.clip->frames : 1;
    const long long views = (long long)cameras.size();
    for (int i = 0; i < sweep.count; ++i)
        for (int k = 0; k < frames; ++k)
            for (std::size_t c = 0; c < cameras.size(); ++c) {
                const long long id = ((long long)i * frames + k) * views + (long long)c;
                const std::string frame =
                    sweep.clip ? fmt::format("samples/{:06d}_{:05d}.png", i, k) : fmt::format("samples/{:06d}.png", i);
                const std::string name = rigCameraPath(frame, cameras[c]).string();
                Json image = {{"id", id}, {"file_name", name}};
                if (sweep.clip) {
                    image["sample"] = i;
                    image["frame"] = k;
                }
                if (!cameras[c].empty())
                    image["camera"] = cameras[c];
                addFrame(out / name, id, std::move(image), images, annotations, nextId);
            }
    return {{"info", {{"description", "rendered by swell dataset"}}},
            {"images", images},
            {"annotations", annotations},
            {"categories", categories}};
}

} // namespace swell::app
