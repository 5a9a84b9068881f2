// Scene files (swell/scene/scene_file.h). Loading runs in four steps, each of which
// throws InputError at the first problem it finds:
//   1. size, text and structure: the text is small enough, is UTF-8 without
//      NUL bytes, and its keys and nesting are shallow enough for the TOML
//      parser's recursion;
//   2. TOML syntax (toml++);
//   3. reading: every key is known, every value has the right type and range
//      (keys and ranges come from the parameter table, swell/scene/parameters.h),
//      and the place of each key is remembered;
//   4. checking the scene as a whole: cross-field rules, referenced files,
//      the wave set. validateScene() runs this step alone.
//
// Step 1 is scene/text_scan.cpp, 3 scene/reader.cpp (with suggestions.cpp),
// 4 scene/checks.cpp; saving is scene/writer.cpp and scene/atomic_save.cpp.
#include "swell/scene/scene_file.h"

#include "core/input_file.h"
#include "scene/checks.h"
#include "scene/places.h"
#include "scene/reader.h"
#include "scene/toml_text.h"
#include "swell/error.h"
#include "swell/scene/scene_changes.h"

#include <fmt/format.h>

#include <toml++/toml.h>

namespace swell {

namespace fs = std::filesystem;
using namespace detail::scenefile;
using detail::readInputFile;

Scene parseScene(std::string_view text, const fs::path& virtualPath)
{
    Places places(virtualPath.string());
    if (text.size() > kMaxSceneFileBytes)
        fail({places.path(), 0, 0}, fmt::format("the scene is {} bytes; scene files are at most {} bytes (4 MiB)",
                                                text.size(), kMaxSceneFileBytes));
    const toml::table root = parseTomlText(text, places);

    Scene scene = readScene(root, places);
    checkScene(scene, places, baseFolder(virtualPath));
    scene.assetFolder = baseFolder(virtualPath).string();
    scene.keyPlaces = places.all();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string key = fmt::format("objects[{}].path", i);
        scene.assetReferences.push_back({key, scene.objects[i].path, places.at(key)});
    }
    for (std::size_t i = 0; i < scene.sky.cubemapFaces.size(); ++i) {
        const std::string key = fmt::format("sky.faces[{}]", i);
        scene.assetReferences.push_back({key, scene.sky.cubemapFaces[i], places.at(key)});
    }
    return scene;
}

Scene loadScene(const fs::path& path)
{
    std::string text;
    try {
        text = readInputFile(path, kMaxSceneFileBytes, "scene file");
    } catch (const InputError& e) {
        // The folder case in the scene's own words; the rest as the reader says it.
        std::error_code ec;
        if (fs::is_directory(path, ec))
            fail(e.place(), "is a folder, not a scene file");
        throw;
    }
    return parseScene(text, path);
}

void validateScene(const Scene& scene, const fs::path& sceneFile)
{
    checkScene(scene, Places(sceneFile.string(), scene.keyPlaces), baseFolder(sceneFile));
}

void validateSceneChange(const Scene& before, const Scene& after, const fs::path& sceneFile)
{
    checkScene(after, Places(sceneFile.string(), after.keyPlaces), baseFolder(sceneFile), sceneChanges(before, after));
}

} // namespace swell
