// libFuzzer target for loadGltf. Each input is written to a file in a private
// temporary folder, as input.glb when it starts with the binary glTF magic and
// as input.gltf otherwise, and loaded. InputError is the expected outcome for
// bad input; a crash, a sanitizer report or any other exception is a bug.
// The folder also holds buffer.bin (64 bytes: a triangle's positions and u16
// indices, then zeros), so inputs can reach external buffers.
#include "assets/mesh_data.h"

#include "swell/error.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <stdlib.h> // mkdtemp

namespace {

namespace fs = std::filesystem;

struct FuzzState {
    fs::path folder;
};

FuzzState& state()
{
    static FuzzState s;
    return s;
}

void removeFolder()
{
    std::error_code ec;
    fs::remove_all(state().folder, ec);
}

void writeFile(const fs::path& path, const void* data, std::size_t size)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    std::string folder = (fs::temp_directory_path() / "swell-fuzz-gltf-XXXXXX").string();
    if (!mkdtemp(folder.data())) {
        std::perror("fuzz_gltf: mkdtemp");
        std::abort();
    }
    state().folder = folder;
    std::atexit(removeFolder);

    unsigned char buffer[64] = {};
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::memcpy(buffer, positions, sizeof positions);
    std::memcpy(buffer + 36, indices, sizeof indices);
    writeFile(state().folder / "buffer.bin", buffer, sizeof buffer);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const fs::path path = state().folder / (binary ? "input.glb" : "input.gltf");
    writeFile(path, data, size);
    try {
        (void)swell::detail::loadGltf(path);
    } catch (const swell::InputError&) {
    }
    std::error_code ec;
    fs::remove(path, ec);
    return 0;
}
