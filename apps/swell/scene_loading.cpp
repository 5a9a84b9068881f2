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

} // namespace swell::app
