// loadGltf, what loads: the project's models, and node transforms and vertex
// formats on small files written here. The files it must refuse, with an
// InputError naming the file and the problem and never a crash, are in
// test_gltf_loader_errors.cpp; the file-writing helpers both use are in
// gltf_test_files.h.
#include "gltf_test_files.h"

#include "assets/mesh_data.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

namespace {

namespace fs = std::filesystem;
using swell::detail::loadGltf;
using swell::detail::MeshData;
using namespace swell::test::gltf_files;

const fs::path kModels = fs::path(SWELL_SOURCE_DIR) / "assets" / "models";

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
};

Bounds boundsOf(const MeshData& mesh)
{
    Bounds b;
    for (const auto& v : mesh.vertices) {
        b.lo = glm::min(b.lo, v.position);
        b.hi = glm::max(b.hi, v.position);
    }
    return b;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const char* what)
{
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " component " << i;
}

// Indices in range, whole triangles, unit normals, and each triangle wound
// counter-clockwise seen from the side its vertex normals point to.
void expectWellFormed(const MeshData& mesh)
{
    ASSERT_FALSE(mesh.indices.empty());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (std::uint32_t i : mesh.indices)
        ASSERT_LT(i, mesh.vertices.size());
    for (const auto& v : mesh.vertices)
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    std::size_t agree = 0, faces = 0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const auto& a = mesh.vertices[mesh.indices[t]];
        const auto& b = mesh.vertices[mesh.indices[t + 1]];
        const auto& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::length(n) < 1e-8f)
            continue;
        ++faces;
        agree += glm::dot(n, a.normal + b.normal + c.normal) > 0.0f;
    }
    EXPECT_EQ(agree, faces) << "triangles wound against their normals";
}

// ---------------------------------------------------------------------------
// The project's models.

TEST(GltfLoader, LighthouseLoads)
{
    const MeshData mesh = loadGltf(kModels / "lighthouse.gltf");
    expectWellFormed(mesh);
    // Counts of the generated model (assets/models/make_models.py).
    EXPECT_EQ(mesh.vertices.size(), 696u);
    EXPECT_EQ(mesh.indices.size(), 3u * 616u);

    // About 20 m tall with its origin at the centre of its base.
    const Bounds b = boundsOf(mesh);
    EXPECT_NEAR(b.lo.y, 0.0f, 1e-4f);
    EXPECT_NEAR(b.hi.y, 20.0f, 1e-4f);
    for (int axis : {0, 2}) {
        EXPECT_GT(b.hi[axis], 4.0f);
        EXPECT_LT(b.hi[axis], 6.0f);
        EXPECT_LT(b.lo[axis], -4.0f);
        EXPECT_GT(b.lo[axis], -6.0f);
    }

    // Grey rock at the bottom, a white tower, a red top.
    const auto colorAt = [&](float y) {
        for (const auto& v : mesh.vertices)
            if (std::abs(v.position.y - y) < 0.01f)
                return v.color;
        return glm::vec3(-1.0f);
    };
    expectNear(colorAt(0.0f), {0.30f, 0.28f, 0.26f}, 1e-4f, "rock");
    expectNear(colorAt(9.0f), {0.85f, 0.85f, 0.82f}, 1e-4f, "tower");
    expectNear(colorAt(20.0f), {0.60f, 0.04f, 0.03f}, 1e-4f, "roof");
    for (const auto& v : mesh.vertices)
        if (v.position.y > 2.5f && v.position.y < 14.9f) {
            EXPECT_GT(v.color.r, 0.8f);
            EXPECT_GT(v.color.b, 0.8f);
        }
}

