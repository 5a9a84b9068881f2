// glTF step 1: the file itself, read as a regular file within the size limit,
// and a .glb split into its JSON and BIN chunks.
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>
#include "core/input_file.h"

#include <system_error>

namespace swell::detail::gltf {

std::uint32_t readU32(const unsigned char* p)
{
    std::uint32_t v = 0;
    std::memcpy(&v, p, 4);
    return v;
}

std::string GltfLoader::readFile() const
{
    if (embedded_)
        return std::string(*embedded_);
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
GlbChunks GltfLoader::splitGlb(std::string_view text) const
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

} // namespace swell::detail::gltf
