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
//   3. tinygltf builds the Model and loads buffer bytes, through file
//      callbacks that read only regular files under the model's folder;
//   4. every index, bufferView, accessor, node and value is checked here
//      before it is used, and the output is capped at kMaxVertices and
//      kMaxIndices before anything is allocated for it.
#include "core/asset_path.h"
#include "core/input_file.h"
#include "core/mesh_data.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

// The one translation unit that compiles tinygltf; image decoding is left out
// (another file compiles stb_image, and we draw no textures).
#include <nlohmann/json.hpp>
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string_view>

namespace swell::detail {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Most vertices and most indices one model may produce: ten million of each
// is about 400 MB of MeshData, far more than any prop we draw, and stops a
// small file that claims huge counts from allocating without bound.
constexpr std::size_t kMaxVertices = 10'000'000;
constexpr std::size_t kMaxIndices = 10'000'000;
// Largest file read, the model or one of its buffers, bytes; tinygltf takes
// sizes as 32-bit, and a bigger model would exceed the limits above anyway.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(512) << 20;
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

// Required extensions that only touch what we ignore (textures, lights,
// material parameters other than the base colour), so the geometry reads right.
bool isHarmlessExtension(std::string_view name)
{
    return name.starts_with("KHR_materials_") || name == "KHR_texture_transform" || name == "KHR_texture_basisu" ||
           name == "EXT_texture_webp" || name == "KHR_lights_punctual";
}

// A piece of user data fit for an error message: printable ASCII, shortened.
std::string printable(std::string_view s, std::size_t maxLength = 60)
{
    std::string out;
    for (char c : s.substr(0, maxLength))
        out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (s.size() > maxLength)
        out += "...";
    return out;
}

// a + b and a * b, or nothing on overflow.
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

// ---------------------------------------------------------------------------
// Step 1: the file.

struct GlbChunks {
    std::string_view json;
    const unsigned char* bin = nullptr; // nullptr when there is no BIN chunk
    std::size_t binSize = 0;
};

constexpr std::uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;  // "BIN\0"
static_assert(std::endian::native == std::endian::little, "glTF data is little-endian; reads below assume the same");

std::uint32_t readU32(const unsigned char* p)
{
    std::uint32_t v = 0;
    std::memcpy(&v, p, 4);
    return v;
}

// ---------------------------------------------------------------------------
// File callbacks for tinygltf. Every external buffer was found, checked and
// read by checkBuffers() (inside the model's folder, a regular file, the
// size it claims); tinygltf is served those bytes and reads nothing itself.

// Buffer files read ahead, by the path tinygltf will ask for.
struct ReadAhead {
    std::string bytes;
    int uses = 0; // buffers that name this file; the last one takes the bytes
};
using ReadAheadFiles = std::map<std::string, ReadAhead>;

bool callbackFileExists(const std::string& file, void* files)
{
    return static_cast<const ReadAheadFiles*>(files)->count(file) != 0;
}

std::string callbackExpandFilePath(const std::string& file, void*)
{
    return file;
}

bool callbackReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* files)
{
    auto& all = *static_cast<ReadAheadFiles*>(files);
    const auto it = all.find(file);
    if (it == all.end() || it->second.uses <= 0) {
        if (err)
            *err += "not a buffer file this model may read";
        return false;
    }
    out->assign(it->second.bytes.begin(), it->second.bytes.end());
    if (--it->second.uses == 0)
        all.erase(it);
    return true;
}

bool callbackWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err += "writing is not supported";
    return false;
}

// tinygltf's decoding of buffer URIs (it also turns '+' into a space), so we
// look for the same file it will.
std::string decodeUri(std::string_view uri)
{
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9')
            return c - '0';
        if (c >= 'a' && c <= 'f')
            return c - 'a' + 10;
        if (c >= 'A' && c <= 'F')
            return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+')
            out += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else
            out += uri[i];
    }
    return out;
}

// The number of bytes a base64 payload decodes to, or nothing if it is not
// plain base64 (alphabet characters, then at most two '=').
std::optional<std::size_t> base64Size(std::string_view s)
{
    std::size_t n = 0;
    while (n < s.size() && (std::isalnum(static_cast<unsigned char>(s[n])) || s[n] == '+' || s[n] == '/'))
        ++n;
    const std::size_t padding = s.size() - n;
    if (padding > 2 || s.find_first_not_of('=', n) != std::string_view::npos || n % 4 == 1 ||
        (padding > 0 && (n + padding) % 4 != 0))
        return std::nullopt;
    return n / 4 * 3 + (n % 4 == 0 ? 0 : n % 4 - 1);
}

// ---------------------------------------------------------------------------

class GltfLoader {
public:
    explicit GltfLoader(const fs::path& path) : path_(path), where_(path.string()) {}

    MeshData load()
    {
        const std::string bytes = readFile();
        const bool binary = bytes.size() >= 4 && readU32(reinterpret_cast<const unsigned char*>(bytes.data())) == kGlbMagic;
        std::string extension = path_.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (!binary && extension == ".glb")
            fail("not a binary glTF file: it does not start with the 'glTF' magic");

        std::error_code ec;
        const fs::path absolute = fs::absolute(path_, ec);
        if (ec)
            fail("cannot resolve the file's folder: " + ec.message());
        folder_ = resolvedFolder(absolute.parent_path());

        GlbChunks chunks;
        if (binary)
            chunks = splitGlb(bytes);
        else
            chunks.json = bytes;

        std::string cleaned = prepareJson(chunks, binary);
        parseWithTinygltf(std::move(cleaned), chunks, binary);
        return assemble();
    }

private:
    [[noreturn]] void fail(const std::string& message, int line = 0, int column = 0) const
    {
        throw InputError(SourcePlace{where_, line, column}, message);
    }

