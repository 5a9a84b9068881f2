#include "render/spray_renderer.h"

#include "render/gl_state.h"
#include "render/view_frame.h"

#include "swell/gpu/bindings.h"
#include "swell/gpu/spray.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace swell::detail {

namespace {

// The crests' slots: every cell's of the lattice, in whole workgroups.
constexpr long long kCrestSlots = SWELL_SPRAY_CELLS * SWELL_SPRAY_CELLS * SWELL_SPRAY_SLOTS;
static_assert(kCrestSlots % SWELL_SPRAY_GROUP == 0 && SWELL_BOW_SPRAY_SLOTS % SWELL_SPRAY_GROUP == 0);
// The streaks a living clump draws: its drops' (the bow's: its piece of
// sheet's too; spray_clump.glsl's SPRAY_STRIPS).
constexpr int kCrestStrips = SWELL_SPRAY_DROPS;
constexpr int kBowStrips = SWELL_BOW_SPRAY_DROPS + 1;

// Whether a wind of windSpeed_mps tears spray (Beaufort 7 and up), in a
// scene that shows it.
bool sprayAt(const Scene& scene, double windSpeed_mps)
{
    return scene.water.spray && scene.debugView == DebugView::Shaded && windSpeed_mps >= SWELL_SPRAY_ONSET_WIND_MPS;
}

// The wind over the crests' spray: the wave model's, whose crests break
// (WaveModelGpu::crestSpray); none for a model whose crests do not.
std::optional<double> crestSprayWind_mps(const Scene& scene, const WaveModelGpu& model)
{
    const std::optional<WaveModelGpu::CrestSpray> crests = model.crestSpray();
    if (!crests || !sprayAt(scene, crests->windSpeed_mps))
        return std::nullopt;
    return crests->windSpeed_mps;
}

// The wind over the bows' spray: the air's, as the scene gives it. The
// bow's sheet is torn by the wind over it, whatever draws the waves: a
// Gerstner sum of listed waves or a host's own model has no wind of its
// own to say, so the scene does (the crests' spray, which only a model
// whose crests break throws, takes the wind that model was made for).
std::optional<WindSettings> bowSprayWind(const Scene& scene)
{
    if (!scene.sea.wind || !sprayAt(scene, scene.sea.wind->windSpeed_mps))
        return std::nullopt;
    return scene.sea.wind;
}

} // namespace