TEST(GltfLoader, CrateLoads)
{
    const MeshData mesh = loadGltf(kModels / "crate.glb");
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertices.size(), 384u);
    EXPECT_EQ(mesh.indices.size(), 3u * 192u);

    // A 1 m cube centred on the origin.
    const Bounds b = boundsOf(mesh);
    expectNear(b.lo, glm::vec3(-0.5f), 1e-5f, "crate min");
    expectNear(b.hi, glm::vec3(0.5f), 1e-5f, "crate max");

    // Wood: every colour brown, from COLOR_0 bytes (no material).
    for (const auto& v : mesh.vertices) {
        EXPECT_GT(v.color.r, v.color.g);
        EXPECT_GT(v.color.g, v.color.b);
        EXPECT_GT(v.color.r, 0.2f);
        EXPECT_LT(v.color.r, 0.5f);
    }
    // No NORMAL in the file: computed, and flat on each face of the box.
    for (const auto& v : mesh.vertices) {
        const glm::vec3 a = glm::abs(v.normal);
        EXPECT_NEAR(std::max({a.x, a.y, a.z}), 1.0f, 1e-5f);
    }
}

// ---------------------------------------------------------------------------
// Transforms and vertex formats, on small files written here.

TEST(GltfLoader, NodeTransformsCompose)
{
    // Parent: scale 2 then move 10 along x; child: up 5 (in the parent's frame).
    Model m = triangle();
    m.doc["nodes"] = {{{"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}, {"children", {1}}},
                      {{"translation", {0, 5, 0}}, {"mesh", 0}}};
    const MeshData mesh = loadGltf(writeGltf("transform_trs.gltf", m));
    expectWellFormed(mesh);
    const Bounds b = boundsOf(mesh);
    expectNear(b.lo, {10, 10, 0}, 1e-5f, "min");
    expectNear(b.hi, {12, 12, 0}, 1e-5f, "max");
}

TEST(GltfLoader, NodeMatrixAndRotation)
{
    // Node 0: a column-major matrix translating by (1, 2, 3). Node 1: 90 degrees about +y.
    Model m = triangle();
    m.doc["nodes"] = {{{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1}}, {"mesh", 0}},
                      {{"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}, {"mesh", 0}}};
    m.doc["scenes"] = {{{"nodes", {0, 1}}}};
    const MeshData mesh = loadGltf(writeGltf("transform_matrix.gltf", m));
    expectWellFormed(mesh);
    ASSERT_EQ(mesh.vertices.size(), 6u);
    expectNear(mesh.vertices[1].position, {2, 2, 3}, 1e-5f, "translated (1,0,0)");
    // +x turns to -z, and the +z face normal to +x.
    expectNear(mesh.vertices[4].position, {0, 0, -1}, 1e-5f, "rotated (1,0,0)");
    expectNear(mesh.vertices[4].normal, {1, 0, 0}, 1e-5f, "rotated normal");
}

TEST(GltfLoader, MirroringKeepsFacesOutward)
{
    // A negative scale flips winding; the loader turns triangles back so that
    // the winding still agrees with the (given) normals.
    Model m = triangle();
    append<float>(m.bin, {0, 0, 1, 0, 0, 1, 0, 0, 1});
    m.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 36}});
    m.doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    m.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    m.doc["nodes"][0]["scale"] = {-1, 1, 1};
    const MeshData mesh = loadGltf(writeGltf("mirrored.gltf", m));
    expectWellFormed(mesh);
    expectNear(mesh.vertices[0].normal, {0, 0, 1}, 1e-6f, "mirrored normal");
    EXPECT_NEAR(boundsOf(mesh).lo.x, -1.0f, 1e-6f);
}

TEST(GltfLoader, NoScenesDrawsAllRootNodesAndDefaultColour)
{
    Model m = triangle();
    m.doc.erase("scene");
    m.doc.erase("scenes");
    m.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 0, 5}}}};
    const MeshData mesh = loadGltf(writeGltf("no_scenes.gltf", m));
    EXPECT_EQ(mesh.vertices.size(), 6u);
    EXPECT_NEAR(boundsOf(mesh).hi.z, 5.0f, 1e-6f);
    // No material: light grey. No normals: computed, facing +z.
    expectNear(mesh.vertices[0].color, glm::vec3(0.8f), 1e-6f, "default colour");
    expectNear(mesh.vertices[0].normal, {0, 0, 1}, 1e-6f, "computed normal");
}