    // ---- Step 1 ------------------------------------------------------------

    std::string readFile() const
    {
        std::string bytes;
        try {
            bytes = readInputFile(path_, kMaxFileBytes, "model");
        } catch (const InputError& e) {
            std::error_code ec;
            if (fs::is_directory(path_, ec))
                fail("is a directory, not a glTF file");
            if (!fs::exists(fs::symlink_status(path_, ec)))
                fail("file does not exist");
            fail(e.message());
        }
        if (bytes.empty())
            fail("file is empty");
        return bytes;
    }

    // Splits a .glb into its JSON and BIN chunks; unknown chunks are skipped.
    GlbChunks splitGlb(std::string_view text) const
    {
        const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
        const std::size_t byteCount = text.size();
        if (byteCount < 12)
            fail(fmt::format("truncated binary glTF: {} bytes is shorter than the 12-byte header", byteCount));
        const std::uint32_t version = readU32(bytes + 4);
        const std::uint32_t length = readU32(bytes + 8);
        if (version != 2)
            fail(fmt::format("unsupported binary glTF version {} (only version 2 is supported)", version));
        if (length < 12)
            fail(fmt::format("invalid binary glTF: the header says {} bytes, less than the header itself", length));
        if (length > byteCount)
            fail(fmt::format("truncated binary glTF: the header says {} bytes but the file has {}", length,
                             byteCount));
        GlbChunks chunks;
        bool haveJson = false;
        std::size_t offset = 12;
        for (int chunk = 0; offset < length; ++chunk) {
            if (length - offset < 8)
                fail(fmt::format("truncated binary glTF: chunk {} at byte {} has no room for its header", chunk,
                                 offset));
            const std::uint32_t chunkLength = readU32(bytes + offset);
            const std::uint32_t type = readU32(bytes + offset + 4);
            offset += 8;
            if (chunkLength > length - offset)
                fail(fmt::format("truncated binary glTF: chunk {} claims {} bytes but only {} remain", chunk,
                                 chunkLength, length - offset));
            const unsigned char* data = bytes + offset;
            if (chunk == 0) {
                if (type != kGlbChunkJson)
                    fail("binary glTF: the first chunk is not JSON");
                chunks.json = std::string_view(reinterpret_cast<const char*>(data), chunkLength);
                haveJson = true;
            } else if (chunk == 1 && type == kGlbChunkBin && chunkLength > 0) {
                chunks.bin = data;
                chunks.binSize = chunkLength;
            }
            offset += chunkLength;
        }
        if (!haveJson)
            fail("truncated binary glTF: there is no JSON chunk");
        return chunks;
    }

    // ---- Step 2 ------------------------------------------------------------

    std::string prepareJson(const GlbChunks& chunks, bool binary)
    {
        json doc;
        {
            bool tooDeep = false;
            json::parser_callback_t depthCheck = [&tooDeep](int depth, json::parse_event_t, json&) {
                if (depth > kMaxJsonDepth)
                    tooDeep = true;
                return !tooDeep;
            };
            try {
                doc = json::parse(chunks.json.begin(), chunks.json.end(), depthCheck);
            } catch (const json::parse_error& e) {
                int line = 0, column = 0;
                std::string what = e.what();
                if (!binary && std::sscanf(what.c_str(), "[json.exception.parse_error.%*d] parse error at line %d, column %d",
                                           &line, &column) != 2)
                    line = column = 0;
                fail("not valid JSON: " + printable(what, 200), line, column);
            } catch (const json::exception& e) {
                fail("not valid JSON: " + printable(e.what(), 200));
            }
            if (tooDeep)
                fail(fmt::format("JSON is nested more than {} levels deep", kMaxJsonDepth));
        }
        if (!doc.is_object())
            fail("not a glTF file: the JSON top level is not an object");

        const auto asset = doc.find("asset");
        if (asset == doc.end() || !asset->is_object())
            fail("not a glTF file: the required 'asset' object is missing");
        const auto version = asset->find("version");
        if (version == asset->end() || !version->is_string())
            fail("not a glTF file: 'asset' has no 'version'");
        if (!version->get_ref<const std::string&>().starts_with("2."))
            fail("unsupported glTF version '" + printable(version->get_ref<const std::string&>()) +
                 "' (only 2.x is supported)");

        if (const auto required = doc.find("extensionsRequired"); required != doc.end() && required->is_array())
            for (const json& e : *required)
                if (e.is_string() && !isHarmlessExtension(e.get_ref<const std::string&>()))
                    fail("requires extension " + printable(e.get_ref<const std::string&>()) +
                         ", which is not supported");

        // What tinygltf gets: the parts we read, nothing else.
        static constexpr std::array<std::string_view, 9> kept{"asset", "scene",   "scenes",      "nodes",    "meshes",
                                                              "accessors", "bufferViews", "buffers", "materials"};
        for (auto it = doc.begin(); it != doc.end();) {
            if (std::find(kept.begin(), kept.end(), it.key()) == kept.end())
                it = doc.erase(it);
            else
                ++it;
        }
        for (const auto& [key, value] : doc.items())
            checkNumbers(value, key, key);
        readBuffers(doc, chunks, binary);
        try {
            return doc.dump();
        } catch (const json::exception& e) {
            fail("cannot re-encode JSON: " + printable(e.what(), 200));
        }
    }

