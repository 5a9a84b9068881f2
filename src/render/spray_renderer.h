// The spray (shaders/spray_clumps.comp, bow_spray_clumps.comp, spray.vert),
// drawn in the main pass after the water: torn from the breaking crests of
// a wave model whose crests break (WaveModelGpu::crestSpray, its amount
// growing with that model's wind from Beaufort 7) and thrown from the bows
// of the bodies under way (the scene's wind); none below Beaufort 7. Blended, depth-tested against the world and
// the water, writing no depth. Every particle is a function of the
// simulated time (and, for the bows' spray, of the bodies' steps up to it).
// Library-internal.
#pragma once

#include "render/programs.h"
#include "render/spray_buffers.h"
#include "swell/scene/scene.h"
#include "swell/view.h"
#include "swell/wave_model_gpu.h"

namespace swell::detail {

struct RenderContext;
struct ViewFrame;
class Telemetry;

class SprayRenderer {
public:
    void draw(RenderContext& context, const ViewFrame& v, const View& view);
    // Gives back the buffers a scene that draws no such spray does not need
    // (the crests' 39 MB of streaks among them).
    void releaseUnused(const Scene& scene, const WaveModelGpu& model, const Programs& programs);

private:
    void drawCrests(RenderContext& context, const ViewFrame& v, const View& view);
    void drawBows(RenderContext& context, const ViewFrame& v);
    // A spray pass's steps, its clumps' uniforms set (render/spray_buffers.h).
    static void drawClumps(Telemetry& telemetry, const SprayPasses& passes, SprayBuffers& buffers, long long slots,
                           long long capacity, long long recordBytes, int strips);

    // The clumps, their list and their draw's command, the crests' and the bows'.
    SprayBuffers crestBuffers_, bowBuffers_;
};

} // namespace swell::detail
