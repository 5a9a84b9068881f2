// CPU triangle meshes of world geometry: built-in procedural models, the
// island heightfield, and glTF files. render/mesh.h uploads them.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace swell::detail {

struct MeshVertex {
    glm::vec3 position{}; // object space, m
    glm::vec3 normal{};
    glm::vec3 color{};    // linear RGB albedo
};

struct MeshData {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices; // triangles
};

// Sets each vertex's normal to the mean of its triangles' (area-weighted).
void addTriangleNormals(MeshData& mesh);

// The built-in island: a heightfield of side size_m centred on the origin,
// peak_m above the water, sloping into shallows and then deep water.
MeshData makeIsland(double size_m, double peak_m, int resolution);

// Built-in models by name ("buoy", "boat", "rock", and the fleet's at their
// design look, swell::kFleetObjects); empty data for unknown names.
MeshData makeBuiltinModel(const std::string& name);

// The closed volume a built-in model's open hull encloses, from the keel up to
// the sheer ("boat": the node "hull" of assets/models/boat.gltf; the fleet's
// likewise, of assets/models/fleet/NAME.gltf); empty for
// models with no open hull. The renderer draws
// it into depth only before the water, so no water shows inside the hull.
MeshData makeBuiltinHullVolume(const std::string& name);

// Loads every mesh of a glTF 2.0 file (.gltf or .glb) into one MeshData, with
// node transforms applied. Throws swell::InputError naming the file and problem.
MeshData loadGltf(const std::filesystem::path& path);

// A glTF model with a declared hull (SceneObject::hullNode): the primitives
// under the node named hullNode (it and its children), in model space, are
// the closed hull volume and are left out of the drawn mesh. Throws
// swell::InputError when no node has that name or it has no triangles.
struct GltfModel {
    MeshData mesh;
    MeshData hull;
};
GltfModel loadGltf(const std::filesystem::path& path, std::string_view hullNode);

// The same from a .gltf's text held in memory (a model compiled into the
// library), named `name` in messages; its buffers must be data: URIs.
GltfModel loadEmbeddedGltf(std::string_view name, std::string_view text, std::string_view hullNode);

} // namespace swell::detail