    // Numbers must be finite, and the integer properties we read must be
    // non-negative integers that fit; tinygltf would otherwise drop or wrap
    // them silently. `extras` and `extensions` hold anything and are skipped.
    void checkNumbers(const json& value, const std::string& where, std::string_view key) const
    {
        if (value.is_number_float() && !std::isfinite(value.get<double>()))
            fail(where + " is not a finite number");
        const bool isSize = std::find(kSizeKeys.begin(), kSizeKeys.end(), key) != kSizeKeys.end();
        const bool isIndex = std::find(kIndexKeys.begin(), kIndexKeys.end(), key) != kIndexKeys.end();
        if (value.is_number() && (isSize || isIndex)) {
            const std::uint64_t limit = isSize ? (std::uint64_t(1) << 53) : std::uint64_t(INT32_MAX);
            if (value.is_number_float() || (value.is_number_integer() && !value.is_number_unsigned()) ||
                value.get<std::uint64_t>() > limit)
                fail(fmt::format("{} must be an integer from 0 to {}, not {}", where, limit, printable(value.dump())));
        }
        if (value.is_object()) {
            for (const auto& [k, v] : value.items()) {
                if (k == "extras" || k == "extensions")
                    continue;
                // Attribute values are accessor indices.
                checkNumbers(v, where + "." + printable(k), key == "attributes" ? std::string_view("indices") : k);
            }
        } else if (value.is_array()) {
            // Node children and scene roots are node indices.
            const std::string_view elementKey = (key == "children" || where.ends_with("].nodes")) ? "mesh" : key;
            for (std::size_t i = 0; i < value.size(); ++i)
                checkNumbers(value[i], fmt::format("{}[{}]", where, i), elementKey);
        }
    }

