// libFuzzer target for the sweep reader (swell/dataset/sweep.h) and what a sweep's
// samples are checked by before anything is made (`swell dataset`).
// Each input is the text of sweep.toml in a private temporary folder that
// also holds base.toml (a small valid scene: a floating boat under way, a
// buoy, the wind's waves), and is taken through loadSweepFile, its scene's
// file (sweepSceneFile), checkSweep against the base scene, and its first
// samples: drawn, validated (validateScene), their lens checked at the
// sweep's size and their history's cost. InputError is the expected result
// for bad input; anything else is a bug, and so are
//   - a scene file resolved outside the sweep's folder,
//   - a sample of a sweep checkSweep accepted holding a value outside its
//     parameter's range (checkSweep vouches for every value drawn),
//   - a refusal of a sample that names no place (no file).
#include "fuzz_support.h"

#include "swell/dataset/sensor.h"
#include "swell/dataset/sweep.h"
#include "swell/error.h"
#include "swell/frame_request.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kBase = R"([waves.wind]
speed_mps = 9.0

[[objects]]
path = "builtin:boat"
floats = true
mass_kg = 2500.0
velocity_m_per_s = [0.0, 0.0, -4.0]

[[objects]]
path = "builtin:buoy"
position_m = [8.0, 0.0, -40.0]
)";

// Samples checked an input: enough to reach every key's stream, few enough
// to keep each input fast.
constexpr int kSamples = 4;

swell::Scene& base()
{
    static swell::Scene scene;
    return scene;
}

const fs::path& folder() { return swell::fuzz::privateFolder(); }

[[noreturn]] void bug(const char* what, const std::string& detail) { swell::fuzz::bug("fuzz_sweep", what, detail); }

void checkSample(const swell::Sweep& sweep, int index)
{
    const swell::SweepSample sample = swell::sweepSample(sweep, base(), index);
    for (const swell::SweepKey& k : sweep.vary) {
        const swell::Parameter* p = swell::sweptParameter(k.key);
        // Numbers only: a vector in range component by component may still
        // be too short to be a direction, which the sample's own check refuses.
        if (!p || (p->kind != swell::ParameterKind::Real && p->kind != swell::ParameterKind::Integer))
            continue;
        // The key as the scene writes it (an item's index read back as written).
        const swell::ParameterValue v = swell::sweptValue(sample.scene, k.key);
        if (const std::string problem = swell::valueProblem(*p, v, k.key); !problem.empty())
            bug("a sample of an accepted sweep holds a value outside its range:", problem);
    }
    try {
        swell::validateScene(sample.scene, folder() / "base.toml");
        if (sweep.size.x <= 256 && sweep.size.y <= 256) // the lens's border walk is as long as the image's
            swell::checkLens(sample.scene, sweep.size, sample.scene.camera.fovY_deg, folder() / "base.toml");
    } catch (const swell::InputError& e) {
        if (e.place().path.empty())
            bug("a sample refused at no place:", e.what());
    }
    (void)swell::historyProblem(sample.scene, sample.time_s);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    std::ofstream(swell::fuzz::privateFolder("sweep") / "base.toml") << kBase;
    base() = swell::loadScene(folder() / "base.toml");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const fs::path path = folder() / "sweep.toml";
    swell::fuzz::writeFile(path, data, size);
    swell::Sweep sweep;
    try {
        sweep = swell::loadSweepFile(path);
        if (const std::optional<fs::path> file = swell::sweepSceneFile(sweep)) {
            const fs::path inside = fs::weakly_canonical(*file).lexically_relative(fs::weakly_canonical(folder()));
            if (inside.empty() || *inside.begin() == "..")
                bug("a sweep's scene resolved outside its folder:", file->string());
        }
        swell::checkSweep(sweep, base());
    } catch (const swell::InputError&) {
        return 0;
    }
    for (int i = 0; i < std::min(sweep.count, kSamples); ++i)
        checkSample(sweep, i);
    return 0;
}
