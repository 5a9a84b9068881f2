// The coast and the harbour presets, as judged by eye and then frozen: a
// swell shoaling and breaking on a 1:40 beach, its surf, wet sand and
// shallows; a breakwater's lee, calm but for what diffracts round its head.
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <filesystem>

namespace {

class CoastPresetsGolden : public swell::test::GlTest {};

swell::Image presetStill(const char* name, double time_s)
{
    const swell::Scene scene = swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / name);
    swell::Renderer renderer(scene);
    return renderer.renderImage(swell::cameraAt(scene.camera, time_s), time_s, {320, 180});
}

// The slack, as the default scene's: llvmpipe renders the same pixels for
// the same inputs on one machine; another CPU's math library and SIMD width
// move a few pixels on wave edges by a few levels.
TEST_F(CoastPresetsGolden, TheCoastMatchesTheJudgedImage)
{
    swell::test::expectMatchesGolden(presetStill("coast.toml", 20.0), "coast_preset", 48, 0.6);
}

TEST_F(CoastPresetsGolden, TheHarbourMatchesTheJudgedImage)
{
    swell::test::expectMatchesGolden(presetStill("harbour.toml", 20.0), "harbour_preset", 48, 0.6);
}

} // namespace