    // Buffers must have the bytes they claim, from a base64 data: URI, a file
    // in the model's folder or below it (read here, for tinygltf to be served
    // by the callbacks above), or (buffer 0 of a .glb) the BIN chunk.
    void readBuffers(const json& doc, const GlbChunks& chunks, bool binary)
    {
        const auto buffers = doc.find("buffers");
        if (buffers == doc.end())
            return;
        if (!buffers->is_array())
            fail("'buffers' is not an array");
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const json& b = (*buffers)[i];
            if (!b.is_object())
                fail(fmt::format("buffer {} is not an object", i));
            const auto lengthIt = b.find("byteLength");
            if (lengthIt == b.end())
                fail(fmt::format("buffer {} has no byteLength", i));
            if (!lengthIt->is_number_unsigned())
                fail(fmt::format("buffer {}'s byteLength is not a non-negative integer", i));
            const std::uint64_t byteLength = lengthIt->get<std::uint64_t>();
            if (byteLength == 0)
                fail(fmt::format("buffer {} has byteLength 0", i));
            const auto uriIt = b.find("uri");
            if (uriIt == b.end()) {
                if (!binary || i != 0)
                    fail(fmt::format("buffer {} has no uri{}", i,
                                     binary ? " (only buffer 0 may use the BIN chunk)" : ""));
                if (!chunks.bin)
                    fail("buffer 0 has no uri and the file has no BIN chunk");
                if (byteLength > chunks.binSize)
                    fail(fmt::format("buffer 0 claims {} bytes but the BIN chunk holds only {}", byteLength,
                                     chunks.binSize));
                continue;
            }
            if (!uriIt->is_string())
                fail(fmt::format("buffer {}'s uri is not a string", i));
            const std::string& uri = uriIt->get_ref<const std::string&>();
            if (uri.starts_with("data:")) {
                std::string_view payload;
                for (std::string_view prefix :
                     {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"})
                    if (uri.starts_with(prefix))
                        payload = std::string_view(uri).substr(prefix.size());
                if (payload.data() == nullptr)
                    fail(fmt::format("buffer {} has an unsupported data URI '{}' (only base64 "
                                     "application/octet-stream or application/gltf-buffer)",
                                     i, printable(uri, 40)));
                const std::optional<std::size_t> size = base64Size(payload);
                if (!size)
                    fail(fmt::format("buffer {} has a data URI that is not valid base64", i));
                if (*size != byteLength)
                    fail(fmt::format("buffer {}'s data URI holds {} bytes but its byteLength is {}", i, *size,
                                     byteLength));
                continue;
            }
            const std::size_t colon = uri.find(':'), slash = uri.find('/');
            if (uri.empty() || uri.front() == '/' || (colon != std::string::npos && colon < slash))
                fail(fmt::format("buffer {} refers to '{}': only relative file paths are supported", i,
                                 printable(uri)));
            readBufferFile(i, uri, byteLength);
        }
    }

    // External buffer i: decoded, resolved (links included) and required to
    // lie under the model's folder before anything about it is looked at, so
    // a refusal tells nothing about a file outside.
    void readBufferFile(std::size_t i, const std::string& uri, std::uint64_t byteLength)
    {
        const std::string decoded = decodeUri(uri);
        if (std::any_of(decoded.begin(), decoded.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
            fail(fmt::format("buffer {}'s uri '{}' holds a control character", i, printable(uri)));
        const std::optional<fs::path> file = resolveInside(folder_, decoded);
        if (!file)
            fail(fmt::format("buffer {} refers to '{}', which lies outside the model's folder; a model may use only "
                             "files in its folder or below it",
                             i, printable(uri)));
        std::string bytes;
        try {
            bytes = readInputFile(*file, kMaxFileBytes, "buffer file");
        } catch (const InputError& e) {
            std::error_code ec;
            if (!fs::exists(fs::symlink_status(*file, ec)))
                fail(fmt::format("buffer {}'s file '{}' was not found beside the model", i, printable(uri)));
            fail(fmt::format("buffer {}'s file '{}': {}", i, printable(uri), e.message()));
        }
        if (bytes.size() != byteLength)
            fail(fmt::format("buffer {}'s file '{}' has {} bytes but its byteLength is {}", i, printable(uri),
                             bytes.size(), byteLength));
        // The path tinygltf asks for: its JoinPath of the base folder and the same decoding.
        const std::string folder = folder_.string();
        ReadAhead& entry = readAhead_[folder.back() == '/' ? folder + decoded : folder + "/" + decoded];
        entry.bytes = std::move(bytes);
        ++entry.uses;
    }

    // ---- Step 3 ------------------------------------------------------------

    void parseWithTinygltf(std::string text, const GlbChunks& chunks, bool binary)
    {
        tinygltf::TinyGLTF loader;
        loader.SetFsCallbacks(tinygltf::FsCallbacks{&callbackFileExists, &callbackExpandFilePath,
                                                    &callbackReadWholeFile, &callbackWriteWholeFile, &readAhead_});
        std::string err, warn;
        bool ok = false;
        try {
            if (binary) {
                // A .glb again, with the cleaned JSON; both chunks padded to 4 bytes.
                text.append((4 - text.size() % 4) % 4, ' ');
                const std::size_t binPadded = chunks.bin ? (chunks.binSize + 3) / 4 * 4 : 0;
                const std::uint64_t total = 12 + 8 + text.size() + (chunks.bin ? 8 + binPadded : 0);
                if (total > std::numeric_limits<std::uint32_t>::max())
                    fail("file is too large for binary glTF");
                std::vector<unsigned char> glb;
                glb.reserve(std::size_t(total));
                const auto put32 = [&glb](std::uint32_t v) {
                    for (int i = 0; i < 4; ++i)
                        glb.push_back(static_cast<unsigned char>(v >> (8 * i)));
                };
                put32(kGlbMagic);
                put32(2);
                put32(std::uint32_t(total));
                put32(std::uint32_t(text.size()));
                put32(kGlbChunkJson);
                glb.insert(glb.end(), text.begin(), text.end());
                if (chunks.bin) {
                    put32(std::uint32_t(binPadded));
                    put32(kGlbChunkBin);
                    glb.insert(glb.end(), chunks.bin, chunks.bin + chunks.binSize);
                    glb.resize(glb.size() + binPadded - chunks.binSize, 0);
                }
                text = std::string();
                ok = loader.LoadBinaryFromMemory(&model_, &err, &warn, glb.data(), std::uint32_t(glb.size()), folder_.string(),
                                                 tinygltf::REQUIRE_VERSION);
            } else {
                if (text.size() > std::numeric_limits<std::uint32_t>::max())
                    fail("file is too large");
                ok = loader.LoadASCIIFromString(&model_, &err, &warn, text.data(), std::uint32_t(text.size()),
                                                folder_.string(), tinygltf::REQUIRE_VERSION);
            }
        } catch (const InputError&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception& e) {
            fail("invalid glTF: " + printable(e.what(), 200));
        }
        if (ok && !err.empty())
            ok = false; // tinygltf reports some problems, such as a malformed primitive, and goes on without them
        if (!ok) {
            while (!err.empty() && (err.back() == '\n' || err.back() == ' '))
                err.pop_back();
            fail("invalid glTF: " + printable(err.empty() ? std::string("unknown error") : err, 200));
        }
    }

    // ---- Step 4 ------------------------------------------------------------

    // Where a run of elements lies: the first byte and the step between
    // elements. data is nullptr when there is nothing to read: no elements,
    // or an accessor without a bufferView (all zeros).
    struct Run {
        const unsigned char* data = nullptr;
        std::size_t stride = 0;
    };

    // Checks that `count` elements of `elementSize` bytes, starting `offset`
    // bytes into bufferView `view`, lie inside that view and the view inside
    // its buffer. Elements are the view's byteStride apart when allowStride,
    // else packed. `user` names the reader in messages.
    Run locate(const std::string& user, int view, std::uint64_t offset, std::uint64_t count, std::size_t elementSize,
               bool allowStride) const
    {
        if (view < 0 || std::size_t(view) >= model_.bufferViews.size())
            fail(fmt::format("{} refers to bufferView {}, which does not exist", user, view));
        const tinygltf::BufferView& v = model_.bufferViews[std::size_t(view)];
        if (v.buffer < 0 || std::size_t(v.buffer) >= model_.buffers.size())
            fail(fmt::format("bufferView {} refers to buffer {}, which does not exist", view, v.buffer));
        const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(v.buffer)].data;
        const std::optional<std::uint64_t> viewEnd = add(v.byteOffset, v.byteLength);
        if (!viewEnd || *viewEnd > buffer.size())
            fail(fmt::format("bufferView {} reads past the end of buffer {} (needs {} bytes, has {})", view, v.buffer,
                             needs(viewEnd), buffer.size()));
        if (count == 0)
            return {};
        std::size_t stride = elementSize;
        if (allowStride && v.byteStride != 0) {
            if (v.byteStride < elementSize || v.byteStride > 252 || v.byteStride % 4 != 0)
                fail(fmt::format("bufferView {} has byteStride {}, which does not fit the {}-byte elements of {}",
                                 view, v.byteStride, elementSize, user));
            stride = v.byteStride;
        }
        std::optional<std::uint64_t> end = mul(count - 1, stride);
        if (end)
            end = add(*end, elementSize);
        if (end)
            end = add(*end, offset);
        if (!end || *end > v.byteLength)
            fail(fmt::format("{} reads past the end of bufferView {} (needs {} bytes, has {})", user, view, needs(end),
                             v.byteLength));
        return {buffer.data() + v.byteOffset + std::size_t(offset), stride};
    }

    static std::size_t componentSize(int type)
    {
        switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        default:
            return 4; // UNSIGNED_INT, FLOAT
        }
    }

    // Reads element components as floats; unsigned integers are normalised to 0..1.
    static float readFloat(const unsigned char* p, int type)
    {
        switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return float(*p) / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v = 0;
            std::memcpy(&v, p, 2);
            return float(v) / 65535.0f;
        }
        default: {
            float v = 0;
            std::memcpy(&v, p, 4);
            return v;
        }
        }
    }

    static std::uint32_t readIndex(const unsigned char* p, int type)
    {
        switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return *p;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v = 0;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            std::uint32_t v = 0;
            std::memcpy(&v, p, 4);
            return v;
        }
        }
    }

    const tinygltf::Accessor& accessorAt(int index, const std::string& semantic) const
    {
        if (index < 0 || std::size_t(index) >= model_.accessors.size())
            fail(fmt::format("{} refers to accessor {}, which does not exist", semantic, index));
        return model_.accessors[std::size_t(index)];
    }

    // Decoded accessor: count elements of `components` values each.
    template <class T>
    struct Values {
        std::vector<T> data;
        int components = 0;
        std::size_t count() const { return components ? data.size() / std::size_t(components) : 0; }
    };

    // Reads accessor `index`, used as `semantic`, whose component type must be
    // in `componentTypes` and element type in `types`. Read converts one
    // component. Sparse substitutions are applied.
    template <class T, class Read>
    Values<T> readAccessor(int index, const std::string& semantic, std::initializer_list<int> componentTypes,
                           std::initializer_list<int> types, const char* expected, Read read) const
    {
        const tinygltf::Accessor& a = accessorAt(index, semantic);
        const std::string user = fmt::format("accessor {} ({})", index, semantic);
        if (std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end() ||
            std::find(types.begin(), types.end(), a.type) == types.end())
            fail(fmt::format("{} must be {}", user, expected));
        if (a.count > kMaxVertices)
            fail(fmt::format("{} has {} elements, more than the limit of {}", user, a.count, kMaxVertices));
        const int components = a.type == TINYGLTF_TYPE_SCALAR ? 1 : a.type; // VEC2..VEC4 are 2..4
        const std::size_t size = componentSize(a.componentType);
        const std::size_t elementSize = size * std::size_t(components);

        const Run run = a.bufferView >= 0 ? locate(user, a.bufferView, a.byteOffset, a.count, elementSize, true) : Run{};
        Values<T> out;
        out.components = components;
        out.data.assign(a.count * std::size_t(components), T{});
        if (run.data) {
            for (std::size_t i = 0; i < a.count; ++i)
                for (int c = 0; c < components; ++c)
                    out.data[i * std::size_t(components) + std::size_t(c)] =
                        read(run.data + i * run.stride + std::size_t(c) * size, a.componentType);
        }
        if (a.sparse.isSparse) {
            const auto& s = a.sparse;
            const std::string sparseUser = user + " sparse";
            if (s.count < 1 || std::size_t(s.count) > a.count)
                fail(fmt::format("{} has {} substitutions for {} elements", sparseUser, s.count, a.count));
            if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
                fail(fmt::format("{} has a negative byteOffset", sparseUser));
            const int indexType = s.indices.componentType;
            if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(fmt::format("{} indices must be unsigned byte, short or int", sparseUser));
            const Run indices = locate(sparseUser + " indices", s.indices.bufferView, std::uint64_t(s.indices.byteOffset),
                                       std::uint64_t(s.count), componentSize(indexType), false);
            const Run values = locate(sparseUser + " values", s.values.bufferView, std::uint64_t(s.values.byteOffset),
                                      std::uint64_t(s.count), elementSize, false);
            for (std::size_t i = 0; i < std::size_t(s.count); ++i) {
                const std::uint32_t target = readIndex(indices.data + i * indices.stride, indexType);
                if (target >= a.count)
                    fail(fmt::format("{} index {} is out of range (the accessor has {} elements)", sparseUser, target,
                                     a.count));
                for (int c = 0; c < components; ++c)
                    out.data[target * std::size_t(components) + std::size_t(c)] =
                        read(values.data + i * values.stride + std::size_t(c) * size, a.componentType);
            }
        }
        return out;
    }

    Values<float> readFloats(int index, const std::string& semantic, bool allowNormalized,
                             std::initializer_list<int> types, const char* expected) const
    {
        Values<float> v = allowNormalized
                              ? readAccessor<float>(index, semantic,
                                                    {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                                    types, expected, readFloat)
                              : readAccessor<float>(index, semantic, {TINYGLTF_COMPONENT_TYPE_FLOAT}, types, expected,
                                                    readFloat);
        for (std::size_t i = 0; i < v.data.size(); ++i)
            if (!std::isfinite(v.data[i]))
                fail(fmt::format("accessor {} ({}) has a non-finite value in element {}", index, semantic,
                                 i / std::size_t(v.components)));
        return v;
    }

    // ---- Nodes -------------------------------------------------------------

    glm::dmat4 localTransform(std::size_t n) const
    {
        const tinygltf::Node& node = model_.nodes[n];
        const auto numbers = [&](const std::vector<double>& v, std::size_t size, const char* what) {
            if (v.size() != size)
                fail(fmt::format("node {} has a {} of {} numbers (needs {})", n, what, v.size(), size));
            for (double x : v)
                if (!std::isfinite(x))
                    fail(fmt::format("node {} has a non-finite {}", n, what));
        };
        if (!node.matrix.empty()) {
            numbers(node.matrix, 16, "matrix");
            glm::dmat4 m(1.0);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    m[c][r] = node.matrix[std::size_t(c * 4 + r)];
            return m;
        }
        glm::dmat4 t(1.0), r(1.0), s(1.0);
        if (!node.translation.empty()) {
            numbers(node.translation, 3, "translation");
            t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
        }
        if (!node.rotation.empty()) {
            numbers(node.rotation, 4, "rotation");
            double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
            const double length = std::sqrt(x * x + y * y + z * z + w * w);
            if (!(length > 1e-12) || !std::isfinite(length))
                fail(fmt::format("node {} has a rotation quaternion of length {}", n, length));
            x /= length, y /= length, z /= length, w /= length;
            r[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0);
            r[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0);
            r[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0);
        }
        if (!node.scale.empty()) {
            numbers(node.scale, 3, "scale");
            s[0][0] = node.scale[0];
            s[1][1] = node.scale[1];
            s[2][2] = node.scale[2];
        }
        return t * r * s;
    }

    // The root nodes to draw, after checking that the nodes form a forest:
    // indices in range, at most one parent each, no cycles.
    std::vector<std::size_t> roots() const
    {
        const std::size_t count = model_.nodes.size();
        constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
        std::vector<std::size_t> parent(count, kNone);
        for (std::size_t n = 0; n < count; ++n) {
            const tinygltf::Node& node = model_.nodes[n];
            if (node.mesh < -1 || node.mesh >= int(std::min<std::size_t>(model_.meshes.size(), INT32_MAX)))
                fail(fmt::format("node {} refers to mesh {}, which does not exist", n, node.mesh));
            for (int child : node.children) {
                if (child < 0 || std::size_t(child) >= count)
                    fail(fmt::format("node {} has child {}, which does not exist", n, child));
                if (std::size_t(child) == n)
                    fail(fmt::format("node graph has a cycle: node {} is its own child", n));
                if (parent[std::size_t(child)] != kNone)
                    fail(fmt::format("node {} has more than one parent (nodes {} and {})", child,
                                     parent[std::size_t(child)], n));
                parent[std::size_t(child)] = n;
            }
        }
        // With one parent each, a cycle is a loop of parent links.
        std::vector<char> state(count, 0); // 0 unseen, 1 on the current walk, 2 done
        for (std::size_t n = 0; n < count; ++n) {
            std::size_t at = n;
            while (at != kNone && state[at] == 0) {
                state[at] = 1;
                at = parent[at];
            }
            if (at != kNone && state[at] == 1)
                fail(fmt::format("node graph has a cycle through node {}", at));
            for (at = n; at != kNone && state[at] == 1; at = parent[at])
                state[at] = 2;
        }

        std::vector<std::size_t> out;
        if (model_.scenes.empty()) {
            if (model_.defaultScene >= 0)
                fail(fmt::format("scene {} does not exist (the file has no scenes)", model_.defaultScene));
            for (std::size_t n = 0; n < count; ++n)
                if (parent[n] == kNone)
                    out.push_back(n);
            return out;
        }
        const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
        if (std::size_t(sceneIndex) >= model_.scenes.size())
            fail(fmt::format("scene {} does not exist (the file has {})", sceneIndex, model_.scenes.size()));
        std::vector<char> listed(count, 0);
        for (int n : model_.scenes[std::size_t(sceneIndex)].nodes) {
            if (n < 0 || std::size_t(n) >= count)
                fail(fmt::format("scene {} lists node {}, which does not exist", sceneIndex, n));
            if (parent[std::size_t(n)] != kNone)
                fail(fmt::format("scene {} lists node {}, which is a child of node {}", sceneIndex, n,
                                 parent[std::size_t(n)]));
            if (listed[std::size_t(n)])
                fail(fmt::format("scene {} lists node {} twice", sceneIndex, n));
            listed[std::size_t(n)] = 1;
            out.push_back(std::size_t(n));
        }
        return out;
    }

    // ---- Primitives --------------------------------------------------------

    // What a primitive draws, from its accessors' counts, before reading any data.
    struct Shape {
        bool drawn = false; // false for points and lines
        int position = -1, normal = -1, color = -1;
        std::size_t vertices = 0;
        std::size_t indices = 0; // as a triangle list
    };

    Shape shape(std::size_t m, std::size_t p) const
    {
        const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
        const std::string where = fmt::format("mesh {} primitive {}", m, p);
        Shape s;
        if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP)
            return s; // points and lines have no surface
        if (prim.mode < TINYGLTF_MODE_TRIANGLES || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail(fmt::format("{} has unknown mode {}", where, prim.mode));
        s.drawn = true;
        const auto attribute = [&](const char* name) {
            const auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        s.position = attribute("POSITION");
        if (s.position < 0)
            fail(where + " has no POSITION attribute");
        s.vertices = accessorAt(s.position, where + " POSITION").count;
        s.normal = attribute("NORMAL");
        s.color = attribute("COLOR_0");
        for (const auto& [index, name] : {std::pair{s.normal, "NORMAL"}, std::pair{s.color, "COLOR_0"}})
            if (index >= 0 && accessorAt(index, where + " " + name).count != s.vertices)
                fail(fmt::format("{} has {} {} values but {} positions", where,
                                 accessorAt(index, where).count, name, s.vertices));
        // Counts are at most 2^53 (checked in the JSON), so these cannot overflow.
        const std::size_t n = prim.indices >= 0 ? accessorAt(prim.indices, where + " indices").count : s.vertices;
        if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
            if (n % 3 != 0)
                fail(fmt::format("{} has {} {}, not a multiple of 3", where, n,
                                 prim.indices >= 0 ? "indices" : "vertices"));
            s.indices = n;
        } else
            s.indices = n >= 3 ? 3 * (n - 2) : 0;
        return s;
    }

    // Appends primitive p of mesh m, placed by `world`.
    void addPrimitive(MeshData& out, std::size_t m, std::size_t p, const glm::dmat4& world, std::size_t node) const
    {
        const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
        const std::string where = fmt::format("mesh {} primitive {}", m, p);
        const Shape s = shape(m, p);
        if (!s.drawn)
            return;
        if (out.vertices.size() + s.vertices > kMaxVertices || out.indices.size() + s.indices > kMaxIndices)
            fail(fmt::format("model has more than {} vertices or {} indices", kMaxVertices, kMaxIndices));

        const Values<float> positions =
            readFloats(s.position, where + " POSITION", false, {TINYGLTF_TYPE_VEC3}, "float VEC3");
        const std::size_t vertexCount = positions.count();
        std::optional<Values<float>> normals, colors;
        if (s.normal >= 0)
            normals = readFloats(s.normal, where + " NORMAL", false, {TINYGLTF_TYPE_VEC3}, "float VEC3");
        if (s.color >= 0)
            colors = readFloats(s.color, where + " COLOR_0", true, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                                "VEC3 or VEC4 of float or normalised unsigned byte or short");

        // Vertex indices of the primitive, then triangles from them.
        std::vector<std::uint32_t> order;
        if (prim.indices >= 0) {
            const Values<std::uint32_t> indices = readAccessor<std::uint32_t>(
                prim.indices, where + " indices",
                {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                {TINYGLTF_TYPE_SCALAR}, "SCALAR unsigned byte, short or int", readIndex);
            for (std::size_t i = 0; i < indices.data.size(); ++i)
                if (indices.data[i] >= vertexCount)
                    fail(fmt::format("{} index {} is {}, but there are only {} vertices", where, i, indices.data[i],
                                     vertexCount));
            order = indices.data;
        } else {
            order.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                order[i] = std::uint32_t(i);
        }
        const std::size_t triangleCount = s.indices / 3;

        const double det = glm::determinant(glm::dmat3(world));
        const bool mirrored = det < 0.0;
        std::vector<std::uint32_t> triangles;
        triangles.reserve(triangleCount * 3);
        for (std::size_t t = 0; t < triangleCount; ++t) {
            std::uint32_t a = 0, b = 0, c = 0;
            if (prim.mode == TINYGLTF_MODE_TRIANGLES)
                a = order[3 * t], b = order[3 * t + 1], c = order[3 * t + 2];
            else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP)
                a = order[t + (t % 2)], b = order[t + 1 - (t % 2)], c = order[t + 2];
            else
                a = order[0], b = order[t + 1], c = order[t + 2];
            if (mirrored)
                std::swap(b, c);
            triangles.insert(triangles.end(), {a, b, c});
        }

        glm::vec3 factor = kDefaultColor;
        if (prim.material >= 0) {
            if (std::size_t(prim.material) >= model_.materials.size())
                fail(fmt::format("{} refers to material {}, which does not exist", where, prim.material));
            const std::vector<double>& f = model_.materials[std::size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
            if (f.size() < 3)
                fail(fmt::format("material {} has a baseColorFactor of {} numbers", prim.material, f.size()));
            for (int c = 0; c < 3; ++c)
                factor[c] = float(std::clamp(f[std::size_t(c)], 0.0, 1.0));
        } else if (colors)
            factor = glm::vec3(1.0f);

        // Normals transform with the cofactor matrix (the inverse transpose
        // scaled by the determinant), which also works for flattening scales.
        const glm::dmat3 linear(world);
        glm::dmat3 cofactor;
        cofactor[0] = glm::cross(linear[1], linear[2]);
        cofactor[1] = glm::cross(linear[2], linear[0]);
        cofactor[2] = glm::cross(linear[0], linear[1]);
        if (mirrored)
            cofactor = -cofactor;

        const auto base = std::uint32_t(out.vertices.size());
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const float* q = &positions.data[3 * i];
            const glm::dvec3 position = glm::dvec3(world * glm::dvec4(q[0], q[1], q[2], 1.0));
            constexpr double kFloatMax = std::numeric_limits<float>::max();
            if (!(std::abs(position.x) <= kFloatMax && std::abs(position.y) <= kFloatMax &&
                  std::abs(position.z) <= kFloatMax))
                fail(fmt::format("node {}'s transform moves {} vertex {} to a non-finite position", node, where, i));
            MeshVertex v;
            v.position = glm::vec3(position);
            if (normals) {
                const float* nn = &normals->data[3 * i];
                const glm::dvec3 n = cofactor * glm::dvec3(nn[0], nn[1], nn[2]);
                const double length = glm::length(n);
                v.normal = length > 1e-30 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0, 1, 0);
            }
            v.color = factor;
            if (colors) {
                const float* c = &colors->data[std::size_t(colors->components) * i];
                v.color *= glm::clamp(glm::vec3(c[0], c[1], c[2]), glm::vec3(0.0f), glm::vec3(1.0f));
            }
            out.vertices.push_back(v);
        }
        if (!normals) {
            // Smooth normals: area-weighted sums of the faces around each vertex.
            for (std::size_t t = 0; t < triangles.size(); t += 3) {
                MeshVertex& a = out.vertices[base + triangles[t]];
                MeshVertex& b = out.vertices[base + triangles[t + 1]];
                MeshVertex& c = out.vertices[base + triangles[t + 2]];
                const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
                if (std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) {
                    a.normal += n;
                    b.normal += n;
                    c.normal += n;
                }
            }
            for (std::size_t i = base; i < out.vertices.size(); ++i) {
                const float length = glm::length(out.vertices[i].normal);
                out.vertices[i].normal = length > 0.0f && std::isfinite(length) ? out.vertices[i].normal / length
                                                                                 : glm::vec3(0, 1, 0);
            }
        }
        for (std::uint32_t i : triangles)
            out.indices.push_back(base + i);
    }

    MeshData assemble() const
    {
        // Pass 1: every primitive drawn, with its node's world transform.
        struct Instance {
            std::size_t node, mesh, primitive;
            glm::dmat4 world;
        };
        std::vector<Instance> instances;
        struct Item {
            std::size_t node;
            glm::dmat4 parent;
        };
        // Depth first in file order: roots and children go on in reverse.
        const std::vector<std::size_t> rootNodes = roots();
        std::vector<Item> stack;
        for (auto r = rootNodes.rbegin(); r != rootNodes.rend(); ++r)
            stack.push_back({*r, glm::dmat4(1.0)});
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            const tinygltf::Node& node = model_.nodes[item.node];
            const glm::dmat4 world = item.parent * localTransform(item.node);
            if (node.mesh >= 0)
                for (std::size_t p = 0; p < model_.meshes[std::size_t(node.mesh)].primitives.size(); ++p) {
                    if (instances.size() == kMaxPrimitiveInstances)
                        fail(fmt::format("model draws more than {} mesh primitives", kMaxPrimitiveInstances));
                    instances.push_back({item.node, std::size_t(node.mesh), p, world});
                }
            for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
                stack.push_back({std::size_t(*c), world});
        }

        // The totals, checked against the limits before anything is read.
        std::optional<std::uint64_t> vertices = 0, indices = 0;
        for (const Instance& i : instances) {
            const Shape s = shape(i.mesh, i.primitive);
            vertices = vertices ? add(*vertices, s.vertices) : vertices;
            indices = indices ? add(*indices, s.indices) : indices;
        }
        if (!vertices || *vertices > kMaxVertices)
            fail(fmt::format("model has {} vertices, more than the limit of {}", needs(vertices), kMaxVertices));
        if (!indices || *indices > kMaxIndices)
            fail(fmt::format("model has {} indices, more than the limit of {}", needs(indices), kMaxIndices));

        // Pass 2: the data.
        MeshData out;
        for (const Instance& i : instances)
            addPrimitive(out, i.mesh, i.primitive, i.world, i.node);
        if (out.indices.empty())
            fail("model has no triangles to draw");
        return out;
    }

    fs::path path_;
    std::string where_;
    fs::path folder_; // resolved (asset_path.h)
    ReadAheadFiles readAhead_;
    tinygltf::Model model_;
};

} // namespace

MeshData loadGltf(const std::filesystem::path& path)
{
    return GltfLoader(path).load();
}

} // namespace swell::detail
