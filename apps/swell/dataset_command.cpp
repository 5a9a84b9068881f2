// `swell dataset SWEEP --out DIR [--shard K/N]`: renders a sweep's samples
// (swell/dataset/sweep.h) into DIR, each file written whole or not at all and each
// sample's JSON last, so a sample whose JSON exists is done: a run killed
// at any point and started again renders each missing sample once and
// nothing twice. DIR/manifest.json records the sweep; DIR/coco.json the
// boxes and masks of every sample, once all are done (docs/DATASETS.md).
#include "commands.h"
#include "dataset_coco.h"
#include "label_files.h"
#include "progress.h"
#include "scene_loading.h"

#include "swell/dataset/atomic_file.h"
#include "swell/dataset/sensor.h"
#include "swell/dataset/sweep.h"
#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <set>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kDatasetFormat = "swell-dataset-1";

fs::path samplePng(const fs::path& out, int i) { return out / "samples" / fmt::format("{:06d}.png", i); }

// "K/N" with 1 <= K <= N.
std::pair<int, int> parseShard(const std::string& shard)
{
    const std::size_t slash = shard.find('/');
    int k = 0, n = 0;
    const auto whole = [](std::string_view s, int& v) {
        const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        return error == std::errc() && end == s.data() + s.size() && !s.empty();
    };
    if (slash == std::string::npos || !whole(std::string_view(shard).substr(0, slash), k) ||
        !whole(std::string_view(shard).substr(slash + 1), n) || n < 1 || k < 1 || k > n)
        throw InputError({"--shard"}, fmt::format("'{}': a shard is K/N, this run's part K of N parts, 1 <= K <= N "
                                                  "(1/4 .. 4/4 for four machines)",
                                                  shard));
    return {k, n};
}

// The folder exists (created if missing) and takes new files.
void prepareOut(const fs::path& out)
{
    std::error_code error;
    fs::create_directories(out / "samples", error);
    if (error)
        throw InputError({"--out"}, fmt::format("cannot create '{}': {}", (out / "samples").string(), error.message()));
    const fs::path probe = out / "samples" / ".write-test";
    {
        std::ofstream test(probe);
        if (!test)
            throw InputError({"--out"}, fmt::format("'{}' is not writable", (out / "samples").string()));
    }
    fs::remove(probe, error);
}

// The manifest: written by the first run, and the same sweep asked of every later one.
void checkManifest(const fs::path& out, const Sweep& sweep, const Scene& base)
{
    const fs::path path = out / "manifest.json";
    Json manifest;
    manifest["format"] = kDatasetFormat;
    manifest["sweep_file"] = sweep.file.filename().string();
    manifest["sweep"] = sweep.text;
    manifest["count"] = sweep.count;
    manifest["seed"] = sweep.seed;
    manifest["size"] = {sweep.size.x, sweep.size.y};
    manifest["labels"] = sweep.labels;
    Json classes = Json::object();
    const std::vector<std::string> names = labelClassesOf(base);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!names[i].empty())
            classes[std::to_string(i)] = names[i];
    manifest["classes"] = classes;
    manifest["samples"] = "samples/NNNNNN.png, and beside each its labels (docs/LABELS.md); a sample is done when "
                          "its .json is there";
    std::error_code error;
    if (fs::exists(path, error)) {
        Json existing;
        try {
            existing = Json::parse(readFileBytes(path));
        } catch (const std::exception& e) {
            throw InputError({path.string()}, fmt::format("not a dataset manifest: {}", e.what()));
        }
        if (existing.value("format", "") != kDatasetFormat || existing.value("sweep", "") != sweep.text)
            throw InputError({"--out"}, fmt::format("'{}' holds another sweep's dataset (its manifest.json records a "
                                                    "different sweep file): give another folder",
                                                    out.string()));
        return;
    }
    writeFileAtomically(path, manifest.dump(2) + "\n");
}

} // namespace

