// Writes a mesh as a small glTF 2.0 file (one buffer embedded as a data URI;
// POSITION, NORMAL and COLOR_0 as float VEC3, u32 indices), so tests can place
// a model of known shape and colour through a scene file.
#pragma once

#include "assets/mesh_data.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swell::test {

void writeGltf(const detail::MeshData& mesh, const std::filesystem::path& path);

// Several meshes, each the mesh of one root node with this name (none when empty).
struct GltfNode {
    std::string name;
    detail::MeshData mesh;
};
void writeGltf(const std::vector<GltfNode>& nodes, const std::filesystem::path& path);

// An axis-aligned box centred on the origin, half-size halfSize_m, one flat
// colour (linear RGB), with outward normals.
detail::MeshData makeBox(float halfSize_m, glm::vec3 color);

} // namespace swell::test