// A spray pass's steps, its clumps' uniforms set (render/spray_buffers.h):
// every slot's clump, the list of the living and the commands, the living
// clumps' streaks, then one draw of their strips. The GPU alone knows how
// many live; the commands it wrote say.
void SprayRenderer::drawClumps(Telemetry& telemetry, const SprayPasses& passes, SprayBuffers& buffers,
                               long long slots, long long capacity, long long recordBytes, int strips)
{
    buffers.bind(capacity, recordBytes, strips);
    passes.useClumps();
    glDispatchCompute(GLuint(slots / SWELL_SPRAY_GROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    passes.useList(int(slots));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    passes.useStreaks();
    glDispatchComputeIndirect(GLintptr(kSprayDispatchOffset));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    releaseProgramStages(); // compute, then a draw (render/gl_state.h)
    passes.useDraw();
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
    ++telemetry.counters.drawCalls;
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    releaseProgramStages();
    Telemetry::addWork(sprayPassWork(slots, recordBytes), telemetry.counters.viewsGpu);
}

void SprayRenderer::releaseUnused(const Scene& scene, const WaveModelGpu& model, const Programs& programs)
{
    if (!crestSprayWind_mps(scene, model) || !programs.spray)
        crestBuffers_ = {};
    if (!bowSprayWind(scene) || scene.objects.empty())
        bowBuffers_ = {};
}

void SprayRenderer::draw(RenderContext& context, const ViewFrame& v, const View& view)
{
    if (!crestSprayWind_mps(context.scene, context.simulation.gpu()) && !bowSprayWind(context.scene))
        return;
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glDepthMask(GL_FALSE);
    glBindVertexArray(context.resources.emptyVao.id());
    drawCrests(context, v, view);
    drawBows(context, v);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

// The spray torn from the breaking crests: its amount grows with the wind
// from Beaufort 7 to Beaufort 10.
void SprayRenderer::drawCrests(RenderContext& context, const ViewFrame& v, const View& view)
{
    const Programs& programs = context.resources.programs;
    const std::optional<double> wind = crestSprayWind_mps(context.scene, context.simulation.gpu());
    if (!programs.spray || !wind)
        return;
    const double wind_mps = *wind;
    const double amount = std::clamp((wind_mps - SWELL_SPRAY_ONSET_WIND_MPS) /
                                         (SWELL_SPRAY_FULL_WIND_MPS - SWELL_SPRAY_ONSET_WIND_MPS), 0.0, 1.0);
    if (amount <= 0.0)
        return;
    const ObservedPass observed(context.telemetry, "spray");
    // The lattice, its cells fixed in the world, ahead of the eye: its
    // centre 0.45 of its width along the view's heading (level), so that it
    // reaches just behind the eye and most of its slots lie in view.
    const double cell_m = SWELL_SPRAY_CELL_M;
    const glm::dvec2 eye(v.origin.x, v.origin.z);
    const glm::dvec2 forward(-view.view[0][2], -view.view[2][2]);
    const double level = glm::length(forward);
    const glm::dvec2 ahead = level > 1e-6 ? forward / level * (0.45 * SWELL_SPRAY_CELLS * cell_m) : glm::dvec2(0.0);
    const glm::dvec2 first = glm::floor((eye + ahead) / cell_m) - glm::dvec2(SWELL_SPRAY_CELLS / 2);
    const glm::vec2 corner_m(first * cell_m - eye);
    programs.spray.set(context.simulation.require().time_s, glm::ivec2(first), corner_m, corner_m - v.base.gridCenter,
                       float(wind_mps), float(amount));
    context.simulation.gpu().bind();
    drawClumps(context.telemetry, programs.spray, crestBuffers_, kCrestSlots, kCrestSlots, kSprayClumpBytes,
               kCrestStrips);
}

// The spray thrown from the bows of the first SWELL_BOW_SPRAY_HULLS bodies
// under way (objects/bow_spray.h): their bows' waterlines where the frame's
// poses put them, and each hull's samples over the last lifetime; nothing
// when no body is under way.
void SprayRenderer::drawBows(RenderContext& context, const ViewFrame& v)
{
    const Programs& programs = context.resources.programs;
    const std::optional<WindSettings> wind = bowSprayWind(context.scene);
    if (!programs.bowSpray || !wind)
        return;
    const Simulated& simulated = context.simulation.require();
    const SceneBodies& bodies = context.simulation.bodies();
    BowSprayHulls hulls;
    double lag_s = 0.0;
    const glm::dmat4 fromSea = glm::translate(glm::dmat4(1.0), -v.origin);
    for (std::size_t i = 0; i < context.simulation.seaScene().objects.size() && hulls.count < SWELL_BOW_SPRAY_HULLS;
         ++i) {
        const SceneBodies::Bow* bow = bodies.bow(i);
        if (!bow || i >= simulated.poses.size())
            continue;
        const int h = hulls.count++;
        const glm::dmat4 pose = fromSea * simulated.poses[i];
        glm::dvec2 side[2];
        for (int s = 0; s < 2; ++s)
            for (int k = 0; k < SWELL_BOW_SPRAY_STATIONS; ++k) {
                const glm::dvec3 p(pose * glm::dvec4(bow->stationsInModel[s][k], 1.0));
                hulls.stations[std::size_t((h * 2 + s) * SWELL_BOW_SPRAY_STATIONS + k)] = glm::vec2(p.x, p.z);
                side[s] = glm::dvec2(p.x, p.z);
            }
        // Out from the keel towards the first side: across the hull at its
        // last station, level, as the pose has it now.
        const glm::dvec2 out = side[0] - side[1];
        const double speed_mps = glm::length(bow->velocity_m_per_s);
        const glm::dvec2 heading = bow->velocity_m_per_s / speed_mps;
        const glm::dvec2 across = glm::length(out) > 1e-6 ? out / glm::length(out) : glm::dvec2(-heading.y, heading.x);
        hulls.body[std::size_t(h)] = int(i);
        hulls.motion[std::size_t(h)] = glm::vec4(glm::vec2(bow->velocity_m_per_s), glm::vec2(heading));
        hulls.across[std::size_t(h)] = glm::vec4(glm::vec2(across), float(speed_mps), float(bow->line.flareCot));
        const std::array<BowSample, SWELL_BOW_SPRAY_HISTORY> history = bodies.bowHistory(i, simulated.time_s, lag_s);
        for (int j = 0; j < SWELL_BOW_SPRAY_HISTORY; ++j) {
            const BowSample& b = history[std::size_t(j)];
            hulls.history[std::size_t(h * SWELL_BOW_SPRAY_HISTORY + j)] = glm::vec4(b.share, b.plunge_mps, b.leaves_m, 0.0f);
        }
    }
    if (hulls.count == 0)
        return;
    hulls.historyLag_s = float(lag_s);
    const ObservedPass observed(context.telemetry, "bow spray");
    const double direction_rad = glm::radians(wind->windDirection_deg);
    programs.bowSpray.set(simulated.time_s, glm::vec2(std::cos(direction_rad), std::sin(direction_rad)),
                          float(wind->windSpeed_mps), hulls);
    drawClumps(context.telemetry, programs.bowSpray, bowBuffers_, hulls.count * SWELL_BOW_SPRAY_SLOTS,
               SWELL_BOW_SPRAY_HULLS * SWELL_BOW_SPRAY_SLOTS, kBowSprayClumpBytes, kBowStrips);
}

} // namespace swell::detail
