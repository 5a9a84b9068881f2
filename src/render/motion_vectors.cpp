// The host's motion vectors (render/motion_vectors.h).
#include "render/motion_vectors.h"

#include "render/frame_uniforms.h"
#include "render/scene_world.h"
#include "swell/gpu/bindings.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace swell::detail {

namespace {

// The colour attachments the output framebuffer draws into now, to be put
// back after the motion pass draws into its own attachment alone.
class DrawBuffersScope {
public:
    explicit DrawBuffersScope(GLuint framebuffer) : framebuffer_(framebuffer)
    {
        GLint most = 0;
        glGetIntegerv(GL_MAX_DRAW_BUFFERS, &most);
        count_ = std::min<GLsizei>(GLsizei(most), GLsizei(buffers_.size()));
        // A framebuffer's draw buffers are read with it bound for drawing.
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
        for (GLsizei i = 0; i < count_; ++i) {
            GLint buffer = GL_NONE;
            glGetIntegerv(GLenum(GL_DRAW_BUFFER0 + i), &buffer);
            buffers_[std::size_t(i)] = GLenum(buffer);
        }
    }
    ~DrawBuffersScope() { glNamedFramebufferDrawBuffers(framebuffer_, count_, buffers_.data()); }
    DrawBuffersScope(const DrawBuffersScope&) = delete;
    DrawBuffersScope& operator=(const DrawBuffersScope&) = delete;

private:
    GLuint framebuffer_;
    std::array<GLenum, 8> buffers_{};
    GLsizei count_ = 0;
};

// The surfaces drawn again must pass the depth test on the depth the
// passes wrote for them, and nowhere behind it. Drawn straight into the
// host's framebuffer they rasterise as the passes did, but for the last
// bits (the water drawn in two passes rasterises in a target of its own,
// at another viewport origin): they are moved toward the eye by 16 of the
// depth format's least steps. Through the view's own target (a render
// scale, MSAA, the temporal resolve) the depth written back was rasterised
// at another resolution or resolved from samples: one depth slope more.
// Where two surfaces lie closer than that, the one drawn later writes its
// vector (the world after the water). A slope tolerance straight in would
// let a face seen edge-on pass from far behind (a hull's other side).
void moveTowardEye(const DepthConvention& depth, bool throughTarget)
{
    const float toward = depth.test == GL_GREATER || depth.test == GL_GEQUAL ? 1.0f : -1.0f;
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(throughTarget ? toward : 0.0f, 16.0f * toward);
}

// The sky's vectors, over the whole viewport: where the depth test passes
// at the far plane, or (hostDepth not 0) where the host's depth's copy is
// at the far plane.
void drawSky(RenderContext& context, const MotionPrograms& programs, const glm::mat4& previousViewProj, bool moves,
             GLuint hostDepth)
{
    programs.sky.use();
    programs.sky.setPreviousViewProj(previousViewProj, moves);
    programs.sky.setReadsHostDepth(hostDepth != 0);
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, hostDepth);
    glBindVertexArray(context.resources.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, 0);
    ++context.telemetry.counters.motionVectorDraws;
}

} // namespace

void MotionVectors::placePreviousWater(RenderContext& context, const ViewFrame& v, std::optional<double> previous_s)
{
    Resources& resources = context.resources;
    WaveModelGpu& model = context.simulation.gpu();
    const std::size_t bytes = std::size_t(resources.waterVertexCount()) * 4 * sizeof(float);
    if (bytes != previousWaterBytes_) {
        previousWater_ = gl::Buffer::create();
        glNamedBufferStorage(previousWater_.id(), GLsizeiptr(bytes), nullptr, 0);
        previousWaterBytes_ = bytes;
    }
    // The model at the previous time where it can give it; else (a first
    // draw, a model that cannot) the current surface: the water still.
    if (previous_s && model.prepareEarlierView(v.gridCenter_m, *previous_s))
        model.bind();
    programs_->waterPrevious.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_PREVIOUS, previousWater_.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(resources.emptyVao.id());
    glDrawArrays(GL_POINTS, 0, resources.waterVertexCount());
    glDisable(GL_RASTERIZER_DISCARD);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    ++context.telemetry.counters.motionVectorDraws;
    // The current time again, for whatever draws next.
    model.prepareView(v.gridCenter_m);
    context.telemetry.addWork(model.takeWork(), context.telemetry.counters.viewsGpu);
    context.simulation.bindForWater();
}

