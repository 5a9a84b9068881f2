// loadGltf, what is refused: hostile files (missing, garbage, truncated,
// reading past their buffers, bad indices, non-finite values, absurd counts,
// bad buffers, node graphs and meshes, deep nesting) that must fail with an
// InputError naming the file and the problem, never crash; the documented
// index count, which loads and one more which does not; and the fuzzer's
// corpus. What loads is in test_gltf_loader.cpp; the file-writing helpers
// both use are in gltf_test_files.h.
#include "gltf_test_files.h"

#include "assets/mesh_data.h"
#include "support/base64.h"

#include "swell/error.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

namespace {

namespace fs = std::filesystem;
using swell::InputError;
using swell::detail::loadGltf;
using swell::detail::MeshData;
using swell::test::base64;
using namespace swell::test::gltf_files;

const fs::path kCorpus = fs::path(SWELL_SOURCE_DIR) / "fuzz" / "corpus" / "gltf";

// Loading `path` must throw InputError whose message has the path and `phrase`.
void expectError(const fs::path& path, const std::string& phrase)
{
    SCOPED_TRACE(path.string());
    try {
        loadGltf(path);
        ADD_FAILURE() << "loaded without error; expected one containing \"" << phrase << "\"";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
        EXPECT_NE(what.find(phrase), std::string::npos) << "\"" << what << "\" lacks \"" << phrase << "\"";
    }
}

// ---------------------------------------------------------------------------
// Hostile files. Each must give an InputError naming the file and the problem.

TEST(GltfLoader, RejectsMissingFilesDirectoriesAndEmptyFiles)
{
    expectError(outputDir() / "does_not_exist.gltf", "file does not exist");
    fs::create_directories(outputDir() / "folder.gltf");
    expectError(outputDir() / "folder.gltf", "is a directory");
    expectError(writeText("empty.glb", ""), "file is empty");
}

TEST(GltfLoader, RejectsGarbage)
{
    Bytes garbage;
    for (std::uint32_t i = 0, x = 12345; i < 600; ++i) {
        x = x * 1103515245u + 12345u;
        garbage.push_back(std::uint8_t(x >> 16));
    }
    expectError(writeBytes("garbage.gltf", garbage), "not valid JSON");
    expectError(writeBytes("garbage.glb", garbage), "does not start with the 'glTF' magic");
    expectError(writeText("not_gltf.gltf", "[1, 2, 3]"), "JSON top level is not an object");
    expectError(writeText("no_asset.gltf", "{\"meshes\": []}"), "'asset' object is missing");
    expectError(writeText("old_version.gltf", R"({"asset": {"version": "1.0"}})"), "unsupported glTF version '1.0'");
}

TEST(GltfLoader, RejectsTruncatedFiles)
{
    // A valid .glb cut short, and a .gltf cut in the middle of its JSON (the
    // error then carries the line and column).
    const Bytes whole = glbBytes(triangle().doc.dump(), triangle().bin);
    expectError(writeBytes("truncated.glb", Bytes(whole.begin(), whole.begin() + long(whole.size() / 2))),
                "truncated binary glTF: the header says");
    expectError(writeBytes("header_only.glb", Bytes(whole.begin(), whole.begin() + 8)),
                "truncated binary glTF: 8 bytes is shorter than the 12-byte header");

    Bytes chunkTooLong = whole;
    chunkTooLong[12] = 0xff; // the JSON chunk's length
    expectError(writeBytes("chunk_too_long.glb", chunkTooLong), "chunk 0 claims");

    Bytes version1 = whole;
    version1[4] = 1;
    expectError(writeBytes("version1.glb", version1), "unsupported binary glTF version 1");

    const std::string text = triangle().doc.dump(1);
    const fs::path cut = writeText("truncated.gltf", text.substr(0, text.size() / 2));
    expectError(cut, "not valid JSON");
    try {
        loadGltf(cut);
    } catch (const InputError& e) {
        EXPECT_GT(e.place().line, 1);
        EXPECT_GT(e.place().column, 0);
    }
}

TEST(GltfLoader, RejectsReadsPastTheEnd)
{
    // An accessor that claims more elements than its bufferView holds.
    Model m = triangle();
    m.doc["accessors"][0]["count"] = 400;
    expectError(writeGltf("accessor_past_view.gltf", m),
                "accessor 0 (mesh 0 primitive 0 POSITION) reads past the end of bufferView 0 (needs 4800 bytes, has 36)");

    // A bufferView longer than its buffer.
    m = triangle();
    m.doc["bufferViews"][0]["byteLength"] = 4800;
    expectError(writeGlb("view_past_buffer.glb", m), "bufferView 0 reads past the end of buffer 0 (needs 4800 bytes, has 44)");

    // Offsets that overflow when added: byteOffset near 2^53 and a huge stride * count.
    m = triangle();
    m.doc["accessors"][0]["byteOffset"] = 9007199254740991ull;
    expectError(writeGltf("offset_overflow.gltf", m), "reads past the end of bufferView 0");
    m = triangle();
    m.doc["accessors"][0]["byteOffset"] = 18446744073709551615ull;
    expectError(writeGltf("offset_2_64.gltf", m), "accessors[0].byteOffset must be an integer from 0 to");
    m = triangle();
    m.doc["bufferViews"][0]["byteStride"] = 252;
    m.doc["accessors"][0]["count"] = 1900000;
    expectError(writeGltf("stride_overflow.gltf", m), "reads past the end of bufferView 0 (needs 478799760 bytes");
    m = triangle();
    m.doc["bufferViews"][0]["byteStride"] = 4;
    expectError(writeGltf("stride_too_small.gltf", m), "bufferView 0 has byteStride 4");
    m = triangle();
    m.doc["accessors"][0]["byteOffset"] = -4;
    expectError(writeGltf("negative_offset.gltf", m), "accessors[0].byteOffset must be an integer from 0 to");
}

TEST(GltfLoader, RejectsBadIndices)
{
    Model m = triangle();
    m.bin[40] = 7; // third index
    expectError(writeGltf("index_out_of_range.gltf", m), "mesh 0 primitive 0 index 2 is 7, but there are only 3 vertices");

    m = triangle();
    m.doc["accessors"][1]["count"] = 2;
    expectError(writeGltf("index_count.gltf", m), "has 2 indices, not a multiple of 3");

    m = triangle();
    m.doc["accessors"][1]["componentType"] = 5126;
    expectError(writeGltf("float_indices.gltf", m), "must be SCALAR unsigned byte, short or int");

    m = triangle();
    m.doc["meshes"][0]["primitives"][0]["indices"] = 9;
    expectError(writeGltf("missing_index_accessor.gltf", m), "invalid glTF");
}

TEST(GltfLoader, RejectsNonFiniteValues)
{
    Model m = triangle();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&m.bin[16], &nan, 4); // vertex 1, y
    expectError(writeGltf("nan_position.gltf", m), "POSITION) has a non-finite value in element 1");

