// swell: view an ocean in a window, render it headless, or benchmark it.
// With no subcommand it shows the default scene in a window when a display is
// usable, and otherwise renders it to a PNG whose path it prints.
#include "commands.h"
#include "data_folders.h"
#include "scene_loading.h"

#include "scene/suggestions.h"

#include "swell/error.h"
#include "swell/frame_request.h"
#include "swell/renderer.h"
#include "swell/scene/parameters.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <vector>

namespace {

// "1280x720" -> width, height; throws CLI::ValidationError otherwise.
void parseSize(const std::string& text, int& width, int& height)
{
    static const std::regex pattern(R"((\d{1,5})x(\d{1,5}))");
    std::smatch m;
    if (!std::regex_match(text, m, pattern))
        throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 1280x720, got '" + text + "'");
    width = std::stoi(m[1]);
    height = std::stoi(m[2]);
    if (width < 1 || height < 1 || width > swell::kMaxFrameSide || height > swell::kMaxFrameSide)
        throw CLI::ValidationError("--size", swell::frameSizeMessage(text));
}

// A number from `lo` to `hi`: finite (range checks alone let NaN through, as
// every comparison with it is false) and in range. The help shows the type
// and the range as "SECONDS:0..3600", not CLI11's own validator names.
CLI::Validator numberIn(double lo, double hi)
{
    CLI::Validator check(
        [lo, hi](std::string& text) {
            try {
                size_t used = 0;
                const double value = std::stod(text, &used);
                if (used == text.size() && std::isfinite(value) && value >= lo && value <= hi)
                    return std::string();
            } catch (const std::exception&) {
            }
            return swell::outsideRangeMessage(text, lo, hi);
        },
        fmt::format("{:g}..{:g}", lo, hi));
    return check;
}

// A whole number from `lo` to `hi`, shown in the help as "N:1..100000".
CLI::Validator wholeNumberIn(long lo, long hi)
{
    CLI::Validator check(
        [lo, hi](std::string& text) {
            try {
                size_t used = 0;
                const long value = std::stol(text, &used);
                if (used == text.size() && value >= lo && value <= hi)
                    return std::string();
            } catch (const std::exception&) {
            }
            return fmt::format("must be a whole number from {} to {}, got '{}'", lo, hi, text);
        },
        fmt::format("{}..{}", lo, hi));
    return check;
}

// What the first argument most likely meant when it is not a subcommand: a
// scene file given without one gets the commands that take it; a word, the
// subcommands (from the parser, so none is left out) and the nearest one.
void suggestSubcommand(const CLI::App& app, const std::string& first)
{
    if (first.empty() || first[0] == '-')
        return;
    const bool sceneLike = first.size() > 5 && first.compare(first.size() - 5, 5, ".toml") == 0;
    if (sceneLike) {
        const std::string stem = std::filesystem::path(first).stem().string();
        std::fprintf(stderr,
                     "swell: a scene file needs a subcommand: `swell view %s` opens it in a window, "
                     "`swell render %s -o %s.png` renders it headless\n",
                     first.c_str(), first.c_str(), stem.c_str());
    } else {
        std::vector<std::string> names;
        for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
            names.push_back(command->get_name());
        std::string list;
        for (std::size_t i = 0; i < names.size(); ++i)
            list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
        const std::optional<std::string> near = swell::detail::scenefile::closest(first, names);
        std::fprintf(stderr, "swell: the subcommands are %s (swell --help)%s\n", list.c_str(),
                     near ? fmt::format("; did you mean `swell {}`?", *near).c_str() : "");
    }
}

// --antialiasing and --scale on a subcommand, into `settings`.
void addOutputOptions(CLI::App& command, swell::app::OutputSettings& settings)
{
    // The scene file's names for the modes, from the parameter table.
    const swell::Parameter& key = *swell::findParameter("antialiasing");
    const std::vector<std::string> names(key.choices.begin(), key.choices.end());
    command.add_option_function<std::string>(
               "--antialiasing",
               [&settings, names](const std::string& name) {
                   const auto at = std::find(names.begin(), names.end(), name);
                   settings.antialiasing = swell::Antialiasing(at - names.begin());
               },
               "Edge smoothing: fxaa, msaa4 or off; overrides the scene's antialiasing key (default fxaa)")
        ->type_name("MODE")
        ->check(CLI::IsMember(names));
    command.add_option("--scale", settings.renderScale,
                       "Render the frame at this fraction of the output size and scale it up (filtered); "
                       "0.5 draws a quarter of the pixels")
        ->type_name("FRACTION")
        ->check(numberIn(swell::kMinRenderScale, swell::kMaxRenderScale))
        ->capture_default_str();
}

constexpr const char* kSceneHelp =
    "Scene file (TOML), or a preset's name (storm, sunset, ...); the built-in default when omitted";

} // namespace

