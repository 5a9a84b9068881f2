// `swell bench`: what each pass of a frame costs (wall time around glFinish,
// GPU time on real GPUs, pipeline statistics), and the floor frame that does
// the same passes with trivial shading.
#include "bench.h"

#include "core/thread_cpu.h"

#include "swell/error.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/gpu/contact.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <array>

namespace swell::app::bench {

namespace {

using Clock = std::chrono::steady_clock;
using detail::processCpu_ms;

double millisecondsBetween(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double, std::milli>(b - a).count();
}

std::uint64_t queryResult(const gl::Query& query)
{
    GLuint64 value = 0;
    glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &value);
    return value;
}

} // namespace

PassCounters& PassCounters::operator+=(const PassCounters& o)
{
    vertexShaderInvocations += o.vertexShaderInvocations;
    fragmentShaderInvocations += o.fragmentShaderInvocations;
    primitivesSubmitted += o.primitivesSubmitted;
    clippingInputPrimitives += o.clippingInputPrimitives;
    clippingOutputPrimitives += o.clippingOutputPrimitives;
    samplesPassed += o.samplesPassed;
    return *this;
}

const PassSample* FrameSample::find(const std::string& name) const
{
    for (const PassSample& p : passes)
        if (p.name == name)
            return &p;
    return nullptr;
}

// One query object per kind; each is begun and ended once per pass segment
// and read right away (the glFinish before has made the result available).
struct PassRecorder::Queries {
    bool statistics = false, timers = false;
    gl::Query samples, time;
    // Pipeline statistics, in the order of kStatisticTargets.
    std::array<gl::Query, 5> statistic;
    static constexpr std::array<GLenum, 5> kStatisticTargets{
        GL_VERTEX_SHADER_INVOCATIONS_ARB, GL_FRAGMENT_SHADER_INVOCATIONS_ARB, GL_PRIMITIVES_SUBMITTED_ARB,
        GL_CLIPPING_INPUT_PRIMITIVES_ARB, GL_CLIPPING_OUTPUT_PRIMITIVES_ARB};
};

PassRecorder::PassRecorder(bool pipelineStatistics, bool gpuTimers, bool stages)
    : queries_(std::make_unique<Queries>()), stages_(stages)
{
    Queries& q = *queries_;
    q.statistics = pipelineStatistics;
    q.timers = gpuTimers;
    q.samples = gl::Query::create(GLenum(GL_SAMPLES_PASSED));
    if (q.timers)
        q.time = gl::Query::create(GLenum(GL_TIME_ELAPSED));
    // Mesa's glCreateQueries refuses the pipeline statistics targets in a 4.5
    // context; a generated name takes its target at the first glBeginQuery.
    if (q.statistics)
        for (gl::Query& query : q.statistic) {
            GLuint name = 0;
            glGenQueries(1, &name);
            query = gl::Query(name);
        }
}

PassRecorder::~PassRecorder() = default;

void PassRecorder::beginFrame()
{
    frame_ = {};
    open_.clear();
    ignoredDepth_ = 0;
    glFinish();
    frameStart_ = Clock::now();
    frameCpuStart_ms_ = processCpu_ms();
}

FrameSample PassRecorder::endFrame()
{
    if (!open_.empty())
        throw Error(fmt::format("swell bench: pass '{}' never ended", frame_.passes[open_.back().index].name));
    glFinish();
    frame_.wall_ms = millisecondsBetween(frameStart_, Clock::now());
    frame_.cpu_ms = processCpu_ms() - frameCpuStart_ms_;
    return std::move(frame_);
}

void PassRecorder::startQueries()
{
    Queries& q = *queries_;
    glBeginQuery(GL_SAMPLES_PASSED, q.samples.id());
    if (q.timers)
        glBeginQuery(GL_TIME_ELAPSED, q.time.id());
    if (q.statistics)
        for (size_t i = 0; i < q.statistic.size(); ++i)
            glBeginQuery(Queries::kStatisticTargets[i], q.statistic[i].id());
}