    m = triangle();
    const float inf = std::numeric_limits<float>::infinity();
    std::memcpy(&m.bin[0], &inf, 4);
    expectError(writeGlb("inf_position.glb", m), "has a non-finite value in element 0");

    // Finite values and transforms that overflow together.
    m = triangle();
    m.doc["nodes"] = {{{"scale", {1e30, 1e30, 1e30}}, {"children", {1}}}, {{"scale", {1e30, 1, 1}}, {"mesh", 0}}};
    expectError(writeGltf("overflowing_transform.gltf", m), "to a non-finite position");

    expectError(writeText("huge_number.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"translation": [1e999, 0, 0]}]})"),
                "number overflow");
    m = triangle();
    m.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectError(writeGltf("zero_rotation.gltf", m), "node 0 has a rotation quaternion of length 0");
    m = triangle();
    m.doc["nodes"][0]["matrix"] = {1, 0, 0};
    expectError(writeGltf("short_matrix.gltf", m), "node 0 has a matrix of 3 numbers (needs 16)");
}

TEST(GltfLoader, RejectsAbsurdCounts)
{
    // No bufferView means zeros: a tiny file that would allocate gigabytes.
    Model m = triangle();
    m.doc["accessors"][0].erase("bufferView");
    m.doc["accessors"][0]["count"] = 20000000;
    expectError(writeGltf("absurd_count.gltf", m), "model has 20000000 vertices, more than the limit of 2000000");

    // Many instances of a mesh that is small on its own.
    m = triangle();
    m.doc["accessors"][0].erase("bufferView");
    m.doc["accessors"][0]["count"] = 1200000;
    m.doc["meshes"][0]["primitives"][0].erase("indices");
    m.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}}};
    m.doc["scenes"] = {{{"nodes", {0, 1}}}};
    expectError(writeGltf("too_many_vertices.gltf", m), "model has 2400000 vertices, more than the limit of 2000000");
}