int main(int argc, char** argv)
{
    swell::app::nameTheDerivedDataCache();
    CLI::App app{"Swell: a real-time ocean renderer.\n"
                 "With no subcommand: a window on the default scene when a display is usable,\n"
                 "otherwise a headless render of it to swell-default.png."};
    // The version, and where this swell finds its presets and shaders.
    app.set_version_flag("--version", [] {
        const swell::app::DataFolders data = swell::app::dataFolders();
        return fmt::format("swell {}\npresets: {}\nshaders: {}", SWELL_VERSION, data.scenes.string(), data.shaders.string());
    });
    app.require_subcommand(0, 1);

    swell::app::ViewOptions view;
    std::string viewSize = "1280x720";
    CLI::App* viewCommand = app.add_subcommand("view", "Open the interactive viewer");
    viewCommand->add_option("scene", view.scenePath,
                            kSceneHelp)
        ->type_name("SCENE");
    viewCommand->add_option("--size", viewSize, "Window size, WIDTHxHEIGHT")->type_name("WxH")->capture_default_str();
    viewCommand->add_option("--exit-after-frames", view.exitAfterFrames,
                            "Quit after this many frames (for tests and scripts)")
        ->type_name("N")
        ->check(wholeNumberIn(0, 1000000));
    viewCommand->add_option("--time-step", view.scriptedStep_s,
                            "With --exit-after-frames: simulation time each frame advances, seconds (default 1/60; "
                            "longer steps stand for slow frames)")
        ->type_name("SECONDS")
        ->check(numberIn(0.0, 60.0));
    viewCommand->add_option("--screenshot", view.screenshotPath,
                            "With --exit-after-frames: write the last frame to this PNG first");
    viewCommand->add_option("--slow-frames", view.slowFrame_ms,
                            "For tests: end every frame with a wait this long, as on a slow machine")
        ->type_name("MS")
        ->check(wholeNumberIn(0, 60000));
    viewCommand->add_flag("--log-input", view.logInput,
                          "For tests: print on stderr what the panel saw pressed each frame (Enter, Esc, clicks)");
    addOutputOptions(*viewCommand, view.outputSettings);
    viewCommand->add_option_function<std::string>(
                   "--temporal",
                   [&view](const std::string& value) {
                       view.temporal = value == "on"    ? swell::app::viewer::TemporalMode::Always
                                       : value == "off" ? swell::app::viewer::TemporalMode::Off
                                                        : swell::app::viewer::TemporalMode::WhileStill;
                   },
                   "Temporal resolve: each frame jittered and blended into the history at the window's full "
                   "resolution, in place of the scene's antialiasing: auto (the default) while the camera rests, "
                   "on always, off never")
        ->type_name("auto|on|off")
        ->check(CLI::IsMember({"auto", "on", "off"}));
    CLI::Option* frameTarget = viewCommand->add_option(
                   "--frame-target", view.frameTarget_ms,
                   "Dynamic resolution: the render scale follows the frame time towards this, ms; 0 keeps the "
                   "scale fixed (default 150, or 0 when --scale is given)")
        ->type_name("MS")
        ->check(numberIn(0.0, 10000.0));

    swell::app::RenderOptions render;
    std::string renderSize = "1280x720";
    double duration = -1.0;
    CLI::App* renderCommand = app.add_subcommand("render", "Render headless to a PNG, an image sequence or an MP4");
    renderCommand->add_option("scene", render.scenePath,
                              kSceneHelp)
        ->type_name("SCENE");
    renderCommand->add_option("-o,--output", render.output,
                              "Output: NAME.png for one frame; with --duration, NAME.png becomes NAME_00000.png, "
                              "NAME_00001.png, ... or NAME.mp4 a video (needs the ffmpeg program). "
                              "Missing parent folders are created")
        ->type_name("FILE")
        ->required();
    renderCommand->add_option("--size", renderSize, "Image size, WIDTHxHEIGHT")->type_name("WxH")->capture_default_str();
    renderCommand->add_option("--time", render.time_s, "Simulation time of the first frame, seconds")
        ->type_name("SECONDS")
        ->check(numberIn(0.0, swell::kMaxFrameTime_s))
        ->capture_default_str();
    renderCommand->add_option("--duration", duration, "Render a sequence this many seconds long")
        ->type_name("SECONDS")
        ->check(numberIn(0.0, 3600.0));
    renderCommand->add_option("--fps", render.fps, "Frames per second of a sequence")
        ->type_name("FPS")
        ->check(numberIn(1.0, 240.0))
        ->capture_default_str();
    renderCommand->add_flag("--labels", render.labels,
                            "Also write each frame's ground truth beside its PNG: NAME.range.npy, NAME.normal.npy, "
                            "NAME.semantic.npy, NAME.instance.npy, NAME.depth.npy, NAME.labels.png, NAME.amodal.npy, "
                            "NAME.kitti.txt, NAME.kitti_calib.txt and NAME.json, and its optical flow to the next "
                            "frame (one --fps interval on): NAME.flow.npy and NAME.flow_valid.npy (docs/LABELS.md)");
    addOutputOptions(*renderCommand, render.outputSettings);

    swell::app::BenchOptions bench;
    std::string benchSize = "1280x720";
    CLI::App* benchCommand = app.add_subcommand("bench", "Benchmark a scene (the default one unless named) headless along a fixed camera path");
    benchCommand->add_option("--size", benchSize, "Frame size, WIDTHxHEIGHT")->type_name("WxH")->capture_default_str();
    benchCommand->add_option("--frames", bench.frames, "Measured frames along the camera path")
        ->type_name("N")
        ->check(wholeNumberIn(1, 100000))
        ->capture_default_str();
    benchCommand->add_option("--warmup", bench.warmup, "Frames rendered first and not measured")
        ->type_name("N")
        ->check(wholeNumberIn(0, 100000))
        ->capture_default_str();
    benchCommand->add_option("--json", bench.jsonPath, "Also write the results as JSON to this file")->type_name("FILE");
    benchCommand->add_flag("--terms", bench.terms,
                           fmt::format("Also measure what the water's shading terms and its reflection lookups cost "
                                       "(each term left out in turn, then each lookup: {} renders a measured frame "
                                       "instead of 1)",
                                       swell::app::benchRendersPerFrameWithTerms()));
    benchCommand->add_flag("--stages", bench.stages,
                           "Also time each stage of the wave model's GPU work inside the ocean pass (a glFinish "
                           "around each, which adds to the pass's time)");
    benchCommand->add_flag("--labels", bench.labels,
                           "Also draw the label pass after each frame, its arrays read back, as `swell dataset` "
                           "draws a labelled sample, and the optical flow from the frame before's labels: its own "
                           "rows (labels, frame + labels, flow) beside the frame, with the same counters");
    benchCommand->add_flag("--sensor", bench.sensor,
                           "Also draw each frame through the scene camera's sensor as `swell render` does (its lens, "
                           "and with camera.shutter_s or readout_s its motion_samples draws): its own row (sensor)");
    benchCommand->add_flag("--motion-vectors", bench.motionVectors,
                           "Also draw each frame into a host's framebuffer (Renderer::draw with Swell's world and sky) "
                           "with motion vectors for a TAA (DrawOptions::motionVectors): their pass's own row "
                           "(motion vectors) and their draws and triangles");
    addOutputOptions(*benchCommand, bench.outputSettings);
    benchCommand->add_flag("--still", bench.still,
                           "Every frame from the scene's own camera (the view `swell view` opens on), not the path");
    benchCommand->add_flag("--temporal", bench.temporal,
                           "Draw with the temporal resolve, as `swell view` does (in place of the antialiasing)");
    benchCommand->add_flag("--interactive", bench.interactive,
                           "Draw as `swell view` does: no frame replays the foam's history, and on a software "
                           "rasteriser the spectral fields come from the CPU's FFTs");
    benchCommand->add_flag("--water-one-pass", bench.waterOnePass,
                           "Draw the water in one pass, its grid shaded in its own fragments, instead of a "
                           "visibility pass and one shading run per water pixel (to compare the two)");
    benchCommand->add_option("scene", bench.scenePath,
                             "Scene file (TOML) or a preset's name, benchmarked along the same camera path; "
                             "the built-in default when omitted")
        ->type_name("SCENE");

    swell::app::DatasetOptions dataset;
    CLI::App* datasetCommand =
        app.add_subcommand("dataset", "Render a sweep's labelled samples into a folder (docs/DATASETS.md); "
                                      "started again, it renders only the samples not done yet");
    datasetCommand->add_option("sweep", dataset.sweepPath, "Sweep file (TOML): a base scene and what varies")
        ->type_name("SWEEP")
        ->required();
    datasetCommand->add_option("--out", dataset.out, "The dataset's folder (created when missing)")
        ->type_name("DIR")
        ->required();
    datasetCommand->add_option("--shard", dataset.shard,
                               "Render only part K of N: the samples i with i % N == K - 1 (one part per machine)")
        ->type_name("K/N")
        ->capture_default_str();
    datasetCommand->add_flag("--dry-run", dataset.dryRun,
                             "Check the sweep, its scene and the folder, write the manifest and say what this shard "
                             "would render; render nothing");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        if (argc > 1 && app.get_subcommands().empty())
            suggestSubcommand(app, argv[1]);
        return swell::kExitBadInput;
    }
    try {
        // A scene named by a path that does not exist may be a preset's name.
        const std::filesystem::path presets = swell::app::dataFolders().scenes;
        if (*viewCommand) {
            parseSize(viewSize, view.width, view.height);
            // A scale asked for is kept, unless a frame target is asked for too.
            if (viewCommand->get_option("--scale")->count() > 0 && frameTarget->count() == 0)
                view.frameTarget_ms = 0.0;
            view.scenePath = swell::app::resolveScenePath(view.scenePath, presets);
            return swell::app::runView(view);
        }
        if (*renderCommand) {
            parseSize(renderSize, render.width, render.height);
            render.scenePath = swell::app::resolveScenePath(render.scenePath, presets);
            if (duration >= 0.0)
                render.duration_s = duration;
            return swell::app::runRender(render);
        }
        if (*datasetCommand) {
            dataset.presets = presets;
            return swell::app::runDataset(dataset);
        }
        if (*benchCommand) {
            parseSize(benchSize, bench.width, bench.height);
            bench.scenePath = swell::app::resolveScenePath(bench.scenePath, presets);
            return swell::app::runBench(bench);
        }
        // No subcommand: the main job. Which path it takes is said on
        // stderr, so that scripts/run.sh's user knows what to look for.
        if (swell::app::displayAvailable()) {
            std::fprintf(stderr, "swell: showing the default scene in a window (Esc quits, F1 the panel)\n");
            return swell::app::runView(view);
        }
        render.output = "swell-default.png";
        std::fprintf(stderr, "swell: no usable display (DISPLAY and WAYLAND_DISPLAY unset, or no X server there): "
                             "rendering the default scene headless to %s\n",
                     std::filesystem::absolute(render.output).c_str());
        return swell::app::runRender(render);
    } catch (const CLI::ParseError& e) { // parseSize's checks
        app.exit(e);
        return swell::kExitBadInput;
    } catch (const swell::InputError& e) {
        std::fprintf(stderr, "swell: error: %s\n", e.what());
        return swell::kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "swell: error: %s\n", e.what());
        return swell::kExitFailure;
    }
}
