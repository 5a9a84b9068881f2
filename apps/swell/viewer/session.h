// What the viewer shows: the scene (always one the renderer accepted), the
// file it came from, and the renderer drawing it. Edits, scene files and
// shader reloads go through here; a bad one leaves the last good state in
// place and keeps its message for the panel instead of stopping the viewer.
#pragma once

#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <filesystem>
#include <memory>
#include <string>

namespace swell::app::viewer {

// A line for the panel; error lines show in red.
struct Message {
    std::string text;
    bool error = false;
};

// Where hot reload reads shaders: the shaders/ folder and the folder that
// holds swell/gpu/*.h (the repository's include/).
struct ShaderFolders {
    std::filesystem::path shaders;
    std::filesystem::path include;
};

class Session {
public:
    // Needs a current OpenGL 4.5 context. sceneFile: where `scene` was loaded
    // from, empty for the built-in default. Throws swell::InputError when the
    // renderer cannot start on the scene.
    Session(Scene scene, std::filesystem::path sceneFile, ShaderFolders shaderFolders);

    Renderer& renderer() { return *renderer_; }
    const Scene& scene() const { return scene_; }
    // Empty for the built-in default scene.
    const std::filesystem::path& sceneFile() const { return sceneFile_; }

    // Makes `edited` the scene: validateScene() against the scene file's
    // folder, then Renderer::setScene(). On swell::InputError the renderer
    // goes back to the last good scene and the message is kept in
    // editMessage(). Returns whether the edit was taken.
    bool apply(const Scene& edited);
    // A value the panel refused before it reached apply().
    void refuseEdit(std::string message) { edit_ = {std::move(message), true}; }
    const Message& editMessage() const { return edit_; }
    void clearEditMessage() { edit_ = {}; }

    // Replaces the scene by the file's (loadScene). On failure nothing changes.
    bool load(const std::filesystem::path& file);
    // Writes `scene` (normally scene(), perhaps with the current view as its
    // camera) to `file` after checking that its relative paths still resolve
    // from that folder.
    bool save(const Scene& scene, const std::filesystem::path& file);
    const Message& fileMessage() const { return file_; }

    // Rebuilds the renderer with shaders read afresh from the folders. On a
    // compile error the old renderer, with its programs, stays.
    bool reloadShaders();
    bool shadersFromDisk() const { return shadersFromDisk_; }
    const ShaderFolders& shaderFolders() const { return shaderFolders_; }
    const Message& shaderMessage() const { return shader_; }

private:
    // Puts the renderer back on scene_ after a setScene() that threw.
    void restoreRenderer();

    Scene scene_;
    std::filesystem::path sceneFile_;
    ShaderFolders shaderFolders_;
    std::unique_ptr<Renderer> renderer_;
    bool shadersFromDisk_ = false;
    Message edit_, file_, shader_;
};

} // namespace swell::app::viewer