// docs/SCENE.md allows 6,000,000 indices a model: one index accessor may
// hold them all (it was once capped at the 2,000,000 vertices' limit), and
// one more is refused.
TEST(GltfLoader, AcceptsTheDocumentedIndexCountInOneAccessor)
{
    // The triangle, its three indices repeated as 32-bit: 24 MB in a .glb.
    auto model = [](std::uint32_t count) {
        Model m = triangle();
        m.bin.resize(36);
        for (std::uint32_t i = 0; i < count; ++i)
            append<std::uint32_t>(m.bin, {i % 3});
        m.doc["bufferViews"][1] = {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 4 * std::size_t(count)}};
        m.doc["accessors"][1] = {{"bufferView", 1}, {"componentType", 5125}, {"count", count}, {"type", "SCALAR"}};
        return m;
    };
    const MeshData mesh = loadGltf(writeGlb("six_million_indices.glb", model(6000000)));
    EXPECT_EQ(mesh.indices.size(), 6000000u);
    expectError(writeGlb("too_many_indices.glb", model(6000003)), "more than the limit of 6000000");
}

TEST(GltfLoader, RejectsBadBuffers)
{
    Model m = triangle();
    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "missing.bin"}}};
    expectError(writeGltf("missing_bin.gltf", m), "buffer 0's file 'missing.bin' was not found beside the model");

    writeBytes("short.bin", Bytes(20, 0));
    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "short.bin"}}};
    expectError(writeGltf("short_bin.gltf", m), "buffer 0's file 'short.bin' has 20 bytes but its byteLength is 44");

    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "/etc/passwd"}}};
    expectError(writeGltf("absolute_uri.gltf", m), "only relative file paths are supported");
    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "https://example.com/a.bin"}}};
    expectError(writeGltf("remote_uri.gltf", m), "only relative file paths are supported");

    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "data:text/html;base64,AAAA"}}};
    expectError(writeGltf("data_uri_type.gltf", m), "unsupported data URI");
    m.doc["buffers"] = {{{"byteLength", 44}, {"uri", "data:application/octet-stream;base64,AA!A"}}};
    expectError(writeGltf("data_uri_base64.gltf", m), "data URI that is not valid base64");
    m.doc["buffers"] = {{{"byteLength", 44},
                         {"uri", "data:application/octet-stream;base64," + base64(Bytes(40, 0))}}};
    expectError(writeGltf("data_uri_short.gltf", m), "buffer 0's data URI holds 40 bytes but its byteLength is 44");
    m.doc["buffers"] = {{{"byteLength", 0}, {"uri", "data:application/octet-stream;base64,"}}};
    expectError(writeGltf("empty_buffer.gltf", m), "buffer 0 has byteLength 0");
    m.doc["buffers"] = {{{"uri", "data:application/octet-stream;base64,"}}};
    expectError(writeGltf("no_byte_length.gltf", m), "buffer 0 has no byteLength");

    // .glb: a buffer claiming more than the BIN chunk holds, and a .glb without BIN.
    m = triangle();
    m.doc["buffers"] = {{{"byteLength", 4400}}};
    expectError(writeGlb("bin_too_short.glb", m), "buffer 0 claims 4400 bytes but the BIN chunk holds only 44");
    m.doc["buffers"] = {{{"byteLength", 44}}};
    expectError(writeBytes("no_bin.glb", glbBytes(m.doc.dump(), m.bin, false)),
                "buffer 0 has no uri and the file has no BIN chunk");
}

