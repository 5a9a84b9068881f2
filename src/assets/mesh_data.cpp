// Procedural built-in models and the island heightfield.
#include "assets/mesh_data.h"

#include "assets/fleet_mesh.h"
#include "assets/island_terrain.h"

#include "embedded_files.h"
#include "swell/error.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <array>
#include <cmath>
#include <map>

namespace swell::detail {

void addTriangleNormals(MeshData& mesh)
{
    for (MeshVertex& v : mesh.vertices)
        v.normal = glm::vec3(0.0f);
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        MeshVertex& a = mesh.vertices[mesh.indices[i]];
        MeshVertex& b = mesh.vertices[mesh.indices[i + 1]];
        MeshVertex& c = mesh.vertices[mesh.indices[i + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        a.normal += n;
        b.normal += n;
        c.normal += n;
    }
    for (MeshVertex& v : mesh.vertices)
        v.normal = glm::length(v.normal) > 0.0f ? glm::normalize(v.normal) : glm::vec3(0, 1, 0);
}

namespace {

// Vertices that share a place share one normal: a lathe repeats its first
// column at its seam and its ends at the poles, and normals averaged on each
// side apart would draw a crease there.
// Places are compared at 0.1 mm: the seam's sin(2 pi) is not exactly 0.
void weldNormals(MeshData& mesh)
{
    const auto place = [](const glm::vec3& p) {
        return std::array<long, 3>{std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f)};
    };
    std::map<std::array<long, 3>, glm::vec3> sums;
    for (const MeshVertex& v : mesh.vertices)
        sums[place(v.position)] += v.normal;
    for (MeshVertex& v : mesh.vertices) {
        const glm::vec3 n = sums[place(v.position)];
        v.normal = glm::length(n) > 0.0f ? glm::normalize(n) : v.normal;
    }
}

// A surface of revolution about +y: profile points (radius, height), each ring
// coloured by colorAt(height). Closed with caps at both ends.
template <class ColorAt>
void addLathe(MeshData& mesh, const std::vector<glm::vec2>& profile, int segments, ColorAt colorAt)
{
    const auto base = std::uint32_t(mesh.vertices.size());
    for (const glm::vec2& p : profile)
        for (int s = 0; s <= segments; ++s) {
            const float a = float(s) / float(segments) * glm::two_pi<float>();
            mesh.vertices.push_back({{p.x * std::cos(a), p.y, p.x * std::sin(a)}, {}, colorAt(p.y)});
        }
    const auto ring = std::uint32_t(segments + 1);
    for (std::uint32_t r = 0; r + 1 < profile.size(); ++r)
        for (std::uint32_t s = 0; s < std::uint32_t(segments); ++s) {
            const std::uint32_t a = base + r * ring + s, b = a + 1, c = a + ring, d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
}

// The built-in boat: assets/models/boat.gltf (make_models.py writes it),
// compiled in and read once by the glTF loader, its node "hull" the closed
// hull volume. One model, whether a scene names builtin:boat or the file.
const GltfModel& builtinBoat()
{
    static const GltfModel boat = [] {
        for (const EmbeddedFile& file : embeddedModelFiles())
            if (file.path == "boat.gltf")
                return loadEmbeddedGltf("builtin:boat", file.text, "hull");
        throw Error("builtin:boat: the library was built without assets/models/boat.gltf");
    }();
    return boat;
}

} // namespace

MeshData makeIsland(double size_m, double peak_m, int resolution)
{
    MeshData mesh;
    const int n = resolution;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = (double(i) / n - 0.5) * size_m, z = (double(j) / n - 0.5) * size_m;
            const double h = islandHeight_m({x, z}, size_m, peak_m);
            glm::vec3 color;
            if (h < -1.0)
                color = {0.55f, 0.50f, 0.38f}; // wet sand under water
            else if (h < 2.5)
                color = {0.80f, 0.73f, 0.55f}; // beach
            else if (h < peak_m * 0.55)
                color = {0.22f, 0.36f, 0.14f}; // vegetation
            else
                color = {0.42f, 0.40f, 0.37f}; // rock
            mesh.vertices.push_back({{float(x), float(h), float(z)}, {}, color});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    addTriangleNormals(mesh);
    return mesh;
}

MeshData makeBuiltinModel(const std::string& name)
{
    MeshData mesh;
    if (name == "buoy") {
        // A 2.4 m navigation buoy: red and white bands, a float below the waterline.
        const std::vector<glm::vec2> profile{{0.0f, -1.2f}, {0.9f, -1.0f}, {1.0f, -0.2f}, {0.9f, 0.3f},
                                             {0.35f, 0.5f}, {0.3f, 2.0f}, {0.45f, 2.1f}, {0.0f, 2.4f}};
        addLathe(mesh, profile, 24, [](float y) {
            return (y > 0.9f && y < 1.5f) || y > 2.05f ? glm::vec3(0.9f, 0.9f, 0.85f) : glm::vec3(0.75f, 0.06f, 0.04f);
        });
    } else if (name == "rock") {
        // A weathered boulder, 6 m across: a lumpy dome that stands in the
        // water, closed underneath so that it is a solid (a body's shape).
        // The relief is the noise's first two octaves, both coarser than the
        // mesh (ring and segment spacing about 0.5 m against features of
        // 1.4 and 0.7 m), so it is drawn as curved surfaces: with five
        // octaves on 20 segments the default scene's rock, 24 m across at
        // 150 m, read as a cut gem. Kept mostly convex (a relief of +-20% of
        // the radius), as the lights on objects cast no shadow on their own
        // body: a deep fold on the side away from the sun would catch it.
        // 1280 triangles: the default frame draws it in three passes.
        constexpr int kRings = 14, kSegments = 40;
        std::vector<glm::vec2> profile{{0.0f, -4.0f}};
        for (int i = 0; i <= kRings; ++i) {
            const float t = float(i) / float(kRings);
            profile.push_back({3.0f * std::sqrt(std::max(0.0f, 1.0f - t * t)) + 0.01f, -4.0f + 7.0f * t});
        }
        profile.push_back({0.0f, 3.05f});
        addLathe(mesh, profile, kSegments, [](float) { return glm::vec3(0.36f, 0.34f, 0.31f); });
        for (MeshVertex& v : mesh.vertices) {
            const float bump =
                float(fractalNoise(v.position.x * 0.7 + 11.0, v.position.z * 0.7 + v.position.y * 0.5, 2));
            v.position *= 1.0f + 0.55f * bump;
        }
        addTriangleNormals(mesh);
        weldNormals(mesh);
        return mesh;
    } else if (name == "boat") {
        // A 7 m motor workboat, normals and all from its file.
        return builtinBoat().mesh;
    } else if (isFleetPath(std::string(kBuiltinObjectPrefix) + name)) {
        // One of the fleet at its design size and paint (assets/fleet_mesh.h).
        return makeFleetModel(name).mesh;
    }
    addTriangleNormals(mesh);
    return mesh;
}

MeshData makeBuiltinHullVolume(const std::string& name)
{
    // The boat's outer skin from the keel to the sheer, closed by its flat
    // transom and a lid at the sheer: the skin coincides with the drawn
    // hull's, so the lid is the only part that can change the depth buffer.
    if (name == "boat")
        return builtinBoat().hull;
    if (isFleetPath(std::string(kBuiltinObjectPrefix) + name))
        return makeFleetModel(name).hull;
    return {};
}

} // namespace swell::detail
