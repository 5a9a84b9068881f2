#include "scene_loading.h"

#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <vector>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

// The presets' names (file names without .toml), sorted.
std::vector<std::string> presetNames(const fs::path& presets)
{
    std::vector<std::string> names;
    std::error_code error;
    for (fs::directory_iterator it(presets, error), end; !error && it != end; it.increment(error))
        if (it->path().extension() == ".toml")
            names.push_back(it->path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

std::string resolveScenePath(const std::string& argument, const fs::path& presets)
{
    // Anything there (a dangling link, a FIFO too) is the user's, for the
    // scene reader to take or refuse with its own reason; so is any path
    // with a folder in it: only a bare name ("storm", "storm.toml") can be a
    // preset's.
    std::error_code error;
    const fs::path name = argument;
    if (argument.empty() || fs::exists(fs::symlink_status(name, error)) || name.has_parent_path())
        return argument;
    const fs::path preset = presets / (name.extension() == ".toml" ? name : fs::path(argument + ".toml"));
    if (fs::is_regular_file(preset, error))
        return preset.string();
    const std::vector<std::string> names = presetNames(presets);
    throw InputError({argument},
                     names.empty() ? fmt::format("no such scene file, and no presets in '{}'", presets.string())
                                   : fmt::format("no such scene file, and no preset of that name; the presets (in '{}') "
                                                 "are: {}",
                                                 presets.string(), fmt::join(names, ", ")));
}

Scene loadSceneOrDefault(const std::string& path)
{
    Scene scene = path.empty() ? defaultScene() : loadScene(path);
    // Waves whose crests would loop over themselves are made gentler when
    // rendered; say so, naming the waves, rather than change them silently.
    WaveSet waves = resolveWaves(scene);
    if (const std::string warning = limitSteepness(waves); !warning.empty())
        std::fprintf(stderr, "swell: warning: %s: %s\n", path.empty() ? "default scene" : path.c_str(), warning.c_str());
    return scene;
}


void checkSteppedHistory(const Scene& scene, double time_s, std::string_view where)
{
    // Floating bodies are stepped from their start (history_start_s, by
    // default 60 s before t = 0) at 1/120 s (docs/BODIES.md): an hour of
    // steps is about a minute of CPU per body, so a first frame much later
    // would look like a hang. Their wake steps too, at 1/30 s and about 5 ms
    // a step (docs/PERFORMANCE.md): 10 minutes of it is a minute and a half.
    // The limits hold the time stepped, from the start to the frame: with
    // the default start, a frame after 3600 s (600 s with a wake).
    constexpr double kLongestBodyHistory_s = 3600.0 + kDevelopedHistory_s;
    constexpr double kLongestWakeHistory_s = 600.0 + kDevelopedHistory_s;
    const bool bodies = std::any_of(scene.objects.begin(), scene.objects.end(),
                                    [](const SceneObject& o) { return o.isRigidBody(); });
    const bool wake = scene.wake.enabled && std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
                          return o.isRigidBody() && (o.velocity_m_per_s.x != 0.0 || o.velocity_m_per_s.z != 0.0);
                      });
    const double stepped_s = time_s - bodiesStart_s(scene);
    if (bodies && stepped_s > kLongestBodyHistory_s)
        throw InputError({std::string(where)}, fmt::format("{} s: the scene's floating bodies are stepped from their start at {} s, "
                                                 "so a first frame more than {} s after it is refused",
                                                 time_s, bodiesStart_s(scene), kLongestBodyHistory_s));
    if (wake && stepped_s > kLongestWakeHistory_s)
        throw InputError({std::string(where)}, fmt::format("{} s: the wake of the scene's bodies under way is stepped from their "
                                                 "start at {} s, so a first frame more than {} s after it is refused "
                                                 "(or set wake.enabled = false)",
                                                 time_s, bodiesStart_s(scene), kLongestWakeHistory_s));
}

} // namespace swell::app
