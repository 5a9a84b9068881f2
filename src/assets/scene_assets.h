// Every file a Scene names, read and checked on the CPU: its models (glTF
// files and the built-ins) and its sky faces. The renderer uploads what this
// returns and reads no file itself.
#pragma once

#include "assets/mesh_data.h"
#include "swell/image.h"
#include "swell/scene/scene.h"

#include <memory>
#include <vector>

namespace swell::detail {

struct ObjectAssets {
    // The model, shared by every object that names the same file (read once).
    std::shared_ptr<const MeshData> mesh;
    // The closed volume of an open hull: a built-in's (makeBuiltinHullVolume),
    // or the glTF node the scene names in SceneObject::hullNode; empty for
    // models without one.
    std::shared_ptr<const MeshData> hullVolume;
    // The farthest any vertex lies from the model's origin, m (unscaled).
    double reach_m = 0.0;
};

struct SceneAssets {
    std::vector<ObjectAssets> objects; // one per Scene::objects entry, in order
    std::vector<Image> skyFaces;       // none, or six square images of one size (+x, -x, +y, -y, +z, -z)
};

// Reads the models and sky faces `scene` names. Relative paths start at
// Scene::assetFolder (the working directory when it is empty); when the
// folder is set, every path must lie inside it, links included, as the scene
// file's own checks require. Throws InputError at the scene key that named
// the broken file, "scene.toml:LINE:COL: objects[2].path: FILE: problem",
// when the scene records where the key was (Scene::assetReferences); else at
// the file itself, "FILE: objects[2].path: problem".
SceneAssets loadSceneAssets(const Scene& scene);

// The closed shapes a scene's floating rigid bodies are built from (CPU
// data, model space), apart from what the GPU draws: per scene object, its
// hull volume when it has one, else its model.
struct SceneShapes {
    std::vector<std::shared_ptr<const MeshData>> objects; // one per Scene::objects entry, in order

    SceneShapes() = default;
    explicit SceneShapes(const SceneAssets& assets);
    // The shapes as SceneBodies takes them (owned here), in order.
    std::vector<const MeshData*> list() const;
};

} // namespace swell::detail
