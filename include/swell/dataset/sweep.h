// Sweep files: a dataset of labelled frames as a base scene and the ranges
// its parameters vary over (docs/DATASETS.md). Sample i of a sweep is fully
// determined by the sweep and i: each varied value is drawn from its own
// stream, keyed by (seed, i, key), so adding a key changes no other key's
// values and any machine draws the same.
#pragma once

#include "swell/export.h"

#include "swell/error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swell {

// The largest sweep: samples are numbered with six digits.
inline constexpr int kMaxSweepSamples = 1000000;

// How one key varies.
struct SWELL_API SweepKey {
    // As written: a scene parameter ("camera.roll_deg", "sun.azimuth_deg")
    // or one in an item of a list ("objects[1].yaw_deg"). The sun's angles
    // may vary on any base scene: the sample's sun is then given by them.
    std::string key;
    SourcePlace place;
    enum class Kind { Range, OneOf } kind = Kind::Range;
    // Range: uniform between lo and hi (both included; whole numbers for an
    // Integer parameter; each component for a vector). OneOf: one of these,
    // each as likely. A single value is a OneOf of one.
    ParameterValue lo{}, hi{};
    std::vector<ParameterValue> choices;
};

// The longest clip a sample may be, frames.
inline constexpr int kMaxClipFrames = 10000;

// A sample that is a clip (docs/DATASETS.md, "Clips"): `frames` frames at
// `fps` along the simulated time from the sample's time, each with its
// labels and its optical flow to the next.
struct SWELL_API SweepClip {
    int frames = 1;      // 1..kMaxClipFrames
    double fps = 30.0;   // frames per second of simulated time, (0, 240]
    SourcePlace place;   // where [clip] was written
    double frameTime_s(double start_s, int frame) const { return start_s + double(frame) / fps; }
};

struct SWELL_API Sweep {
    std::filesystem::path file;
    // The base scene: a scene file in the sweep file's folder (or below it),
    // or a preset's name (the caller looks presets up: sweepSceneFile()).
    std::string scene;
    SourcePlace scenePlace;
    SourcePlace timePlace; // where time_s was written (the file, when it was not)
    int count = 0;              // samples, 1..kMaxSweepSamples
    std::uint64_t seed = 0;
    glm::ivec2 size{640, 480};  // pixels
    double timeMin_s = 0.0, timeMax_s = 0.0; // each sample's time, uniform in [min, max], s
    bool labels = true;         // write each sample's ground truth (swell/dataset/labels.h)
    std::optional<SweepClip> clip; // each sample a clip; empty: a still
    std::vector<SweepKey> vary; // in the file's order
    std::string text;           // the file as read (a dataset's manifest keeps it)
};

// Reads and checks a sweep file's own structure and values. Throws
// InputError at file:line:column (an unknown key with a suggestion, an empty
// range, a value of the wrong type).
SWELL_API Sweep loadSweepFile(const std::filesystem::path& path);

// Checks every varied key against the base scene: it names a parameter the
// scene has (a list item that exists, the wind when the waves come from
// it) and its range lies within the parameter's. Throws InputError at the
// key's place in the sweep file.
SWELL_API void checkSweep(const Sweep& sweep, const Scene& base);

// The base scene's file: `scene` in the sweep file's folder, links
// followed; empty when no file of that name is there (a bare name may then
// be a preset's). Throws InputError at the scene's place when it is empty,
// or names a file outside the sweep's folder (as a scene's models must lie
// in the scene's folder, docs/SCENE.md).
SWELL_API std::optional<std::filesystem::path> sweepSceneFile(const Sweep& sweep);

// Sample `index` (0..count-1): the base scene with each key drawn, and its
// time. The scene's keyPlaces point each varied key at its line in the
// sweep file, so that a check of the drawn scene names it.
struct SWELL_API SweepSample {
    Scene scene;
    double time_s = 0.0;
    std::vector<ParameterValue> values; // each varied key's drawn value, in Sweep::vary's order
};
SWELL_API SweepSample sweepSample(const Sweep& sweep, const Scene& base, int index);

// A varied key's value in a scene (a sample's): the parameter's (the sun's
// angles those of its direction when it is given so). The key must be one a
// sweep file accepted.
SWELL_API ParameterValue sweptValue(const Scene& scene, std::string_view key);
// The parameter a sweep key names; nullptr for a key no sweep accepts.
SWELL_API const Parameter* sweptParameter(std::string_view key);

} // namespace swell
