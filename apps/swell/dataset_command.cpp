// `swell dataset SWEEP --out DIR [--shard K/N]`: renders a sweep's samples
// (swell/dataset/sweep.h) into DIR (docs/DATASETS.md).
//
// The whole request is checked before anything is made: the shard, the
// sweep, its base scene, every sample of the shard as drawn (its scene, its
// lens at the sweep's size, its history's cost), and the folder. Each file
// is written whole or not at all and each sample's JSON last, with Ctrl-C
// and SIGTERM held off while a sample's files are written; a sample counts
// as done only when its files are whole and say what the sweep draws for
// it (dataset_folder.h), so a run stopped at any point and started again
// renders what is not done, once, and gives the same bytes. DIR/coco.json
// is written by the run that finds every sample done, and removed by one
// that finds one not done.
#include "commands.h"
#include "core/thread_cpu.h"
#include "dataset_coco.h"
#include "dataset_folder.h"
#include "flow_files.h"
#include "label_files.h"
#include "label_rig.h"
#include "progress.h"
#include "scene_loading.h"

#include "swell/dataset/atomic_file.h"
#include "swell/dataset/flow.h"
#include "swell/dataset/sensor.h"
#include "swell/dataset/sweep.h"
#include "swell/error.h"
#include "swell/frame_request.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <sched.h>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

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

// The base scene's file: beside the sweep, else a preset of that name.
fs::path baseScenePath(const Sweep& sweep, const fs::path& presets)
{
    if (const std::optional<fs::path> file = sweepSceneFile(sweep))
        return *file;
    try {
        return resolveScenePath(sweep.scene, presets);
    } catch (const InputError& e) {
        throw InputError(sweep.scenePlace, fmt::format("scene: {}", e.message()));
    }
}

// The base scene. A file that cannot be read at all (a folder, a FIFO, a
// device) is refused at the sweep's `scene` line; a problem inside it at
// its own line.
Scene loadBaseScene(const Sweep& sweep, const fs::path& path)
{
    try {
        return loadSceneOrDefault(path.string());
    } catch (const InputError& e) {
        if (e.place().line > 0 || e.place().path != path.string())
            throw;
        throw InputError(sweep.scenePlace, fmt::format("scene: '{}': {}", path.string(), e.message()));
    }
}

// The keys whose values decide whether a lens can draw the sweep's size.
bool variesTheLens(const Sweep& sweep)
{
    return std::any_of(sweep.vary.begin(), sweep.vary.end(), [](const SweepKey& k) {
        return k.key.starts_with("camera.distortion_") || k.key.starts_with("camera.fisheye_") ||
               k.key == "camera.lens" || k.key == "camera.fov_y_deg";
    });
}

// Every sample of the shard as drawn, refused (at the varied key's line in
// the sweep where one is to blame) before anything is made: its scene's
// checks, its lens at the sweep's size, and its history's cost.
void checkSamples(const Sweep& sweep, const Scene& base, const fs::path& scenePath, int shard, int shards)
{
    const bool eachLens = variesTheLens(sweep);
    if (!eachLens)
        checkLens(base, sweep.size, base.camera.fovY_deg, scenePath);
    for (const RigCamera& rig : base.camera.rig) // a rig camera's own field of view, through the same lens
        if (rig.fovY_deg > 0.0)
            checkLens(base, sweep.size, rig.fovY_deg, scenePath);
    for (int i = shard - 1; i < sweep.count; i += shards) {
        const SweepSample sample = sweepSample(sweep, base, i);
        try {
            // As a change of the base scene (valid already): the files and the
            // wave set are checked again only where a varied key changes them.
            validateSceneChange(base, sample.scene, scenePath);
            if (eachLens)
                checkLens(sample.scene, sweep.size, sample.scene.camera.fovY_deg, scenePath);
        } catch (const InputError& e) {
            throw InputError(e.place(), fmt::format("sample {}, as the sweep draws it: {}", i, e.message()));
        }
        // A clip steps on to its last frame's time (and the labels one frame on, its flow's).
        const double last_s = sweep.clip ? sweep.clip->frameTime_s(sample.time_s, sweep.clip->frames) : sample.time_s;
        if (const std::string problem = historyProblem(sample.scene, last_s); !problem.empty())
            throw InputError(sweep.timePlace, fmt::format("time_s: sample {} at {}", i, problem));
    }
}

