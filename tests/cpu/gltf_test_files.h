// What the glTF loader's tests share (test_gltf_loader.cpp, what loads;
// test_gltf_loader_errors.cpp, what is refused): small .gltf and .glb files
// written under the test output folder from a JSON document and the bytes of
// its buffer, starting from one triangle that a test then changes.
#pragma once

#include "support/base64.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

namespace swell::test::gltf_files {

using json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

inline std::filesystem::path outputDir()
{
    const std::filesystem::path dir = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "gltf";
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::filesystem::path writeBytes(const std::string& name, const Bytes& bytes)
{
    const std::filesystem::path path = outputDir() / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

inline std::filesystem::path writeText(const std::string& name, const std::string& text)
{
    return writeBytes(name, Bytes(text.begin(), text.end()));
}

// The values' bytes as this machine stores them (little-endian here, as glTF
// requires), at the end of out.
template <class T>
void append(Bytes& out, std::initializer_list<T> values)
{
    for (T v : values) {
        const std::size_t at = out.size();
        out.resize(at + sizeof(T));
        std::memcpy(out.data() + at, &v, sizeof(T));
    }
}

inline void pad4(Bytes& out)
{
    while (out.size() % 4)
        out.push_back(0);
}

// A glTF document and the bytes of its buffer 0.
struct Model {
    json doc;
    Bytes bin;
};

// .gltf with buffer 0 as a data: URI, unless the document sets its own buffers.
inline std::filesystem::path writeGltf(const std::string& name, Model m)
{
    if (!m.doc.contains("buffers"))
        m.doc["buffers"] = json::array(
            {{{"byteLength", m.bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(m.bin)}}});
    return writeText(name, m.doc.dump(1));
}

inline Bytes glbBytes(const std::string& jsonText, Bytes bin, bool withBin = true)
{
    Bytes text(jsonText.begin(), jsonText.end());
    while (text.size() % 4)
        text.push_back(' ');
    pad4(bin);
    Bytes out;
    const auto total = std::uint32_t(12 + 8 + text.size() + (withBin ? 8 + bin.size() : 0));
    append<std::uint32_t>(out, {0x46546C67, 2, total, std::uint32_t(text.size()), 0x4E4F534A});
    out.insert(out.end(), text.begin(), text.end());
    if (withBin) {
        append<std::uint32_t>(out, {std::uint32_t(bin.size()), 0x004E4942});
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

// .glb with buffer 0 in the BIN chunk, unless the document sets its own buffers.
inline std::filesystem::path writeGlb(const std::string& name, Model m)
{
    if (!m.doc.contains("buffers"))
        m.doc["buffers"] = json::array({{{"byteLength", m.bin.size()}}});
    return writeBytes(name, glbBytes(m.doc.dump(), m.bin));
}

// One triangle, (0,0,0) (1,0,0) (0,1,0), facing +z: accessor 0 POSITION
// (bufferView 0, bytes 0..35), accessor 1 u16 indices (bufferView 1, 36..41).
inline Model triangle()
{
    Model m;
    append<float>(m.bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
    append<std::uint16_t>(m.bin, {0, 1, 2});
    pad4(m.bin);
    m.doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                         {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
           {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
    };
    return m;
}

} // namespace swell::test::gltf_files