TEST(GltfLoader, NonIndexedStripsFansAndByteIndices)
{
    // A unit quad as four vertices: drawn as a strip, a fan (via u8 indices),
    // and as a non-indexed triangle list; plus a points primitive that is skipped.
    Model m;
    append<float>(m.bin, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}); // strip order
    append<std::uint8_t>(m.bin, {0, 1, 3, 2});                  // fan order
    append<float>(m.bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0});
    m.doc = {
        {"asset", {{"version", "2.0"}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}}}, {"mode", 5}},
             {{"attributes", {{"POSITION", 0}}}, {"mode", 6}, {"indices", 1}},
             {{"attributes", {{"POSITION", 2}}}},
             {{"attributes", {{"POSITION", 0}}}, {"mode", 0}}}}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}},
                         {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 4}},
                         {{"buffer", 0}, {"byteOffset", 52}, {"byteLength", 72}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                       {{"bufferView", 1}, {"componentType", 5121}, {"count", 4}, {"type", "SCALAR"}},
                       {{"bufferView", 2}, {"componentType", 5126}, {"count", 6}, {"type", "VEC3"}}}},
    };
    const MeshData mesh = loadGltf(writeGltf("strips_fans.gltf", m));
    EXPECT_EQ(mesh.vertices.size(), 4u + 4u + 6u);
    EXPECT_EQ(mesh.indices.size(), 3u * 6u);
    expectWellFormed(mesh);
    for (const auto& v : mesh.vertices)
        expectNear(v.normal, {0, 0, 1}, 1e-6f, "quad normal");
}

TEST(GltfLoader, InterleavedNormalsAndColours)
{
    // Position and normal interleaved (byteStride 24); COLOR_0 as normalised
    // u16 VEC3 multiplied by the material's base colour.
    Model m;
    for (int i = 0; i < 3; ++i) {
        const float x = i == 1 ? 1.0f : 0.0f, y = i == 2 ? 1.0f : 0.0f;
        append<float>(m.bin, {x, y, 0, 0, 0, 1});
    }
    append<std::uint16_t>(m.bin, {65535, 32768, 0, 65535, 32768, 0, 65535, 32768, 0});
    pad4(m.bin);
    m.doc = {
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1.0, 1.0, 1.0}}}}}}},
        {"meshes",
         {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"COLOR_0", 2}}}, {"material", 0}}}}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", 72}, {"byteStride", 24}},
                         {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 18}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 0}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5123}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}}}},
    };
    const MeshData mesh = loadGltf(writeGlb("interleaved.glb", m));
    expectWellFormed(mesh);
    expectNear(mesh.vertices[1].position, {1, 0, 0}, 0, "second position");
    expectNear(mesh.vertices[2].normal, {0, 0, 1}, 0, "normal");
    expectNear(mesh.vertices[0].color, {0.5f, 32768.0f / 65535.0f, 0.0f}, 1e-6f, "colour");
}

TEST(GltfLoader, SparseAccessorAndExternalBuffer)
{
    // Positions start as the triangle; a sparse substitution moves vertex 2 to
    // (0,3,0). The buffer is a .bin file beside the model.
    Model m = triangle();
    append<std::uint8_t>(m.bin, {2, 0, 0, 0});
    append<float>(m.bin, {0, 3, 0});
    m.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 1}});
    m.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
    m.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 2}, {"componentType", 5121}}},
                                       {"values", {{"bufferView", 3}}}};
    m.doc["accessors"][0]["max"] = {1, 3, 0};
    writeBytes("sparse.bin", m.bin);
    m.doc["buffers"] = {{{"byteLength", m.bin.size()}, {"uri", "sparse.bin"}}};
    const MeshData mesh = loadGltf(writeGltf("sparse.gltf", m));
    expectWellFormed(mesh);
    expectNear(mesh.vertices[2].position, {0, 3, 0}, 0, "substituted vertex");
}

} // namespace
