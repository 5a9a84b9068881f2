// glTF step 3: tinygltf builds its Model from the checked JSON. It reads no
// file itself: the callbacks serve the buffer files read ahead in step 2.
// The one translation unit that compiles tinygltf.
#define TINYGLTF_IMPLEMENTATION
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>

#include <limits>

namespace swell::detail::gltf {

namespace {

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

} // namespace

void GltfLoader::parseWithTinygltf(std::string text, const GlbChunks& chunks, bool binary)
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

} // namespace swell::detail::gltf
