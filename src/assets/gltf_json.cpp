// glTF step 2: the JSON read by us before tinygltf sees it: nesting depth,
// number ranges, required extensions, and the buffers, whose files are
// resolved inside the model's folder and read here (see asset_path.h).
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>
#include "core/asset_path.h"
#include "core/input_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace swell::detail::gltf {

namespace {

// Required extensions that only touch what we ignore (textures, lights,
// material parameters other than the base colour), so the geometry reads right.
bool isHarmlessExtension(std::string_view name)
{
    return name.starts_with("KHR_materials_") || name == "KHR_texture_transform" || name == "KHR_texture_basisu" ||
           name == "EXT_texture_webp" || name == "KHR_lights_punctual";
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

// Removes `extras` and `extensions` everywhere: we use neither (required
// extensions were checked to be harmless), and tinygltf would convert every
// value in them into a struct of its own.
void dropExtras(json& value)
{
    if (value.is_object()) {
        value.erase("extras");
        value.erase("extensions");
    }
    if (value.is_object() || value.is_array())
        for (json& child : value)
            dropExtras(child);
}

} // namespace

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

std::string GltfLoader::prepareJson(const GlbChunks& chunks, bool binary)
{
    if (chunks.json.size() > kMaxJsonBytes)
        fail(fmt::format("the JSON is {} bytes; at most {} are allowed (keep geometry in buffers: .bin files or a .glb)",
                         chunks.json.size(), kMaxJsonBytes));
    scanJson(chunks.json);
    json doc;
    try {
        doc = json::parse(chunks.json.begin(), chunks.json.end());
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
    checkEntries(doc);
    for (const auto& [key, value] : doc.items())
        checkNumbers(value, key, key);
    readBuffers(doc, chunks, binary);
    dropExtras(doc);
    try {
        return doc.dump();
    } catch (const json::exception& e) {
        fail("cannot re-encode JSON: " + printable(e.what(), 200));
    }
}

// Nesting and the number of values, counted in the text before parsing:
// the parser's recursion follows the nesting, and its allocations the values.
// (Counting with the parser's own callback is no use: nlohmann's callback
// parser takes time quadratic in the length of an array of objects, 1.3 s
// for 40,000 "{}" here.) Strings are skipped; each [, { and , starts at most
// one value, so their count bounds the values.
void GltfLoader::scanJson(std::string_view text) const
{
    int depth = 0;
    std::size_t values = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        switch (text[i]) {
        case '"':
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\')
                    ++i;
            break;
        case '[':
        case '{':
            if (++depth > kMaxJsonDepth)
                fail(fmt::format("JSON is nested more than {} levels deep", kMaxJsonDepth));
            ++values;
            break;
        case ']':
        case '}': --depth; break;
        case ',': ++values; break;
        default: break;
        }
        if (values > kMaxJsonValues)
            fail(fmt::format("the JSON holds more than {} values", kMaxJsonValues));
    }
}

void GltfLoader::checkEntries(const json& doc) const
{
    std::size_t entries = 0;
    for (const auto& [key, value] : doc.items()) {
        if (!value.is_array())
            continue;
        entries += value.size();
        if (key == "meshes")
            for (const json& mesh : value)
                if (const auto p = mesh.find("primitives"); mesh.is_object() && p != mesh.end() && p->is_array())
                    entries += p->size();
    }
    if (entries > kMaxJsonEntries)
        fail(fmt::format("the file lists {} scenes, nodes, meshes, primitives, accessors, bufferViews, buffers and "
                         "materials; at most {} are allowed",
                         entries, kMaxJsonEntries));
}

// Numbers must be finite, and the integer properties we read must be
// non-negative integers that fit; tinygltf would otherwise drop or wrap
// them silently. `extras` and `extensions` hold anything and are skipped.
void GltfLoader::checkNumbers(const json& value, const std::string& where, std::string_view key) const
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
void GltfLoader::readBuffers(const json& doc, const GlbChunks& chunks, bool binary)
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
void GltfLoader::readBufferFile(std::size_t i, const std::string& uri, std::uint64_t byteLength)
{
    if (embedded_)
        fail(fmt::format("buffer {} names the file '{}'; a built-in model holds its buffers as data: URIs", i,
                         printable(uri)));
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

} // namespace swell::detail::gltf
