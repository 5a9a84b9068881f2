// The glTF loader's parts, shared by its files (see gltf_loader.cpp for the
// steps). Private to src/assets/; the entry point is loadGltf() in
// assets/mesh_data.h.
#pragma once

#include "assets/mesh_data.h"

#include <glm/mat4x4.hpp>

// Image decoding is left out of tinygltf (assets/image.cpp compiles
// stb_image, and we draw no textures); gltf_tinygltf.cpp compiles it.
#include <nlohmann/json.hpp>
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swell::detail::gltf {

namespace fs = std::filesystem;
using nlohmann::json;

// Most vertices and most indices one model may produce. They bound what
// loading allocates whatever the file holds: an accessor without a
// bufferView is all zeros, so a file of a few hundred bytes may claim the
// full count. At these caps MeshData is 72 MB of vertices and 24 MB of
// indices, and loading stays within the bound in docs/TESTING.md; two
// million vertices is still far more than any prop we draw.
constexpr std::size_t kMaxVertices = 2'000'000;
constexpr std::size_t kMaxIndices = 6'000'000;
// Largest file read, the model or one of its buffers, bytes. Loading holds
// the file, tinygltf's copy of its buffers and the decoded mesh at once, so
// this also bounds memory; a model within the caps above needs about 100 MB
// of vertex data at most.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(64) << 20;
// Largest JSON accepted, bytes: the glTF's own JSON, or a .glb's JSON chunk.
// Geometry belongs in buffers; the JSON is parsed twice (here and by
// tinygltf), and its strings are copied on the way.
constexpr std::size_t kMaxJsonBytes = std::size_t(16) << 20;
// Most JSON values (numbers, strings, objects, arrays) accepted: parsing
// allocates for each, about 100 bytes, so this bounds the parse at about
// 100 MB whatever the text ("[{},{},...]" is three bytes a value).
constexpr std::size_t kMaxJsonValues = 1'000'000;
// Most entries in the sections tinygltf reads (scenes, nodes, meshes and
// their primitives, accessors, bufferViews, buffers, materials) together:
// it makes a struct of several hundred bytes for each.
constexpr std::size_t kMaxJsonEntries = 65'536;
// Deepest JSON nesting accepted: glTF needs about 6 levels, and tinygltf
// converts `extras` recursively, so deep nesting could exhaust the stack.
constexpr int kMaxJsonDepth = 64;
// Most mesh primitives drawn, counting each node that instances a mesh once;
// bounds the work for files that instance empty primitives many times.
constexpr std::size_t kMaxPrimitiveInstances = 100'000;
// Colour of primitives without a material (linear RGB).
constexpr glm::vec3 kDefaultColor{0.8f, 0.8f, 0.8f};

// Integer-valued glTF properties we read, and the largest value each may have:
// sizes and counts up to 2^53 (larger are rejected later, with a clearer
// message), indices and enums up to INT32_MAX, since tinygltf keeps them as int.
constexpr std::array<std::string_view, 3> kSizeKeys{"byteOffset", "byteLength", "count"};
constexpr std::array<std::string_view, 9> kIndexKeys{"buffer",   "bufferView", "byteStride", "componentType", "mode",
                                                     "indices",  "material",   "mesh",       "scene"};

constexpr std::uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;  // "BIN\0"
static_assert(std::endian::native == std::endian::little, "glTF data is little-endian; reads below assume the same");

std::uint32_t readU32(const unsigned char* p);

// A piece of user data fit for an error message: printable ASCII, shortened.
std::string printable(std::string_view s, std::size_t maxLength = 60);

// a + b and a * b, or nothing on overflow.
std::optional<std::uint64_t> add(std::uint64_t a, std::uint64_t b);
std::optional<std::uint64_t> mul(std::uint64_t a, std::uint64_t b);
// A byte count for a message, or "more than 2^64".
std::string needs(std::optional<std::uint64_t> bytes);

// tinygltf's decoding of buffer URIs (it also turns '+' into a space), so we
// look for the same file it will.
std::string decodeUri(std::string_view uri);

struct GlbChunks {
    std::string_view json;
    const unsigned char* bin = nullptr; // nullptr when there is no BIN chunk
    std::size_t binSize = 0;
};

// Buffer files read ahead in step 2, by the path tinygltf will ask for in step 3.
struct ReadAhead {
    std::string bytes;
    int uses = 0; // buffers that name this file
};
using ReadAheadFiles = std::map<std::string, ReadAhead>;

class GltfLoader {
public:
    explicit GltfLoader(const fs::path& path) : path_(path), where_(path.string()) {}
    // A model compiled into the library (a built-in): `text` is the whole
    // .gltf, named `name` in messages. It may hold data: URIs only.
    GltfLoader(std::string_view name, std::string_view text) : path_(name), where_(name), embedded_(text) {}
    MeshData load(std::string_view hullNode = {}, MeshData* hull = nullptr);

private:
    [[noreturn]] void fail(const std::string& message, int line = 0, int column = 0) const;

    // Step 1 (gltf_file.cpp)
    std::string readFile() const;
    GlbChunks splitGlb(std::string_view text) const;

    // Step 2 (gltf_json.cpp)
    std::string prepareJson(const GlbChunks& chunks, bool binary);
    void checkNumbers(const json& value, const std::string& where, std::string_view key) const;
    void scanJson(std::string_view text) const;
    void checkEntries(const json& doc) const;
    void readBuffers(const json& doc, const GlbChunks& chunks, bool binary);
    void readBufferFile(std::size_t i, const std::string& uri, std::uint64_t byteLength);

    // Step 3 (gltf_tinygltf.cpp)
    void parseWithTinygltf(std::string text, const GlbChunks& chunks, bool binary);

    // Step 4: accessors (gltf_accessors.cpp). A Run is where elements lie:
    // the first byte and the step between elements; data is nullptr when
    // there is nothing to read (no elements, or an accessor without a
    // bufferView, all zeros).
    struct Run {
        const unsigned char* data = nullptr;
        std::size_t stride = 0;
    };
    // A decoded accessor: count elements of `components` values each.
    template <class T>
    struct Values {
        std::vector<T> data;
        int components = 0;
        std::size_t count() const { return components ? data.size() / std::size_t(components) : 0; }
    };
    Run locate(const std::string& user, int view, std::uint64_t offset, std::uint64_t count, std::size_t elementSize,
               bool allowStride) const;
    static std::size_t componentSize(int type);
    static float readFloat(const unsigned char* p, int type);
    static std::uint32_t readIndex(const unsigned char* p, int type);
    const tinygltf::Accessor& accessorAt(int index, const std::string& semantic) const;
    template <class T, class Read>
    Values<T> readAccessor(int index, const std::string& semantic, std::size_t maxElements,
                           std::initializer_list<int> componentTypes,
                           std::initializer_list<int> types, const char* expected, Read read) const;
    Values<float> readFloats(int index, const std::string& semantic, bool allowNormalized,
                             std::initializer_list<int> types, const char* expected) const;
    Values<std::uint32_t> readIndices(int index, const std::string& semantic) const;

    // Step 4: nodes (gltf_nodes.cpp)
    glm::dmat4 localTransform(std::size_t n) const;
    std::vector<std::size_t> roots() const;

    // Step 4: primitives (gltf_primitives.cpp). A Shape is what a primitive
    // draws, from its accessors' counts, before reading any data.
    struct Shape {
        bool drawn = false; // false for points and lines
        int position = -1, normal = -1, color = -1;
        std::size_t vertices = 0;
        std::size_t indices = 0; // as a triangle list
    };
    Shape shape(std::size_t m, std::size_t p) const;
    void addPrimitive(MeshData& out, std::size_t m, std::size_t p, const glm::dmat4& world, std::size_t node) const;
    // The drawn mesh; the primitives under the node named hullNode (when
    // not empty) go to *hull instead.
    MeshData assemble(std::string_view hullNode = {}, MeshData* hull = nullptr) const;

    fs::path path_;
    std::string where_;
    fs::path folder_; // the model's folder, resolved (core/asset_path.h); empty for an embedded model
    std::optional<std::string_view> embedded_;
    ReadAheadFiles readAhead_;
    tinygltf::Model model_;
};

} // namespace swell::detail::gltf
