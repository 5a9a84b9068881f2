// swell: view an ocean in a window, render it headless, or benchmark it.
// With no subcommand it shows the default scene in a window when a display is
// usable, and otherwise renders it to a PNG whose path it prints.
#include "commands.h"
#include "data_folders.h"

#include "swell/error.h"
#include "swell/parameters.h"
#include "swell/renderer.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw CLI::ValidationError("--size", "each side must be 1..16384 pixels, got '" + text + "'");
}

// Range checks let NaN through (every comparison with it is false).
const CLI::Validator finiteNumber(
    [](std::string& text) {
        try {
            return std::isfinite(std::stod(text)) ? std::string() : "must be a finite number, got '" + text + "'";
        } catch (const std::exception&) {
            return "must be a number, got '" + text + "'";
        }
    },
    "FINITE");

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
        ->check(CLI::IsMember(names));
    command.add_option("--scale", settings.renderScale,
                       fmt::format("Render the frame at this fraction of the output size and scale it up (filtered), "
                                   "{}..{}", swell::kMinRenderScale, swell::kMaxRenderScale))
        ->check(finiteNumber & CLI::Range(swell::kMinRenderScale, swell::kMaxRenderScale))
        ->capture_default_str();
}

} // namespace

int main(int argc, char** argv)
{
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
    viewCommand->add_option("scene", view.scenePath, "Scene file (TOML); the built-in default when omitted");
    viewCommand->add_option("--size", viewSize, "Window size, WIDTHxHEIGHT")->capture_default_str();
    viewCommand->add_option("--exit-after-frames", view.exitAfterFrames,
                            "Quit after this many frames (for tests and scripts)")->check(CLI::Range(0, 1000000));
    viewCommand->add_option("--time-step", view.scriptedStep_s,
                            "With --exit-after-frames: simulation time each frame advances, seconds (default 1/60; "
                            "longer steps stand for slow frames)")
        ->check(CLI::Range(0.0, 60.0));
    viewCommand->add_option("--screenshot", view.screenshotPath,
                            "With --exit-after-frames: write the last frame to this PNG first");
    addOutputOptions(*viewCommand, view.outputSettings);

    swell::app::RenderOptions render;
    std::string renderSize = "1280x720";
    double duration = -1.0;
    CLI::App* renderCommand = app.add_subcommand("render", "Render headless to a PNG, an image sequence or an MP4");
    renderCommand->add_option("scene", render.scenePath, "Scene file (TOML); the built-in default when omitted");
    renderCommand->add_option("-o,--output", render.output,
                              "Output: NAME.png for one frame; with --duration, NAME.png becomes NAME_00000.png, "
                              "NAME_00001.png, ... or NAME.mp4 a video (needs the ffmpeg program). "
                              "Missing parent folders are created")->required();
    renderCommand->add_option("--size", renderSize, "Image size, WIDTHxHEIGHT")->capture_default_str();
    renderCommand->add_option("--time", render.time_s, "Simulation time of the first frame, seconds")
        ->check(finiteNumber & CLI::Range(0.0, 1.0e9))->capture_default_str();
    renderCommand->add_option("--duration", duration, "Render a sequence this many seconds long")
        ->check(finiteNumber & CLI::Range(0.0, 3600.0));
    renderCommand->add_option("--fps", render.fps, "Frames per second of a sequence")
        ->check(finiteNumber & CLI::Range(1.0, 240.0))->capture_default_str();
    addOutputOptions(*renderCommand, render.outputSettings);

    swell::app::BenchOptions bench;
    std::string benchSize = "1280x720";
    CLI::App* benchCommand = app.add_subcommand("bench", "Benchmark a scene (the default one unless named) headless along a fixed camera path");
    benchCommand->add_option("--size", benchSize, "Frame size, WIDTHxHEIGHT")->capture_default_str();
    benchCommand->add_option("--frames", bench.frames, "Measured frames")->check(CLI::Range(1, 100000))->capture_default_str();
    benchCommand->add_option("--warmup", bench.warmup, "Frames rendered first and not measured")
        ->check(CLI::Range(0, 100000))->capture_default_str();
    benchCommand->add_option("--json", bench.jsonPath, "Also write the results as JSON to this file");
    bool noTerms = false;
    benchCommand->add_flag("--no-terms", noTerms,
                           "Skip the water shading terms' costs (each term left out in turn: 8 renders a frame instead of 1)");
    addOutputOptions(*benchCommand, bench.outputSettings);
    benchCommand->add_flag("--still", bench.still,
                           "Every frame from the scene's own camera (the view `swell view` opens on), not the path");
    benchCommand->add_option("scene", bench.scenePath,
                             "Scene file (TOML) to benchmark along the same camera path; the built-in default when omitted");

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
        return swell::kExitBadInput;
    }
    try {
        if (*viewCommand) {
            parseSize(viewSize, view.width, view.height);
            return swell::app::runView(view);
        }
        if (*renderCommand) {
            parseSize(renderSize, render.width, render.height);
            if (duration >= 0.0)
                render.duration_s = duration;
            return swell::app::runRender(render);
        }
        if (*benchCommand) {
            parseSize(benchSize, bench.width, bench.height);
            bench.terms = !noTerms;
            return swell::app::runBench(bench);
        }
        // No subcommand: the main job.
        if (swell::app::displayAvailable())
            return swell::app::runView(view);
        render.output = "swell-default.png";
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
