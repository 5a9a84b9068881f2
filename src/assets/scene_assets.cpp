// Loading the files a scene names (scene_assets.h).
#include "assets/scene_assets.h"

#include "assets/fleet_mesh.h"
#include "core/asset_path.h"
#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace swell::detail {

namespace fs = std::filesystem;

namespace {

class AssetReader {
public:
    explicit AssetReader(const Scene& scene) : scene_(scene)
    {
        if (!scene.assetFolder.empty())
            resolvedFolder_ = resolvedFolder(scene.assetFolder);
    }

    // Runs `load` on the file `path` names; an InputError from it is
    // reported at the scene key `key` (see loadSceneAssets).
    template <class Load>
    auto read(const std::string& key, const std::string& path, Load load)
    {
        const fs::path file = fileOf(key, path);
        try {
            return load(file);
        } catch (const InputError& e) {
            fail(key, path, e.place(), e.message());
        }
    }

    // The problem `message`, found in `file` (named by `key` as `path`), at the scene key.
    [[noreturn]] void fail(const std::string& key, const std::string& path, const SourcePlace& file,
                           const std::string& message) const
    {
        for (const AssetReference& r : scene_.assetReferences)
            if (r.key == key && r.path == path)
                throw InputError(r.place, fmt::format("{}: {}: {}", key, file.str(), message));
        throw InputError(file, fmt::format("{}: {}", key, message));
    }

    // The file a scene path names: relative to the asset folder, and inside it when it is set.
    fs::path fileOf(const std::string& key, const std::string& path) const
    {
        const fs::path p(path);
        if (scene_.assetFolder.empty())
            return p;
        const fs::path file = p.is_absolute() ? p : fs::path(scene_.assetFolder) / p;
        if (!resolveInside(resolvedFolder_, p))
            fail(key, path, {file.string()},
                 fmt::format("lies outside the scene's folder '{}'; a scene may name only files in its folder or "
                             "below it, links included",
                             scene_.assetFolder));
        return file;
    }

private:
    const Scene& scene_;
    fs::path resolvedFolder_;
};

double reachOf(const MeshData& mesh)
{
    double reach = 0.0;
    for (const MeshVertex& v : mesh.vertices)
        reach = std::max(reach, double(glm::length(v.position)));
    return reach;
}

} // namespace

SceneAssets loadSceneAssets(const Scene& scene)
{
    AssetReader reader(scene);
    SceneAssets assets;

    // Models: each distinct path read once, however many objects place it.
    std::map<std::string, ObjectAssets> byPath;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string& path = scene.objects[i].path;
        const std::string& hullNode = scene.objects[i].hullNode;
        const std::string key = fmt::format("objects[{}].path", i);
        // The same file with another hull node is another model, and so is
        // one of the fleet in another look.
        const std::optional<FleetLook> look =
            isFleetPath(path) ? std::optional<FleetLook>(fleetLookOf(scene.objects[i])) : std::nullopt;
        const std::string shared = path + '\0' + hullNode + (look ? '\0' + fleetLookKey(*look) : std::string());
        auto found = byPath.find(shared);
        if (found == byPath.end()) {
            ObjectAssets object;
            if (look) {
                GltfModel model = makeFleetModel(path.substr(kBuiltinObjectPrefix.size()), *look);
                object.mesh = std::make_shared<const MeshData>(std::move(model.mesh));
                object.hullVolume = std::make_shared<const MeshData>(std::move(model.hull));
            } else if (path.starts_with(kBuiltinObjectPrefix)) {
                const std::string name = path.substr(kBuiltinObjectPrefix.size());
                object.mesh = std::make_shared<const MeshData>(makeBuiltinModel(name));
                if (object.mesh->vertices.empty())
                    reader.fail(key, path, {path}, "not a built-in model");
                object.hullVolume = std::make_shared<const MeshData>(makeBuiltinHullVolume(name));
            } else if (hullNode.empty()) {
                object.mesh = reader.read(key, path, [](const fs::path& file) {
                    return std::make_shared<const MeshData>(loadGltf(file));
                });
                object.hullVolume = std::make_shared<const MeshData>();
            } else {
                GltfModel model = reader.read(key, path, [&](const fs::path& file) { return loadGltf(file, hullNode); });
                object.mesh = std::make_shared<const MeshData>(std::move(model.mesh));
                object.hullVolume = std::make_shared<const MeshData>(std::move(model.hull));
            }
            object.reach_m = std::max(reachOf(*object.mesh), reachOf(*object.hullVolume));
            found = byPath.emplace(shared, std::move(object)).first;
        }
        assets.objects.push_back(found->second);
    }

    // Sky faces: square, all of the first one's size.
    for (std::size_t i = 0; i < scene.sky.cubemapFaces.size(); ++i) {
        const std::string& path = scene.sky.cubemapFaces[i];
        const std::string key = fmt::format("sky.faces[{}]", i);
        Image face = reader.read(key, path, [](const fs::path& file) { return readImage(file); });
        const int first = assets.skyFaces.empty() ? face.width : assets.skyFaces.front().width;
        if (face.width != face.height || face.width != first)
            reader.fail(key, path, {reader.fileOf(key, path).string()},
                        fmt::format("sky cubemap face is {}x{}; faces must be square and all the size of the first "
                                    "({}x{})",
                                    face.width, face.height, first, first));
        assets.skyFaces.push_back(std::move(face));
    }
    return assets;
}

SceneShapes::SceneShapes(const SceneAssets& assets)
{
    for (const ObjectAssets& o : assets.objects)
        objects.push_back(o.hullVolume->indices.empty() ? o.mesh : o.hullVolume);
}

std::vector<const MeshData*> SceneShapes::list() const
{
    std::vector<const MeshData*> shapes;
    for (const std::shared_ptr<const MeshData>& shape : objects)
        shapes.push_back(shape.get());
    return shapes;
}

} // namespace swell::detail