TEST(GltfLoader, RejectsBadNodeGraphs)
{
    Model m = triangle();
    // Nodes 1 and 2 are each other's child, unreachable from the scene but not allowed.
    m.doc["nodes"] = {{{"mesh", 0}}, {{"children", {2}}}, {{"children", {1}}}};
    expectError(writeGltf("cycle.gltf", m), "node graph has a cycle through node 1");

    m.doc["nodes"] = {{{"mesh", 0}, {"children", {0}}}};
    expectError(writeGltf("self_child.gltf", m), "node 0 is its own child");

    // A diamond would draw node 2 twice; a chain of them grows exponentially.
    m.doc["nodes"] = {{{"children", {1, 2}}}, {{"children", {2}}}, {{"mesh", 0}}};
    expectError(writeGltf("two_parents.gltf", m), "node 2 has more than one parent");

    m.doc["nodes"] = {{{"mesh", 5}}};
    expectError(writeGltf("missing_mesh.gltf", m), "node 0 refers to mesh 5, which does not exist");
    m.doc["nodes"] = {{{"mesh", 0}, {"children", {4}}}};
    expectError(writeGltf("missing_child.gltf", m), "node 0 has child 4, which does not exist");

    m = triangle();
    m.doc["scene"] = 3;
    expectError(writeGltf("missing_scene.gltf", m), "scene 3 does not exist");
    m = triangle();
    m.doc["scenes"] = {{{"nodes", {0, 0}}}};
    expectError(writeGltf("scene_twice.gltf", m), "scene 0 lists node 0 twice");
}

TEST(GltfLoader, RejectsUnusableMeshes)
{
    Model m = triangle();
    m.doc["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
    expectError(writeGltf("no_position.gltf", m), "mesh 0 primitive 0 has no POSITION attribute");

    m = triangle();
    m.doc["accessors"][0]["componentType"] = 5123;
    expectError(writeGltf("short_positions.gltf", m), "POSITION) must be float VEC3");

    m = triangle();
    m.doc["meshes"][0]["primitives"][0]["mode"] = 0;
    expectError(writeGltf("points_only.gltf", m), "model has no triangles to draw");
    m.doc["meshes"][0]["primitives"][0]["mode"] = 9;
    expectError(writeGltf("bad_mode.gltf", m), "mesh 0 primitive 0 has unknown mode 9");

    m = triangle();
    m.doc["meshes"][0]["primitives"][0]["material"] = 2;
    expectError(writeGltf("missing_material.gltf", m), "refers to material 2, which does not exist");

    m = triangle();
    m.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectError(writeGltf("draco.gltf", m), "requires extension KHR_draco_mesh_compression, which is not supported");

    m = triangle();
    m.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                                       {"values", {{"bufferView", 0}}}};
    m.bin[36] = 9; // the first index, used as the sparse index
    expectError(writeGltf("sparse_out_of_range.gltf", m), "sparse index 9 is out of range");
}

TEST(GltfLoader, RejectsDeepNesting)
{
    std::string deep = R"({"asset": {"version": "2.0"}, "extras": )";
    deep += std::string(100000, '[') + std::string(100000, ']') + "}";
    expectError(writeText("deep.gltf", deep), "nested more than 64 levels deep");
}

// The fuzzer's seed corpus, fuzz/corpus/gltf: valid_* files load, invalid_*
// files fail; anything else there is an input the fuzzer found (crash-*, ...),
// which must load or fail cleanly.
TEST(GltfLoader, FuzzCorpus)
{
    int valid = 0, invalid = 0;
    for (const auto& entry : fs::directory_iterator(kCorpus)) {
        const std::string name = entry.path().filename().string();
        if (name == "buffer.bin")
            continue; // the external buffer valid_external.gltf uses
        SCOPED_TRACE(entry.path().string());
        try {
            const MeshData mesh = loadGltf(entry.path());
            EXPECT_FALSE(name.starts_with("invalid_")) << "loaded without error";
            valid += name.starts_with("valid_");
            EXPECT_FALSE(mesh.indices.empty());
        } catch (const InputError& e) {
            EXPECT_FALSE(name.starts_with("valid_")) << e.what();
            invalid += name.starts_with("invalid_");
            EXPECT_NE(std::string(e.what()).find(entry.path().string()), std::string::npos) << e.what();
        }
    }
    EXPECT_GE(valid, 5);
    EXPECT_GE(invalid, 4);
}

} // namespace