// Ctrl-C, SIGTERM and SIGHUP held off while one sample's files (or the
// COCO file) are written, so that a run stopped that way never leaves part
// of a sample: a stop that comes then is kept, and acted on (the default
// action: the process ends) once the files are in place. Any other time it
// acts at once. Whichever thread the signal reaches (the renderer has
// threads of its own), the handler decides.
std::atomic<bool> writing{false};
volatile sig_atomic_t heldStop = 0;

void onStop(int signal)
{
    if (writing.load()) {
        heldStop = signal;
        return;
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

class HoldStops {
public:
    HoldStops()
    {
        static const bool installed = [] {
            for (int s : {SIGINT, SIGTERM, SIGHUP})
                std::signal(s, onStop);
            return true;
        }();
        (void)installed;
        writing.store(true);
    }
    ~HoldStops()
    {
        writing.store(false);
        if (const int s = heldStop) {
            std::signal(s, SIG_DFL);
            std::raise(s);
        }
    }
    HoldStops(const HoldStops&) = delete;
    HoldStops& operator=(const HoldStops&) = delete;
};

// One frame of a sample: a still, or frame `frame` of a clip drawn at
// time_s, with its flow to the next frame when it has one.
struct SampleFrame {
    int frame = 0;
    double time_s = 0.0;
    Camera camera;               // the scene's camera: the platform of a rig
    PlatformMotion platform;     // how it moves
    std::optional<PlatformMotion> previousPlatform; // at the clip's frame before (none for its first, a still)
    std::vector<RigFrame> shots; // each camera's frame: the rig's, or the scene's camera alone (named "")
};

void writeFrame(const fs::path& out, int i, const Sweep& sweep, const SweepSample& sample, const Renderer& renderer,
                const SampleFrame& f, const std::vector<std::optional<FrameFlow>>& flows)
{
    const std::vector<std::string> cameras = frameCameras(sample.scene);
    const HoldStops hold;
    try {
        for (std::size_t c = 0; c < f.shots.size(); ++c) {
            const RigFrame& shot = f.shots[c];
            const std::optional<FrameFlow>& flow = flows[c];
            const fs::path png = rigCameraPath(framePng(out, i, sweep, f.frame), shot.name);
            FrameLabels labels;
            if (shot.frame.labels) {
                labels = *shot.frame.labels;
            } else {
                labels.size = sweep.size;
                labels.camera = sensorCalibrationOf(shot.camera, lensOf(sample.scene.camera), sweep.size);
                labels.horizon = horizonOf(labels.camera);
                labels.classes = labelClassesOf(sample.scene);
            }
            Json json =
                frameJson(labels, sample.scene, f.time_s, 4.0 * renderer.waveModel().heightDeviation_m(), png);
            json["sample"] = i;
            if (sweep.clip)
                json["frame"] = f.frame;
            if (flow)
                json["flow"] = flowJson(*flow, f.time_s);
            json["platform"] = platformJson(f.platform, f.camera, sample.scene.labels.worldFrame, f.previousPlatform);
            if (!shot.name.empty())
                json["rig"] = rigJson(shot.name, labels.camera, f.platform, cameras);
            Json varied = Json::object();
            for (std::size_t k = 0; k < sweep.vary.size(); ++k)
                varied[sweep.vary[k].key] = sweptValueJson(sweep.vary[k], sample.values[k]);
            json["varied"] = varied;
            writePngAtomically(shot.frame.image, png);
            if (shot.frame.labels)
                writeLabelArrays(labels, png, sample.scene.labels.worldFrame);
            if (flow)
                writeFlowFiles(*flow, png);
            writeFrameJson(json, png); // last: the camera's frame is done
        }
    } catch (...) {
        removeSample(out, i, sweep, cameras); // a disk that filled half way: none of the sample stays
        throw;
    }
}

SampleFrame drawFrame(Renderer& renderer, const Sweep& sweep, int frame, double time_s)
{
    SampleFrame f;
    f.frame = frame;
    f.time_s = time_s;
    if (!renderer.scene().camera.rig.empty()) {
        f.shots = renderRigFrames(renderer, time_s, sweep.size, sweep.labels);
        f.camera = renderer.sceneCameraAt(time_s);
    } else {
        SensorFrame sensor = renderSensorFrame(
            renderer, [&renderer](double s) { return renderer.sceneCameraAt(s); }, time_s, sweep.size, sweep.labels);
        f.camera = sensor.camera;
        f.shots.push_back({"", f.camera, std::move(sensor)});
    }
    // After the draws, which go through the sensor's times in order.
    f.platform = renderer.platformAt(time_s);
    return f;
}

// A clip's frames in order, the camera and the bodies moving as the
// simulation moves them, one renderer throughout: each frame written once
// the next one's labels give its flow (the last frame's: labels drawn one
// frame on for it alone).
void writeClip(const fs::path& out, int i, const Sweep& sweep, const SweepSample& sample, Renderer& renderer)
{
    const SweepClip& clip = *sweep.clip;
    const double interval_s = 1.0 / clip.fps;
    std::optional<SampleFrame> pending;
    // Each camera's flow to its own frame in `next` (none without labels).
    const auto flowsTo = [&](const SampleFrame& from, const SampleFrame* next) {
        std::vector<std::optional<FrameFlow>> flows(from.shots.size());
        for (std::size_t c = 0; next != nullptr && c < from.shots.size(); ++c)
            flows[c] = opticalFlowOf(*from.shots[c].frame.labels, from.time_s, *next->shots[c].frame.labels,
                                     interval_s, seaMotionOf(renderer.scene(), renderer.waveModel()));
        return flows;
    };
    for (int k = 0; k < clip.frames; ++k) {
        SampleFrame f = drawFrame(renderer, sweep, k, clip.frameTime_s(sample.time_s, k));
        if (pending)
            f.previousPlatform = pending->platform;
        if (pending)
            writeFrame(out, i, sweep, sample, renderer, *pending, flowsTo(*pending, sweep.labels ? &f : nullptr));
        pending = std::move(f);
    }
    std::vector<std::optional<FrameFlow>> lastFlows(pending->shots.size());
    if (sweep.labels) {
        const double next_s = clip.frameTime_s(sample.time_s, clip.frames);
        if (renderer.scene().camera.rig.empty()) {
            // Its labels alone: the sensor's draws of an image nobody sees
            // would cost motion_samples frames with a shutter.
            lastFlows[0] = opticalFlowOf(*pending->shots[0].frame.labels, pending->time_s,
                                         renderSensorLabels(renderer, renderer.sceneCameraAt(next_s), next_s, sweep.size),
                                         interval_s, seaMotionOf(renderer.scene(), renderer.waveModel()));
        } else {
            const SampleFrame next = drawFrame(renderer, sweep, clip.frames, next_s);
            lastFlows = flowsTo(*pending, &next);
        }
    }
    writeFrame(out, i, sweep, sample, renderer, *pending, lastFlows);
}

void renderSamples(const fs::path& out, const Sweep& sweep, const Scene& base, const std::vector<int>& todo)
{
    gl::HeadlessContext context(true);
    gl::DebugHandler debug = gl::logOnceDebugHandler();
    gl::installDebugHandler(&debug);
    std::unique_ptr<Renderer> renderer;
    Progress progress("rendering samples", int(todo.size()));
    for (int i : todo) {
        const SweepSample sample = sweepSample(sweep, base, i);
        // One renderer for the shard: a new sample rebuilds only what its
        // values change (the wave model for a new wind, not the programs).
        if (!renderer)
            renderer = std::make_unique<Renderer>(sample.scene);
        else
            renderer->setScene(sample.scene);
        if (sweep.clip)
            writeClip(out, i, sweep, sample, *renderer);
        else
            writeFrame(out, i, sweep, sample, *renderer, drawFrame(*renderer, sweep, 0, sample.time_s),
                       std::vector<std::optional<FrameFlow>>(frameCameras(sample.scene).size()));
        progress.advance();
    }
    progress.finish();
}

// The cores this process may run on (its CPU affinity), which a software
// rasteriser's threads share: the run's cores.
int coresOfThisProcess()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof set, &set) != 0)
        return 1;
    return std::max(1, CPU_COUNT(&set));
}