void PassRecorder::stopQueries(size_t index)
{
    Queries& q = *queries_;
    glEndQuery(GL_SAMPLES_PASSED);
    if (q.timers)
        glEndQuery(GL_TIME_ELAPSED);
    if (q.statistics)
        for (GLenum target : Queries::kStatisticTargets)
            glEndQuery(target);

    PassSample& pass = frame_.passes[index];
    PassCounters c;
    c.samplesPassed = queryResult(q.samples);
    if (q.statistics) {
        c.vertexShaderInvocations = queryResult(q.statistic[0]);
        c.fragmentShaderInvocations = queryResult(q.statistic[1]);
        c.primitivesSubmitted = queryResult(q.statistic[2]);
        c.clippingInputPrimitives = queryResult(q.statistic[3]);
        c.clippingOutputPrimitives = queryResult(q.statistic[4]);
    }
    pass.counters += c;
    if (q.timers)
        pass.gpu_ms = pass.gpu_ms.value_or(0.0) + double(queryResult(q.time)) * 1.0e-6;
}

void PassRecorder::beginPass(const char* name)
{
    if (ignoredDepth_ > 0 || (!stages_ && !open_.empty() && frame_.passes[open_.back().index].name == "ocean")) {
        ++ignoredDepth_;
        return;
    }
    glFinish();
    if (!open_.empty())
        stopQueries(open_.back().index);
    PassSample pass;
    pass.name = name;
    pass.depth = int(open_.size());
    if (!open_.empty())
        pass.parent = frame_.passes[open_.back().index].name;
    frame_.passes.push_back(std::move(pass));
    open_.push_back({frame_.passes.size() - 1, Clock::now(), processCpu_ms()});
    startQueries();
}

void PassRecorder::endPass(const char* name)
{
    if (ignoredDepth_ > 0) {
        --ignoredDepth_;
        return;
    }
    if (open_.empty() || frame_.passes[open_.back().index].name != name)
        throw Error(fmt::format("swell bench: pass '{}' ended but was not the one running", name));
    glFinish();
    const Clock::time_point end = Clock::now();
    const double cpuEnd_ms = processCpu_ms();
    const Open open = open_.back();
    open_.pop_back();
    stopQueries(open.index);
    const PassSample& pass = frame_.passes[open.index];
    frame_.passes[open.index].wall_ms = millisecondsBetween(open.start, end);
    frame_.passes[open.index].cpu_ms = cpuEnd_ms - open.cpuStart_ms;
    if (!open_.empty()) {
        // The outer pass includes this one.
        PassSample& outer = frame_.passes[open_.back().index];
        outer.counters += pass.counters;
        if (pass.gpu_ms)
            outer.gpu_ms = outer.gpu_ms.value_or(0.0) + *pass.gpu_ms;
        startQueries();
    }
}

namespace {

// One full-screen triangle at a depth set by uniform 0, in a constant colour.
const char* const kFloorVertex = R"(
layout(location = 0) uniform float uDepth;
void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    gl_Position = vec4(p, uDepth, 1.0);
}
)";
const char* const kFloorFragment = R"(
out vec4 fragColor;
void main() { fragColor = vec4(0.2, 0.4, 0.6, 1.0); }
)";

} // namespace

