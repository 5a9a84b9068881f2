// A dataset's COCO file (docs/DATASETS.md): every sample's objects as
// instance annotations, from the samples' JSON and instance masks.
#pragma once

#include "label_files.h"

#include "swell/dataset/sweep.h"

#include "swell/scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace swell::app {

// COCO's object-detection format: images, annotations (bbox [x, y, width,
// height] in pixels, area = visible pixels, segmentation as uncompressed
// run-length counts in column-major order), categories (the objects'
// classes, with the ids of the samples' semantic masks). A clip's frames are
// an image each (id: the sample's index times the clip's frames plus the
// frame's), with its "sample" and "frame".
// `cameras`: the rig's camera names (an image per camera per frame, its
// "camera" named), or {""}.
Json cocoJson(const std::filesystem::path& out, const Sweep& sweep, const std::vector<std::string>& classes,
              const std::vector<std::string>& cameras);

// A file's whole content; throws swell::Error when it cannot be read.
std::string readFileBytes(const std::filesystem::path& path);

} // namespace swell::app
