// `swell render --labels`: a frame's forward optical flow (swell/dataset/flow.h)
// written beside its colour image NAME.png, each file whole or not at all:
//   NAME.flow.npy        float32 (H, W, 2): where each pixel's point is seen
//                        in the next frame, less the pixel's centre, pixels
//   NAME.flow_valid.npy  uint8 (H, W): 1 where it is seen there
// (docs/LABELS.md, "Optical flow").
#pragma once

#include "label_files.h"
#include "swell/dataset/flow.h"

#include <filesystem>
#include <vector>

namespace swell::app {

// The files written for the colour image `colour`, in the order above.
std::vector<std::filesystem::path> flowFilePaths(const std::filesystem::path& colour);

void writeFlowFiles(const FrameFlow& flow, const std::filesystem::path& colour);

// The frame JSON's "flow" entry for a frame drawn at time_s whose flow goes
// to the frame flow.interval_s later: {"interval_s", "next_time_s"}.
Json flowJson(const FrameFlow& flow, double time_s);

} // namespace swell::app