OffscreenTarget makeOffscreenTarget(glm::ivec2 size, GLenum colorFormat)
{
    OffscreenTarget t;
    t.size = size;
    t.color = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(t.color.id(), 1, colorFormat, size.x, size.y);
    t.depth = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(t.depth.id(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
    t.framebuffer = gl::Framebuffer::create();
    glNamedFramebufferTexture(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, t.color.id(), 0);
    glNamedFramebufferTexture(t.framebuffer.id(), GL_DEPTH_ATTACHMENT, t.depth.id(), 0);
    if (glCheckNamedFramebufferStatus(t.framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("swell bench: offscreen framebuffer incomplete");
    return t;
}

struct FloorFrame::State {
    gl::Program program;
    gl::VertexArray vao;
    OffscreenTarget contact, reflection, refraction, waterline, output, presented;
    bool present = false;
    bool waterInTwoPasses = false;

    // The state the renderer's passes set, then a clear.
    void bind(const OffscreenTarget& t) const
    {
        glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
        glViewport(0, 0, t.size.x, t.size.y);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CLIP_DISTANCE0);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    void triangle(float depth) const
    {
        glUseProgram(program.id());
        glUniform1f(0, depth);
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
};

FloorFrame::FloorFrame(glm::ivec2 passSize, glm::ivec2 mainSize, glm::ivec2 outputSize, bool present,
                       bool waterInTwoPasses)
    : state_(std::make_unique<State>())
{
    const gl::ShaderSources sources = gl::ShaderSources::fromMap({{"floor.vert", kFloorVertex}, {"floor.frag", kFloorFragment}});
    state_->program = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "floor.vert"}, {GL_FRAGMENT_SHADER, "floor.frag"}});
    state_->vao = gl::VertexArray::create();
    // The contact pass's map (swell/gpu/contact.h): its depth, with an R8
    // colour the offscreen target brings along.
    state_->contact = makeOffscreenTarget(glm::ivec2(SWELL_CONTACT_SIZE), GL_R8);
    state_->reflection = makeOffscreenTarget(passSize, GL_RGBA16F);
    state_->refraction = makeOffscreenTarget(passSize, GL_RGBA16F);
    state_->waterline = makeOffscreenTarget(mainSize, GL_R8);
    state_->output = makeOffscreenTarget(mainSize, GL_RGBA8);
    state_->present = present;
    state_->waterInTwoPasses = waterInTwoPasses;
    if (present)
        state_->presented = makeOffscreenTarget(outputSize, GL_RGBA8);
}

FloorFrame::~FloorFrame() = default;

void FloorFrame::render(PassObserver& observer, bool occasional)
{
    const State& s = *state_;
    // The wave model's own work for the frame: at the least, none.
    observer.beginPass("ocean");
    observer.endPass("ocean");
    observer.beginPass("bodies");
    observer.endPass("bodies");
    observer.beginPass("wake");
    observer.endPass("wake");
    observer.beginPass("queries");
    observer.endPass("queries");

    // The contact foam's pass, drawn only where something stands in the
    // water near the eye: its map cleared and covered.
    if (occasional) {
        observer.beginPass("contact");
        s.bind(s.contact);
        s.triangle(0.5f);
        observer.endPass("contact");
    }

    observer.beginPass("reflection");
    s.bind(s.reflection);
    s.triangle(0.5f);
    observer.endPass("reflection");

    observer.beginPass("refraction");
    s.bind(s.refraction);
    s.triangle(0.5f);
    observer.endPass("refraction");

    // The waterline mask, drawn only when the camera is in the waves: its
    // full-size R8 target.
    if (occasional) {
        observer.beginPass("waterline");
        s.bind(s.waterline);
        s.triangle(0.5f);
        observer.endPass("waterline");
    }

    // The water's stand-in lies in front of the first triangle, so it passes
    // the depth test like the visible water does.
    observer.beginPass("main");
    s.bind(s.output);
    s.triangle(0.5f);
    observer.beginPass("water");
    if (s.waterInTwoPasses) {
        observer.beginPass("water visibility");
        s.triangle(0.0f);
        observer.endPass("water visibility");
        observer.beginPass("water shading");
        s.triangle(-0.5f);
        observer.endPass("water shading");
    } else {
        s.triangle(0.0f);
    }
    observer.endPass("water");
    observer.endPass("main");
    if (s.present) {
        observer.beginPass("present");
        const glm::ivec2 from = s.output.size, to = s.presented.size;
        glBlitNamedFramebuffer(s.output.framebuffer.id(), s.presented.framebuffer.id(), 0, 0, from.x, from.y, 0, 0, to.x,
                               to.y, GL_COLOR_BUFFER_BIT, from == to ? GL_NEAREST : GL_LINEAR);
        observer.endPass("present");
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace swell::app::bench
