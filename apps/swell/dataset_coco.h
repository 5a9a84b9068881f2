// A dataset's COCO file (docs/DATASETS.md): every sample's objects as
// instance annotations, from the samples' JSON and instance masks.
#pragma once

#include "label_files.h"

#include "swell/scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace swell::app {

// COCO's object-detection format: images, annotations (bbox [x, y, width,
// height] in pixels, area = visible pixels, segmentation as uncompressed
// run-length counts in column-major order), categories (the objects'
// classes, with the ids of the samples' semantic masks).
Json cocoJson(const std::filesystem::path& out, int count, const std::vector<std::string>& classes);

// A file's whole content; throws swell::Error when it cannot be read.
std::string readFileBytes(const std::filesystem::path& path);

} // namespace swell::app
