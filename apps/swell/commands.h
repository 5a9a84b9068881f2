// The subcommands of the swell executable. Each returns a process exit code;
// bad input throws swell::InputError and other failures std::exception, which
// main() turns into kExitBadInput and kExitFailure with one message format.
#pragma once

#include "viewer/view_quality.h"

#include "swell/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace swell::app {

// How frames reach the output, shared by view, render and bench.
struct OutputSettings {
    std::optional<Antialiasing> antialiasing; // --antialiasing; unset: the scene's
    double renderScale = 1.0;                 // --scale: frame size over output size
    // Applies the antialiasing override to a scene.
    void applyTo(Scene& scene) const
    {
        if (antialiasing)
            scene.antialiasing = *antialiasing;
    }
};

struct RenderOptions {
    std::string scenePath;          // empty: the built-in default scene
    std::string output;             // .png (one frame, or a sequence), or .mp4
    int width = 1280, height = 720; // pixels
    double time_s = 0.0;            // simulation time of the (first) frame, s
    std::optional<double> duration_s; // render a sequence this long, s
    double fps = 30.0;              // frames per second of a sequence
    bool labels = false;            // also write each frame's ground truth (label_files.h)
    OutputSettings outputSettings;
};
int runRender(const RenderOptions& options);

struct DatasetOptions {
    std::string sweepPath;       // the sweep file (swell/dataset/sweep.h)
    std::string out;             // the dataset's folder
    std::string shard = "1/1";   // K/N: this run renders samples i with i % N == K - 1
    std::filesystem::path presets; // where a sweep's scene may be a preset's name
    bool dryRun = false;         // check and write the manifest, render nothing
};
int runDataset(const DatasetOptions& options);

struct ViewOptions {
    std::string scenePath;
    // For tests and scripts: quit after this many frames, writing a screenshot
    // to screenshotPath first when it is set.
    int exitAfterFrames = 0;
    // Simulation time a scripted frame advances, s: 1/60 by default; longer
    // steps stand for the slow frames of a real-time run on a slow machine.
    double scriptedStep_s = 1.0 / 60.0;
    std::string screenshotPath;
    // For tests: end every frame with a wait this long, ms (a deliberately
    // slow frame), and log what the panel saw pressed (viewer/gui.h).
    int slowFrame_ms = 0;
    bool logInput = false;
    int width = 1280, height = 720;
    OutputSettings outputSettings;
    // When the renderer's temporal resolve (Renderer::setTemporalResolve)
    // replaces the scene's antialiasing: by default while the camera rests
    // (viewer/view_quality.h).
    viewer::TemporalMode temporal = viewer::TemporalMode::WhileStill;
    // Dynamic resolution: the render scale follows the frame time towards
    // this, ms (viewer/dynamic_scale.h); 0 keeps outputSettings.renderScale.
    double frameTarget_ms = viewer::QualitySettings{}.frameTarget_ms;
};
int runView(const ViewOptions& options);

// True when a window can be opened (a display is there and usable).
bool displayAvailable();

struct BenchOptions {
    int width = 1280, height = 720;
    // The defaults keep a run of the default scene at 1280x720 to about a
    // minute on 2 shared cores with llvmpipe (docs/PERFORMANCE.md).
    int frames = 40;       // measured frames along the camera path
    int warmup = 5;        // frames rendered and discarded first
    std::string jsonPath;  // also write the results as JSON here
    bool stages = false;   // also time the wave model's stages inside the "ocean" pass
    bool terms = false;    // also measure the water with each shading term left out, and each reflection lookup
    // Also draw the label pass after each frame (Renderer::renderLabels, its
    // arrays read back), as `swell dataset` draws a labelled sample, and
    // report it beside the colour frame.
    bool labels = false;
    // Also draw each frame through the scene camera's sensor
    // (swell::renderSensorFrame: its lens, shutter and readout) and report
    // it beside the frame.
    bool sensor = false;
    // Also draw each frame as a host would (Renderer::draw, Swell's world
    // and sky) with motion vectors (DrawOptions::motionVectors) and report
    // their pass beside the frame.
    bool motionVectors = false;
    OutputSettings outputSettings;
    // Every frame from the scene's own camera (the view `swell view` opens
    // on) instead of the camera path, to compare with the viewer.
    bool still = false;
    // The renderer's temporal resolve on (as `swell view` draws), in place
    // of the scene's antialiasing: its pass is "temporal resolve".
    bool temporal = false;
    // The renderer interactive (Renderer::setInteractive), as `swell view`
    // draws: no frame replays the foam's history, and on a software
    // rasteriser the spectral fields come from the CPU's FFTs.
    bool interactive = false;
    // The water drawn in one pass, its grid shaded in its own fragments, in
    // place of a visibility pass and one shading run per water pixel
    // (docs/RENDERING.md "The water in two passes"), to compare the two.
    bool waterOnePass = false;
    std::string scenePath; // the scene benchmarked; empty: the built-in default
};
int runBench(const BenchOptions& options);
// Renders a measured frame takes with BenchOptions::terms: the frame, each
// term variant, and each reflection lookup.
int benchRendersPerFrameWithTerms();

} // namespace swell::app
