// `swell bench`: the parts of the GPU benchmark shared between its files.
//   bench_command.cpp  the camera path and the run: real frames, floor, LOD
//   bench_passes.cpp   per-pass wall and CPU time, GPU timers and pipeline
//                      counters; the floor (the same passes, trivial shading)
//   bench_lod.cpp      the water grid's triangles seen from the camera
//   bench_report.cpp   the machine, the text table and the JSON file
//   bench_terms.cpp    what each term of the water shading costs
//   bench_simulation.cpp  the renderer's own counts: the simulation's CPU
//                      time by part, Swell's GPU work per frame
#pragma once

#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/gl/handle.h"
#include "swell/renderer.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json_fwd.hpp>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace swell::app::bench {

// What the driver counted during one pass (GL_ARB_pipeline_statistics_query
// and GL_SAMPLES_PASSED). Exact and deterministic for a given frame.
struct PassCounters {
    std::uint64_t vertexShaderInvocations = 0;
    std::uint64_t fragmentShaderInvocations = 0;
    std::uint64_t primitivesSubmitted = 0;
    std::uint64_t clippingInputPrimitives = 0;
    std::uint64_t clippingOutputPrimitives = 0;
    std::uint64_t samplesPassed = 0;
    PassCounters& operator+=(const PassCounters& other);
};

// One pass of one frame. A pass that contains another ("main" holds
// "water") includes the inner pass in its time and counters.
struct PassSample {
    std::string name;
    double wall_ms = 0.0;          // steady clock between glFinish at begin and end
    double cpu_ms = 0.0;           // process CPU time over the same span (all threads:
                                   // a software rasteriser's workers included)
    std::optional<double> gpu_ms;  // GL_TIME_ELAPSED, only on a real GPU
    PassCounters counters;
    int depth = 0;                 // 0 for a top-level pass, 1 inside another
    std::string parent;            // the pass this one is inside, or empty
};

struct FrameSample {
    double wall_ms = 0.0;          // the whole frame, glFinish before and after
    double cpu_ms = 0.0;           // process CPU time over the same span
    std::vector<PassSample> passes; // in the order they began
    const PassSample* find(const std::string& name) const;
};

// Records each pass of the frames rendered while it observes: glFinish at
// begin and end around a steady clock and the process CPU time clock (which,
// on a machine shared with other work, varies much less than wall time when
// the GPU is a software rasteriser), and, when available, pipeline
// statistics, samples passed and GPU time. GL queries of one kind cannot
// nest, so an outer pass's queries are paused while an inner pass runs and
// the inner results are added to the outer pass afterwards.
class PassRecorder : public PassObserver {
public:
    // pipelineStatistics: the context has GL_ARB_pipeline_statistics_query.
    // gpuTimers: record GL_TIME_ELAPSED (meaningless on software rasterisers).
    // stages: record the passes a wave model names inside "ocean" (its
    // stages); otherwise they are not told apart, and cost no glFinish.
    PassRecorder(bool pipelineStatistics, bool gpuTimers, bool stages = false);
    ~PassRecorder() override;
    PassRecorder(const PassRecorder&) = delete;
    PassRecorder& operator=(const PassRecorder&) = delete;

    // Brackets one frame; `draw` renders it (and tells this recorder its passes).
    template <class Draw>
    FrameSample recordFrame(Draw&& draw)
    {
        beginFrame();
        draw();
        return endFrame();
    }

    void beginPass(const char* name) override;
    void endPass(const char* name) override;

private:
    struct Queries;
    struct Open {
        size_t index;   // into frame_.passes
        std::chrono::steady_clock::time_point start;
        double cpuStart_ms;
    };
    void beginFrame();
    FrameSample endFrame();
    void startQueries();
    // Ends the running queries and adds their results to frame_.passes[index].
    void stopQueries(size_t index);

    std::unique_ptr<Queries> queries_;
    bool stages_ = false;
    int ignoredDepth_ = 0; // passes begun inside "ocean" and not recorded, still open
    std::vector<Open> open_;
    FrameSample frame_;
    std::chrono::steady_clock::time_point frameStart_;
    double frameCpuStart_ms_ = 0.0;
};

// A colour + depth framebuffer, formats as the renderer's: GL_RGBA16F for its
// reflection and refraction images, GL_RGBA8 for the output, 32-bit float depth.
struct OffscreenTarget {
    glm::ivec2 size{0};
    gl::Texture color, depth;
    gl::Framebuffer framebuffer;
};
// Throws swell::Error when the framebuffer is incomplete.
OffscreenTarget makeOffscreenTarget(glm::ivec2 size, GLenum colorFormat);

