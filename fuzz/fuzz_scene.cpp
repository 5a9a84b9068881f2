// libFuzzer target for the scene parser and validator (swell/scene/scene_file.h).
// Each input is parsed as scene TOML with parseScene, as if it were the file
// input.toml in a private temporary folder. InputError is the expected
// outcome for bad input; a crash, a sanitizer report or any other exception
// is a bug. A scene that parses must also:
//   - pass validateScene (the two share their checks; disagreement is a bug),
//   - save with saveScene to TOML that parseScene reads back without error
//     (the viewer saves what it loaded; a scene it cannot reload is a bug).
// The folder holds model.gltf and model.glb (empty files: only their
// existence is checked), so inputs can reach the object-path checks.
#include "fuzz_support.h"

#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using swell::fuzz::privateFolder;

[[noreturn]] void bug(const char* what, const std::string& detail) { swell::fuzz::bug("fuzz_scene", what, detail); }

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    std::ofstream(privateFolder("scene") / "model.gltf");
    std::ofstream(privateFolder() / "model.glb");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const fs::path path = privateFolder() / "input.toml";
    swell::Scene scene;
    try {
        scene = swell::parseScene(text, path);
    } catch (const swell::InputError&) {
        return 0;
    }
    try {
        swell::validateScene(scene, path);
    } catch (const swell::InputError& e) {
        bug("validateScene rejects a scene that parseScene accepted:", e.what());
    }
    const std::string saved = swell::saveScene(scene);
    try {
        (void)swell::parseScene(saved, path);
    } catch (const swell::InputError& e) {
        bug("parseScene rejects what saveScene wrote:", std::string(e.what()) + "\n--- saved ---\n" + saved);
    }
    return 0;
}
