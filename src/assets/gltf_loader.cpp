// glTF 2.0 models as MeshData: .gltf (buffers as base64 data: URIs or .bin
// files beside it) and .glb. Reads TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN
// primitives (points and lines are skipped), float POSITION and NORMAL,
// COLOR_0 as float or normalised u8/u16 VEC3/VEC4, u8/u16/u32 indices,
// interleaved bufferViews, sparse accessors, and node hierarchies with TRS or
// matrix transforms. Textures, skins, morph targets, animations and cameras
// are ignored.
//
// Every file is untrusted. The steps, each of which may throw InputError:
//   1. read the file (regular file, size limit) and split a .glb into chunks;
//   2. parse the JSON ourselves: nesting depth, integer and number ranges, the
//      buffers' URIs and sizes, required extensions; then drop the sections we
//      do not draw (images, animations, ...), since tinygltf indexes some of
//      them without bounds checks;
//   3. tinygltf builds the Model from the checked JSON and the buffer bytes
//      read in step 2; it reads no file itself;
//   4. every index, bufferView, accessor, node and value is checked here
//      before it is used, and the output is capped at kMaxVertices and
//      kMaxIndices before anything is allocated for it.
//
// The steps live in gltf_file.cpp, gltf_json.cpp, gltf_tinygltf.cpp and
// gltf_accessors/nodes/primitives.cpp; gltf_loader.h declares their parts.
#include "assets/gltf_loader.h"

#include "core/asset_path.h"
#include "swell/error.h"

#include <algorithm>
#include <cctype>

namespace swell::detail {
namespace gltf {

std::string printable(std::string_view s, std::size_t maxLength)
{
    std::string out;
    for (char c : s.substr(0, maxLength))
        out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (s.size() > maxLength)
        out += "...";
    return out;
}

std::optional<std::uint64_t> add(std::uint64_t a, std::uint64_t b)
{
    std::uint64_t r = 0;
    return __builtin_add_overflow(a, b, &r) ? std::nullopt : std::optional(r);
}

std::optional<std::uint64_t> mul(std::uint64_t a, std::uint64_t b)
{
    std::uint64_t r = 0;
    return __builtin_mul_overflow(a, b, &r) ? std::nullopt : std::optional(r);
}

std::string needs(std::optional<std::uint64_t> bytes)
{
    return bytes ? std::to_string(*bytes) : std::string("more than 2^64");
}

void GltfLoader::fail(const std::string& message, int line, int column) const
{
    throw InputError(SourcePlace{where_, line, column}, message);
}

MeshData GltfLoader::load(std::string_view hullNode, MeshData* hull)
{
    const std::string bytes = readFile();
    const bool binary = bytes.size() >= 4 && readU32(reinterpret_cast<const unsigned char*>(bytes.data())) == kGlbMagic;
    std::string extension = path_.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (!binary && extension == ".glb")
        fail("not a binary glTF file: it does not start with the 'glTF' magic");

    if (!embedded_) {
        std::error_code ec;
        const fs::path absolute = fs::absolute(path_, ec);
        if (ec)
            fail("cannot resolve the file's folder: " + ec.message());
        folder_ = resolvedFolder(absolute.parent_path());
    }

    GlbChunks chunks;
    if (binary)
        chunks = splitGlb(bytes);
    else
        chunks.json = bytes;

    std::string cleaned = prepareJson(chunks, binary);
    parseWithTinygltf(std::move(cleaned), chunks, binary);
    return assemble(hullNode, hull);
}

} // namespace gltf

MeshData loadGltf(const std::filesystem::path& path)
{
    return gltf::GltfLoader(path).load();
}

GltfModel loadGltf(const std::filesystem::path& path, std::string_view hullNode)
{
    GltfModel model;
    model.mesh = gltf::GltfLoader(path).load(hullNode, &model.hull);
    return model;
}

GltfModel loadEmbeddedGltf(std::string_view name, std::string_view text, std::string_view hullNode)
{
    GltfModel model;
    model.mesh = gltf::GltfLoader(name, text).load(hullNode, &model.hull);
    return model;
}

} // namespace swell::detail