// The floor: for each pass of the real frame, a target of the same size
// cleared and covered by one full-screen triangle with a constant colour;
// "water" is one more such triangle inside "main" (two, "water visibility"
// and "water shading", when the real frame draws its water in two passes).
// What a frame costs at
// the least on this machine at this size, shading aside. When the real
// frame has a "present" step (anti-aliasing, a render scale), the floor's is
// a plain copy of its main target into the output.
class FloorFrame {
public:
    // Sizes: the reflection and refraction targets, the main pass (the
    // output's at render scale 1), and the output when `present`.
    FloorFrame(glm::ivec2 passSize, glm::ivec2 mainSize, glm::ivec2 outputSize, bool present, bool waterInTwoPasses);
    ~FloorFrame();
    FloorFrame(const FloorFrame&) = delete;
    FloorFrame& operator=(const FloorFrame&) = delete;
    // occasional: also the passes real frames draw only at times: the
    // waterline mask's (the camera in the waves) and the contact foam's
    // (something standing in the water near the eye). The benchmark
    // alternates: the frame's floor (the least) is then one without them,
    // each pass's own floor comes from the frames with them.
    void render(PassObserver& observer, bool occasional);

private:
    struct State;
    std::unique_ptr<State> state_;
};

// The water grid seen from one camera: how many of its triangles reach the
// view frustum, and how large those are on screen.
struct LodSample {
    int frame = 0;                  // measured frame index on the path
    Camera camera;
    long long triangles = 0;        // submitted (the whole grid)
    long long inFrustum = 0;        // at least partly inside the view frustum
    double inFrustumShare = 0.0;    // inFrustum / triangles
    // The water pass's clipper: output / input primitives of the same frame.
    std::optional<double> clipShare;
    std::uint64_t clipInput = 0, clipOutput = 0;
    // Projected area of the in-frustum triangles, px² (the part behind the
    // near plane cut away; the part outside the screen counted).
    double areaP10_px2 = 0.0, areaMedian_px2 = 0.0, areaP90_px2 = 0.0;
    double edgeMedian_px = 0.0;     // longest projected edge, median, px
    double subPixelShare = 0.0;     // share of in-frustum triangles under 1 px²
};

// vertices: captureWaterVertices() output, 8 floats per vertex (restPoint.xz,
// position xyz, normal xyz, relative to the render origin); triangles: the
// vertex indices the frame draws, three per triangle (the tiles in view).
// viewProj: the renderer's, relative to the same origin.
LodSample measureLod(const std::vector<float>& vertices, int vertexCount, const std::vector<std::uint32_t>& triangles,
                     const glm::dmat4& viewProj, glm::ivec2 size);

// minimum, median, p95 (nearest rank) and maximum of a series.
struct Summary {
    double min = 0.0, median = 0.0, p95 = 0.0, max = 0.0;
};
// The floor's cost from its frames: the least. Every floor frame does the
// same work, so what any frame took beyond the least was the machine's other
// load; its median moved by 2x between runs on a shared machine. (The real
// frames differ along the camera path, so they are summarised by the median.)
inline double floorCost(const Summary& floor) { return floor.min; }
Summary summarize(std::vector<double> values);
// Nearest-rank percentile q (0..1) of values, which it reorders.
double percentile(std::vector<double>& values, double q);
// The middle value (the mean of the two middle ones for an even count); 0 when empty.
double median(std::vector<double>& values);

// The water pass of the default scene with each reflection lookup
// (scene.reflection.mode), measured frame for frame in turn on the same
// cameras (bench_reflection.cpp).
struct ReflectionModeCost {
    std::string mode;                  // "fixed" or "raymarch", as scene files write it
    std::vector<double> waterWall_ms;  // per frame
    std::vector<double> waterCpu_ms;
};
std::vector<ReflectionModeCost> measureReflectionModes(const Scene& scene, PassRecorder& recorder, int frames,
                                                       glm::ivec2 size, unsigned framebuffer,
                                                       const std::vector<Camera>& cameras,
                                                       const std::vector<double>& times_s);

// Everything one run found, for the table and the JSON file.
struct Machine {
    std::string cpu;       // "model name" of /proc/cpuinfo
    int cores = 0;
    std::string glRenderer, glVersion;
    std::string commit;    // short hash of the source tree, or "unknown"
};
Machine describeMachine();

