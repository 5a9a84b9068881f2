// libFuzzer target for loadGltf. Each input is written to a file in a private
// temporary folder, as input.glb when it starts with the binary glTF magic and
// as input.gltf otherwise, and loaded. InputError is the expected outcome for
// bad input; a crash, a sanitizer report or any other exception is a bug.
// The folder also holds buffer.bin (64 bytes: a triangle's positions and u16
// indices, then zeros), so inputs can reach external buffers.
#include "assets/mesh_data.h"
#include "fuzz_support.h"

#include "swell/error.h"

#include <cstdint>
#include <cstring>
#include <filesystem>

using swell::fuzz::privateFolder;
using swell::fuzz::writeFile;

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    privateFolder("gltf");
    unsigned char buffer[64] = {};
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::memcpy(buffer, positions, sizeof positions);
    std::memcpy(buffer + 36, indices, sizeof indices);
    writeFile(privateFolder() / "buffer.bin", buffer, sizeof buffer);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::filesystem::path path = privateFolder() / (binary ? "input.glb" : "input.gltf");
    writeFile(path, data, size);
    try {
        (void)swell::detail::loadGltf(path);
    } catch (const swell::InputError&) {
    }
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return 0;
}