// What a core of a cluster renders: this run's samples over its wall time
// (from its start, the checks included, to its last sample written) and
// over its cores; then the same samples over the process's CPU time (all
// threads), which another program's load on the machine moves far less.
void reportSamplesPerCore(int rendered, std::chrono::steady_clock::time_point start)
{
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int cores = coresOfThisProcess();
    const double cpu_s = detail::processCpu_ms() * 1e-3;
    std::fprintf(stderr,
                 "swell: %d samples rendered in %.2f s on %d cores: %.4f samples per second per core "
                 "(samples / wall time / cores); %.2f s of CPU: %.4f samples per CPU second\n",
                 rendered, wall_s, cores, double(rendered) / wall_s / double(cores), cpu_s,
                 cpu_s > 0.0 ? double(rendered) / cpu_s : 0.0);
}

} // namespace

int runDataset(const DatasetOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    // The whole request, checked before anything is made.
    const auto [shard, shards] = parseShard(options.shard);
    if (options.out.empty())
        throw InputError({"--out"}, "the dataset's folder is empty: give a folder (made when missing)");
    const Sweep sweep = loadSweepFile(options.sweepPath);
    const fs::path scenePath = baseScenePath(sweep, options.presets);
    const Scene base = loadBaseScene(sweep, scenePath);
    checkSweep(sweep, base);
    checkSamples(sweep, base, scenePath, shard, shards);
    const fs::path out = options.out;
    checkOutputFolder(out, sweep);

    prepareOutputFolder(out, sweep, base);
    removeOrphanedTemporaries(out);
    // What this shard renders: each of its samples not done, and a broken
    // one (a file cut short, emptied, or another sweep's) said and removed.
    std::vector<int> todo;
    int done = 0;
    for (int i = shard - 1; i < sweep.count; i += shards) {
        const std::string why = sampleNotDone(out, i, sweep, sweepSample(sweep, base, i));
        if (why.empty()) {
            ++done;
            continue;
        }
        std::error_code error;
        if (fs::exists(frameFiles(out, i, sweep, 0, frameCameras(base).front()).back(), error))
            std::fprintf(stderr, "swell: sample %d is not whole (%s): %s\n", i, why.c_str(),
                         options.dryRun ? "it would be rendered again" : "rendering it again");
        if (!options.dryRun)
            removeSample(out, i, sweep, frameCameras(base));
        todo.push_back(i);
    }
    std::fprintf(stderr, "swell: shard %d/%d of %s: %d samples to render, %d done already\n", shard, shards,
                 sweep.file.string().c_str(), int(todo.size()), done);
    if (options.dryRun)
        return kExitOk;
    std::error_code error;
    if (!todo.empty()) {
        fs::remove(out / "coco.json", error); // it describes samples that are not all there
        renderSamples(out, sweep, base, todo);
        reportSamplesPerCore(int(todo.size()), start);
    }

    // Every sample of every shard done: the dataset's COCO file.
    for (int i = 0; i < sweep.count; ++i)
        if (!sampleNotDone(out, i, sweep, sweepSample(sweep, base, i)).empty()) {
            fs::remove(out / "coco.json", error);
            std::printf("%s\n", fs::absolute(out).c_str());
            return kExitOk;
        }
    if (sweep.labels) {
        const std::string coco = cocoJson(out, sweep, labelClassesOf(base), frameCameras(base)).dump() + "\n";
        const HoldStops hold;
        writeFileAtomically(out / "coco.json", coco);
    }
    std::printf("%s\n", fs::absolute(out).c_str());
    return kExitOk;
}

} // namespace swell::app