// The water shading with terms left out (RendererTesting::create),
// rendered along the same path, each frame right after the full frame of the
// same camera and time so that both see the same load on the machine.
struct TermVariant {
    std::string name;        // "wave normals", ...; "every term" when all are left out
    unsigned omitted = 0;    // SWELL_TERM_* bits
    std::vector<FrameSample> frames; // the measured frames, in path order
};
// Each term alone, then all of them (what the water costs shaded by nothing).
std::vector<TermVariant> termVariants();

// The pass --labels records after each frame (Renderer::renderLabels).
inline constexpr const char* kLabelsPass = "labels";
// With --labels, the optical flow from the last frame's labels to this
// one's (swell::opticalFlowOf, on the CPU), recorded after the label pass.
inline constexpr const char* kFlowPass = "flow";
// With --sensor, the frame drawn again through the scene camera's sensor
// (swell::renderSensorFrame: lens, shutter, readout), recorded apart.
inline constexpr const char* kSensorPass = "sensor";
// With --motion-vectors, the pass that draws a host's motion vectors
// (DrawOptions::motionVectors) inside the frame drawn again as a host's.
inline constexpr const char* kMotionVectorsPass = "motion vectors";

struct Results {
    Machine machine;
    glm::ivec2 size{0}, passSize{0};
    std::string surface; // the wave model's summary()
    std::string output;  // how frames reach the output: "antialiasing fxaa, render scale 1"
    int gridCells = 0, frames = 0, warmup = 0;
    double frameStep_s = 0.0;
    bool pipelineStatistics = false, gpuTimers = false;
    std::vector<FrameSample> real, floor;
    // With --labels: each measured frame's label pass, recorded apart right
    // after it (one pass, "labels"); empty otherwise.
    std::vector<FrameSample> labels;
    // With --labels: each measured frame's flow from the frame before it
    // (one pass, "flow"); none for a first frame without one before it.
    std::vector<FrameSample> flow;
    // With --sensor: each measured frame drawn through the sensor (one
    // pass, "sensor"), and how many draws it took.
    std::vector<FrameSample> sensor;
    int sensorDraws = 0;
    // With --motion-vectors: each measured frame drawn again into a host's
    // framebuffer with motion vectors (its passes; "motion vectors" is
    // theirs), and that draw's counters (motionVectorDraws, motionVectorTriangles).
    std::vector<FrameSample> motionVectors;
    std::vector<FrameCounters> motionVectorCounters;
    std::vector<double> realTimes_s;     // simulation time of each measured frame
    std::vector<Camera> realCameras;     // camera of each measured frame
    std::vector<LodSample> lod;
    std::vector<TermVariant> terms;      // empty when not measured (--no-terms)
    std::vector<ReflectionModeCost> reflectionModes;
    int floatingBodies = 0;
    std::vector<long long> bodySteps; // per measured frame, all bodies (Renderer::counters())
    std::vector<long long> wakeSteps; // per measured frame, the bodies' wake field's steps (1/30 s each)
    std::vector<double> wakeSteps_ms; // per measured frame, the wall time of those steps (within "bodies")
    // Per measured frame, Renderer::counters() after it: the simulation's CPU
    // time by part (simulationCpu) and Swell's GPU work (simulationGpu,
    // viewsGpu, drawCalls).
    std::vector<FrameCounters> counters;
};

void printReport(const Results& results);
// The line of the simulation's CPU time (FrameCounters::simulationCpu), and
// the table of Swell's GPU work per frame (bench_simulation.cpp).
void printSimulationCpuLine(const Results& results);
void printGpuWork(const Results& results);
nlohmann::ordered_json simulationCpuJson(const Results& results);
nlohmann::ordered_json frameSimulationCpuJson(const FrameCounters& counters);
nlohmann::ordered_json frameGpuWorkJson(const FrameCounters& counters);
// The views' culling of the frame (FrameCounters::cullBoxesTested): exact.
nlohmann::ordered_json frameCullingJson(const FrameCounters& counters);
// The terms' table (nothing when they were not measured), and its JSON.
void printTermReport(const Results& results);
nlohmann::ordered_json termsJson(const Results& results);
// Throws swell::Error when the file cannot be written.
void writeJson(const Results& results, const std::string& path);

} // namespace swell::app::bench