void MotionVectors::draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request)
{
    const ObservedPass observed(context.telemetry, "motion vectors");
    MotionHistory& history = state.motion;
    updateMotionPrograms(context.resources.sources, programs_, context.resources.programs.flags);
    const Simulated& simulated = context.simulation.require();
    const double now_s = simulated.time_s;
    // The host's own view and projection (unjittered by Swell's resolve).
    const glm::dmat4 viewProj = request.unjitteredViewProj.value_or(request.view.projection * request.view.view);
    // The view moves on from its last draw: else (its first, a time before
    // the last, or a gap too long) every vector is zero.
    const bool continues = history.drawn && now_s >= history.time_s &&
                           now_s - history.time_s <= kMotionVectorLongestGap_s;
    const glm::dmat4 toOrigin = glm::translate(glm::dmat4(1.0), context.simulation.sea().toWorld(v.origin));
    const glm::mat4 previousViewProj((continues ? history.viewProj : viewProj) * toOrigin);
    const glm::dmat4 fromOrigin = glm::translate(glm::dmat4(1.0), -v.origin);
    std::vector<glm::mat4> previousPoses(v.poses);
    for (std::size_t i = 0; continues && i < previousPoses.size() && i < history.poses.size(); ++i)
        previousPoses[i] = glm::mat4(fromOrigin * history.poses[i]);

    placePreviousWater(context, v, continues ? std::optional<double>(history.time_s) : std::nullopt);

    PassState pass;
    pass.slot = PassMain;
    pass.frame = v.base;
    pass.frame.passViewProj = pass.frame.cameraViewProj = glm::mat4(viewProj * toOrigin);
    pass.frame.passInvViewProj = pass.frame.cameraInvViewProj = glm::mat4(glm::inverse(viewProj * toOrigin));
    setViewport(pass.frame, request.outputSize());
    pass.frame.viewportOrigin = glm::vec2(request.outputViewport.x, request.outputViewport.y);
    pass.framebuffer = request.output;
    pass.viewport = request.outputViewport;
    pass.depth = v.depth;
    pass.begin(context.resources, context.telemetry);
    const DrawBuffersScope drawBuffers(request.output);
    const GLenum attachment = GLenum(request.options.motionVectors);
    glNamedFramebufferDrawBuffers(request.output, 1, &attachment);
    glDepthMask(GL_FALSE);
    glDepthFunc(v.depth.testOrFar);
    FrameCounters& counters = context.telemetry.counters;
    const MotionPrograms& programs = *programs_;

    // Through the view's own target, the sky first wherever the host drew
    // nothing (its depth's copy); the surfaces then write over it.
    const bool skyFirst = request.options.sky && request.throughTarget();
    if (skyFirst) {
        glDepthFunc(GL_ALWAYS);
        drawSky(context, programs, previousViewProj, continues, state.hostPictureDepth.texture());
        glDepthFunc(v.depth.testOrFar);
    }
    moveTowardEye(v.depth, request.throughTarget());
    programs.water.use();
    programs.water.setPreviousViewProj(previousViewProj, continues);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_PREVIOUS, previousWater_.id());
    glBindVertexArray(context.resources.waterGrid.vertexArray());
    counters.motionVectorTriangles += context.resources.waterGrid.draw();
    ++counters.motionVectorDraws;

    if (request.options.sceneWorld) {
        // Swell's world drawn again with the motion program: its meshes'
        // counters are the main pass's already, so it counts into a copy.
        FrameCounters worldCounters{};
        SceneWorld world(context.resources.world, programs.mesh, programs.mesh, v.poses, v.island, v.seabed,
                         worldCounters);
        world.setIslandTolerance(context.islandTolerance_px);
        world.setPreviousPoses(&previousPoses);
        programs.mesh.setPreviousViewProj(previousViewProj, continues);
        PassView view;
        view.pass = PassKind::Main;
        view.view = request.view.view;
        view.projection = request.view.projection;
        view.viewport = request.outputViewport;
        view.depth = request.view.depth;
        view.eye_m = request.view.eye_m();
        // The open hulls' lids first, which hide the water inside them and
        // move with their hulls; the meshes drawn after them write their
        // own points wherever they pass the test too.
        view.pass = PassKind::WaterMask;
        world.drawPass(view);
        view.pass = PassKind::Main;
        world.drawPass(view);
        counters.motionVectorTriangles += worldCounters.worldTriangles;
        counters.motionVectorDraws += worldCounters.drawCalls;
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 0.0f);

    // Straight in, the sky last where the depth is still at the far plane.
    if (request.options.sky && !skyFirst)
        drawSky(context, programs, previousViewProj, continues, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_PREVIOUS, 0);
    setPassState(pass.viewport, pass.depth);

    history.drawn = true;
    history.time_s = now_s;
    history.viewProj = viewProj;
    history.poses = simulated.poses;
    // A spectral sea keeps its step before from now on, for the next draw.
    context.simulation.gpu().keepPreviousStep(true);
}

} // namespace swell::detail
