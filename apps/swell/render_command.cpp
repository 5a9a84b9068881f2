// `swell render`: headless frames to PNG, a PNG sequence, or an MP4 through
// the ffmpeg program.
#include "commands.h"
#include "flow_files.h"
#include "label_files.h"
#include "label_rig.h"
#include "progress.h"
#include "scene_loading.h"

#include "swell/camera.h"
#include "swell/dataset/flow.h"
#include "swell/dataset/sensor.h"
#include "swell/error.h"
#include "swell/frame_request.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <unistd.h>

namespace swell::app {

namespace {

namespace fs = std::filesystem;

bool programOnPath(const std::string& name)
{
    const char* path = std::getenv("PATH");
    if (!path)
        return false;
    std::string dirs = path;
    size_t start = 0;
    while (start <= dirs.size()) {
        const size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (::access(candidate.c_str(), X_OK) == 0)
            return true;
        start = end + 1;
    }
    return false;
}

// Where frame i of a sequence goes: NAME.png -> NAME_00042.png.
fs::path sequencePath(const fs::path& output, int frame)
{
    return output.parent_path() / fmt::format("{}_{:05d}{}", output.stem().string(), frame, output.extension().string());
}

// Pipes raw RGBA frames into ffmpeg, which encodes H.264 into an MP4.
class VideoWriter {
public:
    VideoWriter(const fs::path& output, int width, int height, double fps)
    {
        const std::string command = fmt::format(
            "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s {}x{} -r {} -i - -c:v libx264 -pix_fmt yuv420p "
            "-movflags +faststart '{}'",
            width, height, fps, output.string());
        pipe_ = ::popen(command.c_str(), "w");
        if (!pipe_)
            throw Error("cannot start ffmpeg");
    }
    ~VideoWriter()
    {
        if (pipe_)
            ::pclose(pipe_);
    }
    void write(const Image& image)
    {
        if (std::fwrite(image.rgba.data(), 1, image.rgba.size(), pipe_) != image.rgba.size())
            throw Error("ffmpeg stopped taking frames (see its message above)");
    }
    void finish()
    {
        const int status = ::pclose(pipe_);
        pipe_ = nullptr;
        if (status != 0)
            throw Error(fmt::format("ffmpeg failed (exit status {})", status));
    }

private:
    FILE* pipe_ = nullptr;
};

// Creates the output's missing parent folders (as --help says), or says in
// plain words why it cannot: a part of the path that is a file, no permission.
void createOutputFolder(const fs::path& output)
{
    const fs::path folder = output.parent_path();
    if (folder.empty())
        return;
    // The deepest part of the path that exists must be a folder.
    for (fs::path part = folder; !part.empty(); part = part.parent_path()) {
        std::error_code error;
        const fs::file_status status = fs::status(part, error);
        if (fs::exists(status)) {
            if (!fs::is_directory(status))
                throw InputError({"--output"}, fmt::format("cannot write '{}': '{}' is a file, not a folder",
                                                           output.string(), part.string()));
            break;
        }
        if (part == part.parent_path())
            break;
    }
    std::error_code error;
    fs::create_directories(folder, error);
    if (error)
        throw InputError({"--output"}, fmt::format("cannot create the folder '{}' for '{}': {}", folder.string(),
                                                   output.string(), error.message()));
}

// A labelled frame of one camera waiting for the next frame's labels, which
// its flow needs, with the platform's state at its time.
struct PendingLabels {
    FrameLabels labels;
    fs::path colour;
    double time_s = 0.0;
    std::string camera; // its rig camera's name; "" without a rig
    PlatformMotion platform;
    Camera platformCamera;
    std::optional<PlatformMotion> previousPlatform; // at the frame before (none for the first)
};

// Writes a frame's labels with its flow to `next` (drawn interval_s later):
// the arrays, the flow, then the JSON, last, as for every labelled frame.
void writeLabelsWithFlow(const PendingLabels& frame, const FrameLabels& next, double interval_s,
                         const Renderer& renderer)
{
    const FrameFlow flow = opticalFlowOf(frame.labels, frame.time_s, next, interval_s,
                                         seaMotionOf(renderer.scene(), renderer.waveModel()));
    const Scene& scene = renderer.scene();
    writeLabelArrays(frame.labels, frame.colour, scene.labels.worldFrame);
    writeFlowFiles(flow, frame.colour);
    Json json = frameJson(frame.labels, scene, frame.time_s, 4.0 * renderer.waveModel().heightDeviation_m(),
                          frame.colour);
    json["flow"] = flowJson(flow, frame.time_s);
    json["platform"] = platformJson(frame.platform, frame.platformCamera, scene.labels.worldFrame, frame.previousPlatform);
    if (!frame.camera.empty())
        json["rig"] = rigJson(frame.camera, frame.labels.camera, frame.platform, frameCameras(scene));
    writeFrameJson(json, frame.colour);
}

// Every camera's frame at time_s: the rig's, drawn from one simulated
// state, or the scene's one camera.
std::vector<RigFrame> cameraFrames(Renderer& renderer, double time_s, glm::ivec2 size, bool labels)
{
    if (!renderer.scene().camera.rig.empty())
        return renderRigFrames(renderer, time_s, size, labels);
    SensorFrame frame = renderSensorFrame(
        renderer, [&renderer](double s) { return renderer.sceneCameraAt(s); }, time_s, size, labels);
    std::vector<RigFrame> frames;
    frames.push_back({"", frame.camera, std::move(frame)});
    return frames;
}

} // namespace

int runRender(const RenderOptions& options)
{
    const fs::path output = options.output;
    const std::string extension = output.extension().string();
    if (extension != ".png" && extension != ".mp4")
        throw InputError({"--output"}, fmt::format("'{}': the output must end in .png or .mp4", options.output));
    const bool video = extension == ".mp4";
    if (video && !options.duration_s)
        throw InputError({"--output"}, "an .mp4 output needs --duration SECONDS");
    if (video && options.labels)
        throw InputError({"--labels"}, "labels are written beside PNG frames: give a .png output (with --duration, "
                                       "a sequence) instead of an .mp4");
    if (video && !programOnPath("ffmpeg"))
        throw InputError({"--output"}, "writing .mp4 needs the ffmpeg program, which is not installed "
                                       "(apt-get install ffmpeg), or write a PNG sequence instead");
    Scene scene = loadSceneOrDefault(options.scenePath);
    options.outputSettings.applyTo(scene);
    if (video && !scene.camera.rig.empty())
        throw InputError({"--output"}, "a rig's cameras are written as PNG frames, one per camera: give a .png output");
    if (const std::string problem = historyProblem(scene, options.time_s); !problem.empty())
        throw InputError({"--time"}, problem);
    // A long wait before the first frame says what it is spent on.
    if (const std::string note = historyNote(scene, options.time_s); !note.empty())
        std::fprintf(stderr, "swell: %s\n", note.c_str());
    checkLens(scene, {options.width, options.height}, scene.camera.fovY_deg, options.scenePath);
    for (const RigCamera& rig : scene.camera.rig)
        if (rig.fovY_deg > 0.0)
            checkLens(scene, {options.width, options.height}, rig.fovY_deg, options.scenePath);
    // Everything checked: only now is anything made on disk.
    createOutputFolder(output);
    gl::HeadlessContext context(true);
    gl::DebugHandler debug = gl::logOnceDebugHandler();
    gl::installDebugHandler(&debug);
    Renderer renderer(scene);
    renderer.setRenderScale(options.outputSettings.renderScale);
    const glm::ivec2 size(options.width, options.height);

    const int frames = options.duration_s ? std::max(1, int(std::lround(*options.duration_s * options.fps))) : 1;
    std::unique_ptr<VideoWriter> videoWriter;
    if (video)
        videoWriter = std::make_unique<VideoWriter>(output, options.width, options.height, options.fps);
    Progress progress("rendering frames", frames);
    // A frame's flow goes to the next frame, one frame interval on (a still's
    // and the last frame's: to a frame of labels drawn for it alone).
    const double interval_s = 1.0 / options.fps;
    std::vector<PendingLabels> pending;
    std::optional<PlatformMotion> previousPlatform;
    for (int i = 0; i < frames; ++i) {
        const double t = options.time_s + double(i) / options.fps;
        // Through the camera's lens and sensor (swell/dataset/sensor.h), the
        // camera where the scene puts it at each time the sensor draws.
        std::vector<RigFrame> shots = cameraFrames(renderer, t, size, options.labels);
        const fs::path frame = options.duration_s ? sequencePath(output, i) : output;
        // The flow asks the waves at the last frame's time and this one's
        // before the bodies' thread asks them at the next.
        if (options.labels) {
            const PlatformMotion platform = renderer.platformAt(t);
            const Camera platformCamera = renderer.sceneCameraAt(t);
            for (std::size_t c = 0; c < pending.size(); ++c)
                writeLabelsWithFlow(pending[c], *shots[c].frame.labels, interval_s, renderer);
            pending.clear();
            for (RigFrame& shot : shots)
                pending.push_back(PendingLabels{std::move(*shot.frame.labels), rigCameraPath(frame, shot.name), t,
                                                shot.name, platform, platformCamera, previousPlatform});
            previousPlatform = platform;
        }
        // The bodies step towards the next frame (or the last frame's labels
        // for its flow) while this one is written.
        if (i + 1 < frames || options.labels)
            renderer.anticipate(firstDrawTime_s(scene.camera, options.time_s + double(i + 1) / options.fps));
        for (const RigFrame& shot : shots) {
            if (video)
                videoWriter->write(shot.frame.image);
            else
                writePngAtomically(shot.frame.image, rigCameraPath(frame, shot.name));
        }
        progress.advance();
    }
    if (!pending.empty()) {
        const double next_s = options.time_s + double(frames) / options.fps;
        if (scene.camera.rig.empty()) {
            const FrameLabels next = renderSensorLabels(renderer, renderer.sceneCameraAt(next_s), next_s, size);
            writeLabelsWithFlow(pending.front(), next, interval_s, renderer);
        } else {
            const std::vector<RigFrame> next = renderRigFrames(renderer, next_s, size, true);
            for (std::size_t c = 0; c < pending.size(); ++c)
                writeLabelsWithFlow(pending[c], *next[c].frame.labels, interval_s, renderer);
        }
    }
    if (videoWriter)
        videoWriter->finish();
    progress.finish();
    if (options.duration_s && !video)
        std::printf("%s .. %s\n", fs::absolute(sequencePath(output, 0)).c_str(),
                    fs::absolute(sequencePath(output, frames - 1)).c_str());
    else
        std::printf("%s\n", fs::absolute(output).c_str());
    return kExitOk;
}

} // namespace swell::app
