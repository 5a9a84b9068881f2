// `swell render --labels`: a frame's ground truth (swell/dataset/labels.h) written
// beside its colour image NAME.png, each file whole or not at all:
//   NAME.range.npy     float32 (H, W): metres along each pixel's ray; inf: sky
//   NAME.normal.npy    float32 (H, W, 3): unit world normal; 0: sky
//   NAME.semantic.npy  uint16 (H, W): class ids (NAME.json's "classes")
//   NAME.instance.npy  uint16 (H, W): 0, or an object's instance id
//   NAME.depth.npy     float32 (H, W): z-depth, metres along the optical axis; inf: sky
//   NAME.labels.png    the classes and instances in colour, for people
//   NAME.amodal.npy    uint8 (N, H, W): each object's amodal mask, in NAME.json's object order
//   NAME.kitti.txt     the objects as KITTI's 3D boxes (label_kitti.h)
//   NAME.kitti_calib.txt  the calibration that projects them (KITTI's calib file)
//   NAME.json          camera, horizon, objects and their boxes, sea state
// (docs/LABELS.md describes each field.)
#pragma once

#include "swell/dataset/labels.h"
#include "swell/image.h"
#include "swell/scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace swell::app {

using Json = nlohmann::ordered_json;

// A 4x4 matrix as JSON rows.
Json matrixJson(const glm::dmat4& m);

// A rig camera's colour image beside the frame's: NAME.png -> NAME.CAM.png
// (its labels then NAME.CAM.range.npy, ...); `colour` itself for "" (no rig).
std::filesystem::path rigCameraPath(const std::filesystem::path& colour, const std::string& camera);

// The files written for the colour image `colour`, in the order above.
std::vector<std::filesystem::path> labelFilePaths(const std::filesystem::path& colour);


// Writes them, the JSON last. `significantHeight_m`: the significant wave
// height drawn, m.
void writeLabelFiles(const FrameLabels& labels, const Scene& scene, double time_s, double significantHeight_m,
                     const std::filesystem::path& colour);
// The arrays and the preview alone, the world's normals and the KITTI
// files' world in `frame`'s axes (scene.labels.world_frame).
void writeLabelArrays(const FrameLabels& labels, const std::filesystem::path& colour,
                      LabelWorldFrame frame = LabelWorldFrame::Swell);
// The JSON's content (camera, horizon, classes, objects, sea; its world
// quantities in the axes of scene.labels.world_frame), and writing it.
Json frameJson(const FrameLabels& labels, const Scene& scene, double time_s, double significantHeight_m,
               const std::filesystem::path& colour);
void writeFrameJson(const Json& json, const std::filesystem::path& colour);

// A PNG written whole or not at all (a temporary file renamed).
void writePngAtomically(const Image& image, const std::filesystem::path& path);

// The .npy bytes (NumPy's format, version 1.0) of a row-major array.
std::string npyBytes(const void* data, std::size_t bytes, const std::string& descr, const std::vector<int>& shape);

} // namespace swell::app