int runDataset(const DatasetOptions& options)
{
    const Sweep sweep = loadSweepFile(options.sweepPath);
    // The base scene: beside the sweep file, else a preset of that name.
    fs::path scenePath = sweep.file.parent_path() / sweep.scene;
    std::error_code error;
    if (!fs::exists(scenePath, error)) {
        try {
            scenePath = resolveScenePath(sweep.scene, options.presets);
        } catch (const InputError& e) {
            throw InputError(sweep.scenePlace, fmt::format("scene: {}", e.message()));
        }
    }
    const Scene base = loadSceneOrDefault(scenePath.string());
    checkSweep(sweep, base);
    // Each sample is a still: its bodies are stepped from their start.
    checkSteppedHistory(base, sweep.timeMax_s, fmt::format("{}: time_s", sweep.file.string()));
    const auto [shard, shards] = parseShard(options.shard);
    const fs::path out = options.out;
    prepareOut(out);
    checkManifest(out, sweep, base);

    std::vector<int> todo;
    int done = 0;
    for (int i = shard - 1; i < sweep.count; i += shards) {
        if (fs::exists(labelFilePaths(samplePng(out, i))[5], error))
            ++done;
        else
            todo.push_back(i);
    }
    // A run killed while writing leaves its temporary files (".NAME.*.tmp",
    // swell/dataset/atomic_file.h): those of the samples this shard renders again
    // go (no other shard writes them).
    std::set<std::string> again;
    for (int i : todo)
        again.insert(fmt::format(".{:06d}.", i));
    for (const fs::directory_entry& e : fs::directory_iterator(out / "samples", error)) {
        const std::string name = e.path().filename().string();
        if (name.size() > 8 && name.ends_with(".tmp") && again.count(name.substr(0, 8)))
            fs::remove(e.path(), error);
    }
    std::fprintf(stderr, "swell: shard %d/%d of %s: %d samples to render, %d done already\n", shard, shards,
                 sweep.file.string().c_str(), int(todo.size()), done);

    if (options.dryRun)
        return kExitOk;
    if (!todo.empty()) {
        gl::HeadlessContext context(true);
        gl::DebugHandler debug = gl::logOnceDebugHandler();
        gl::installDebugHandler(&debug);
        std::unique_ptr<Renderer> renderer;
        Progress progress("rendering samples", int(todo.size()));
        for (int i : todo) {
            const SweepSample sample = sweepSample(sweep, base, i);
            try {
                validateScene(sample.scene, scenePath);
            } catch (const InputError& e) {
                throw InputError({sweep.file.string()}, fmt::format("sample {}: the drawn values make a scene that "
                                                                  "is refused: {}",
                                                                  i, e.what()));
            }
            // One renderer for the shard: a new sample rebuilds only what its
            // values change (the wave model for a new wind, not the programs).
            if (!renderer)
                renderer = std::make_unique<Renderer>(sample.scene);
            else
                renderer->setScene(sample.scene);
            const Camera camera = renderer->sceneCameraAt(sample.time_s);
            const fs::path png = samplePng(out, i);
            const SensorFrame sensor = renderSensorFrame(*renderer, camera, sample.time_s, sweep.size, sweep.labels);
            writePngAtomically(sensor.image, png);
            FrameLabels labels;
            if (sensor.labels) {
                labels = *sensor.labels;
                writeLabelArrays(labels, png);
            } else {
                labels.size = sweep.size;
                labels.camera = calibrationOf(camera, sweep.size);
                const LensDistortion lens = lensOf(sample.scene.camera);
                labels.camera.k1 = lens.k1;
                labels.camera.k2 = lens.k2;
                labels.camera.k3 = lens.k3;
                labels.camera.p1 = lens.p1;
                labels.camera.p2 = lens.p2;
                labels.horizon = horizonOf(labels.camera);
                labels.classes = labelClassesOf(sample.scene);
            }
            Json json = frameJson(labels, sample.scene, sample.time_s, 4.0 * renderer->waveModel().heightDeviation_m(), png);
            json["sample"] = i;
            Json varied = Json::object();
            for (const SweepKey& k : sweep.vary)
                varied[k.key] = sampleValueJson(sample.scene, k.key);
            json["varied"] = varied;
            writeFrameJson(json, png); // last: the sample is done
            progress.advance();
        }
        progress.finish();
    }

    // Every sample of every shard done: the dataset's COCO file.
    for (int i = 0; i < sweep.count; ++i)
        if (!fs::exists(labelFilePaths(samplePng(out, i))[5], error)) {
            std::printf("%s\n", fs::absolute(out).c_str());
            return kExitOk;
        }
    if (sweep.labels)
        writeFileAtomically(out / "coco.json", cocoJson(out, sweep.count, labelClassesOf(base)).dump() + "\n");
    std::printf("%s\n", fs::absolute(out).c_str());
    return kExitOk;
}

} // namespace swell::app
