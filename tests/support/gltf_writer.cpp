#include "support/gltf_writer.h"

#include "support/base64.h"

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace swell::test {

namespace {


template <class T>
void appendRaw(std::vector<std::uint8_t>& out, const T& value)
{
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

} // namespace

void writeGltf(const detail::MeshData& mesh, const std::filesystem::path& path)
{
    writeGltf(std::vector<GltfNode>{{"", mesh}}, path);
}

void writeGltf(const std::vector<GltfNode>& nodes, const std::filesystem::path& path)
{
    using nlohmann::json;
    // Per node: positions, normals, colours (each n * 12 bytes), then indices.
    std::vector<std::uint8_t> buffer;
    json views = json::array(), accessors = json::array(), meshes = json::array(), nodeList = json::array(),
         roots = json::array();
    for (const GltfNode& node : nodes) {
        const detail::MeshData& mesh = node.mesh;
        const std::size_t start = buffer.size();
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const detail::MeshVertex& v : mesh.vertices) {
            appendRaw(buffer, v.position);
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        for (const detail::MeshVertex& v : mesh.vertices)
            appendRaw(buffer, v.normal);
        for (const detail::MeshVertex& v : mesh.vertices)
            appendRaw(buffer, v.color);
        for (std::uint32_t i : mesh.indices)
            appendRaw(buffer, i);
        const std::size_t n = mesh.vertices.size(), attribute = n * 12;
        const std::size_t view0 = views.size(), accessor0 = accessors.size();
        for (std::size_t a = 0; a < 3; ++a)
            views.push_back({{"buffer", 0}, {"byteOffset", start + a * attribute}, {"byteLength", attribute}});
        views.push_back({{"buffer", 0}, {"byteOffset", start + 3 * attribute}, {"byteLength", mesh.indices.size() * 4}});
        for (std::size_t a = 0; a < 3; ++a) {
            json accessor{{"bufferView", view0 + a}, {"componentType", 5126}, {"count", n}, {"type", "VEC3"}};
            if (a == 0) {
                accessor["min"] = {lo.x, lo.y, lo.z};
                accessor["max"] = {hi.x, hi.y, hi.z};
            }
            accessors.push_back(accessor);
        }
        accessors.push_back(
            {{"bufferView", view0 + 3}, {"componentType", 5125}, {"count", mesh.indices.size()}, {"type", "SCALAR"}});
        meshes.push_back({{"primitives",
                           {{{"attributes", {{"POSITION", accessor0}, {"NORMAL", accessor0 + 1}, {"COLOR_0", accessor0 + 2}}},
                             {"indices", accessor0 + 3}}}}});
        json entry{{"mesh", meshes.size() - 1}};
        if (!node.name.empty())
            entry["name"] = node.name;
        roots.push_back(nodeList.size());
        nodeList.push_back(entry);
    }
    const json gltf{
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", roots}}}},
        {"nodes", nodeList},
        {"meshes", meshes},
        {"buffers", {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
        {"bufferViews", views},
        {"accessors", accessors},
    };
    std::ofstream(path) << gltf.dump(1);
}

detail::MeshData makeBox(float halfSize_m, glm::vec3 color)
{
    detail::MeshData mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            // Two tangents with u x v = n, so the triangles wind counter-clockwise seen from outside.
            glm::vec3 u(0.0f), v(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            const auto base = std::uint32_t(mesh.vertices.size());
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                mesh.vertices.push_back({(n + u * c.x + v * c.y) * halfSize_m, n, color});
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    return mesh;
}

} // namespace swell::test
