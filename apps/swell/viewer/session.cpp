// Scene edits, scene files and shader reloads, each kept or refused whole.
#include "viewer/session.h"

#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

namespace swell::app::viewer {

namespace fs = std::filesystem;

namespace {

// The scene file named for validation and error places; a scene that came
// from no file resolves relative paths from the working directory.
fs::path validationPath(const fs::path& sceneFile) { return sceneFile.empty() ? fs::path("untitled.toml") : sceneFile; }

std::string absoluteText(const fs::path& path)
{
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).string();
}

} // namespace

Session::Session(Scene scene, fs::path sceneFile, ShaderFolders shaderFolders)
    : scene_(std::move(scene)), sceneFile_(std::move(sceneFile)), shaderFolders_(std::move(shaderFolders)),
      renderer_(std::make_unique<Renderer>(scene_))
{
}

void Session::restoreRenderer()
{
    // scene_ was accepted before, so this only fails if the GPU side did;
    // that is not an input problem and ends the viewer.
    renderer_->setScene(scene_);
}

bool Session::apply(const Scene& edited)
{
    try {
        // Only what the edit can affect: a slider tick reads no files.
        validateSceneChange(scene_, edited, validationPath(sceneFile_));
        renderer_->setScene(edited);
    } catch (const InputError& e) {
        // The place is the scene file with no line; the message names the key.
        edit_ = {e.message(), true};
        restoreRenderer();
        return false;
    }
    scene_ = edited;
    edit_ = {};
    return true;
}

bool Session::load(const fs::path& file)
{
    try {
        Scene loaded = loadScene(file);
        renderer_->setScene(loaded);
        scene_ = std::move(loaded);
    } catch (const InputError& e) {
        file_ = {e.what(), true};
        restoreRenderer();
        return false;
    }
    sceneFile_ = file;
    edit_ = {};
    file_ = {"Loaded " + absoluteText(file)};
    return true;
}

bool Session::save(const Scene& scene, const fs::path& file)
{
    if (file.empty()) {
        file_ = {"Type a path to save to", true};
        return false;
    }
    try {
        validateScene(scene, file);
        saveSceneFile(scene, file);
    } catch (const InputError& e) {
        file_ = {e.what(), true};
        return false;
    }
    file_ = {"Saved " + absoluteText(file)};
    return true;
}

bool Session::reloadShaders()
{
    // A fresh ShaderSources reads every file again; the renderer's own
    // sources keep the text they read first, so reloadShaders() on the
    // running renderer would compile the old text. A new renderer on the
    // same scene replaces the old one only once it has compiled.
    try {
        RendererOptions options;
        options.shaders = gl::ShaderSources::fromDirectory(shaderFolders_.shaders, shaderFolders_.include);
        auto fresh = std::make_unique<Renderer>(scene_, std::move(options));
        renderer_ = std::move(fresh);
    } catch (const InputError& e) {
        shader_ = {e.what(), true};
        return false;
    }
    shadersFromDisk_ = true;
    shader_ = {fmt::format("Reloaded from {}", shaderFolders_.shaders.string())};
    return true;
}

} // namespace swell::app::viewer
