// A dataset's folder (docs/DATASETS.md, "The output folder"): checked
// before anything is made in it, its manifest, and which samples in it are
// done: a sample is done when every file it has is there whole and says
// what the manifest's sweep draws for it, not merely when its JSON exists.
#pragma once

#include "label_files.h"

#include "swell/dataset/sweep.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swell::app {

// samples/NNNNNN.png, and beside it its label files (label_files.h).
std::filesystem::path samplePng(const std::filesystem::path& out, int index);
// The frames of each of the sweep's samples: its clip's, or 1 (a still).
int framesOf(const Sweep& sweep);
// Frame `frame` of sample `index`: a still's samplePng(); frame F of a
// clip's samples/NNNNNN_FFFFF.png.
std::filesystem::path framePng(const std::filesystem::path& out, int index, const Sweep& sweep, int frame);
// Every file of one frame, the JSON last: the PNG, the label files and, for
// a clip's frame, its flow (flow_files.h); the PNG and the JSON alone when
// the sweep writes no labels.
// With a rig, camera names the rig camera whose files they are
// (NNNNNN.CAM.png, ...: rigCameraPath()).
std::vector<std::filesystem::path> frameFiles(const std::filesystem::path& out, int index, const Sweep& sweep,
                                              int frame, const std::string& camera = "");

// The manifest's content for this sweep and base scene.
Json manifestJson(const Sweep& sweep, const Scene& base);

// Refuses (InputError at --out) a folder that cannot become this sweep's
// dataset, making nothing: an empty path; a path through a file; a file
// where the folder, samples/ or manifest.json should be; a manifest that
// is not one or records another sweep; a folder that cannot be written.
void checkOutputFolder(const std::filesystem::path& out, const Sweep& sweep);

// Makes the folder and samples/, and writes the manifest when it is not
// there yet. checkOutputFolder() first.
void prepareOutputFolder(const std::filesystem::path& out, const Sweep& sweep, const Scene& base);

// Why sample `index` is not done ("" when it is): a file of one of its
// frames missing, cut short or not parsing, or a JSON that is another
// sample's (its index, frame, size, time or varied values not those
// `sample` has); each camera's files, for a rig (frameCameras of its scene).
std::string sampleNotDone(const std::filesystem::path& out, int index, const Sweep& sweep, const SweepSample& sample);

// Removes what a run that stopped left of sample `index`: its frames'
// files, the JSONs first (so that it never looks done), and its temporary
// files.
// `cameras`: frameCameras() of the sweep's scene.
void removeSample(const std::filesystem::path& out, int index, const Sweep& sweep,
                  const std::vector<std::string>& cameras);

// Removes the temporary files of the manifest and COCO file whose writer
// (the process named in their names, swell/dataset/atomic_file.h) is gone.
void removeOrphanedTemporaries(const std::filesystem::path& out);

// A sample's value of a varied key, as its JSON's "varied" writes it:
// numbers, [x, y, z], or a choice's name.
Json sweptValueJson(const SweepKey& key, const ParameterValue& value);

} // namespace swell::app
