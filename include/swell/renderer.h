// The ocean renderer. Simulation and drawing are apart: advanceTo() moves the
// ocean, the floating bodies and their wake to an absolute time; draw()
// draws one view of that time into a host's frame, as often as there are
// views (split screen, two eyes), without simulating again. render() does
// both for a Swell Camera, with Swell owning the frame. Passes of a view:
//   1  reflection: the world (the host's geometry through swell/view.h's
//      callback, Swell's own scene world through the same) mirrored about
//      the sea level, then the sky (colour + depth)
//   1b refraction: the world below the sea level (colour + depth)
//   2  main: into the host's framebuffer, depth-tested against what the host
//      drew (render(): cleared, the world drawn first, and the closed volumes
//      of open hulls into depth only), the water, then the sky where nothing is
//   present (render() only): when the scene's antialiasing is on or the
//      render scale is not 1, the main pass drew into its own target:
//      resolved (MSAA), filtered (FXAA) and scaled (bilinear) into the output
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/drawn_surface.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/temporal.h"
#include "swell/gpu/variants.h"
#include "swell/image.h"
#include "swell/labels.h"
#include "swell/pass_observer.h"
#include "swell/scene.h"
#include "swell/surface_source.h"
#include "swell/view.h"
#include "swell/wave_model.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace swell {

// The smallest and largest render scale: below 0.1 a 1280x720 frame is
// 128x72, too coarse to see anything; 2 draws 4 pixels per output pixel
// (supersampling), beyond it the linear filter that scales the image down
// skips pixels and memory grows with the square.
inline constexpr double kMinRenderScale = 0.1;
inline constexpr double kMaxRenderScale = 2.0;

// The size every pass draws at for an output of `outputSize` at
// `renderScale` (each side rounded, at least 1 pixel).
SWELL_API glm::ivec2 scaledFrameSize(glm::ivec2 outputSize, double renderScale);

struct SWELL_API RendererOptions {
    // Where shaders come from: the embedded copies, or a folder for hot reload.
    gl::ShaderSources shaders = gl::ShaderSources::embedded();
    // For measuring what each term of the water shading costs (swell bench):
    // the terms left out, a bitwise or of SWELL_TERM_* (swell/gpu/variants.h),
    // each replaced by its cheapest stand-in. 0 draws the water in full.
    unsigned omittedWaterTerms = 0;
};

// The CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID) that Swell's
// simulation work for a frame took, ms, by part. GL calls made in these parts
// count as far as the driver works on the calling thread (uploads,
// validation, and on a software rasteriser whatever it does there before
// handing work on); what a driver runs on threads of its own (llvmpipe's
// rasteriser and compute threads: the emulated GPU) does not, nor does a
// PassObserver's own time. Not in any part: issuing the passes' draws and
// their state (the pass table of `swell bench` has those).
struct SWELL_API SimulationCpuTime {
    // The wave model: its frame's preparation (WaveModelGpu::prepareFrame:
    // the spectral model's dispatches, and on a software rasteriser the
    // steps of a foam replay before the last) and each view's (prepareView,
    // bind).
    double model_ms = 0.0;
    // The floating bodies and their wake stepped to the frame's time (their
    // own water queries included), the wake's frame blended and uploaded.
    double bodies_ms = 0.0;
    // The frame's queries of the water: answered on the GPU (the dispatch,
    // the wait for it, the triangles found among its vertices) or, for a
    // model whose CPU queries are cheap, with those; the scene objects'
    // poses found with them, and a view's query of which side of the water
    // its eye is when it is not the simulated viewpoint.
    double queries_ms = 0.0;
    // Each view's culling and uniforms: the grid's tiles culled, the frame
    // uniforms and the world's boxes found, the uniforms and the surface
    // sources' parameters uploaded (every pass's).
    double views_ms = 0.0;
    double total_ms() const { return model_ms + bodies_ms + queries_ms + views_ms; }
};

// Swell's GPU work other than drawing, counted where the library makes the
// calls (swell/wave_model_gpu.h's Work): exact, the same in every run and on
// every machine, except a frame that replays the foam's history, whose
// steps before the last run on the CPU on a software rasteriser.
struct SWELL_API GpuWork {
    int dispatches = 0;         // glDispatchCompute calls
    int barriers = 0;           // glMemoryBarrier calls
    int mipmaps = 0;            // glGenerateTextureMipmap calls
    long long bytesWritten = 0; // texels the dispatches, mipmaps, clears and image uploads wrote, times their formats' sizes
};

// What the last advanceTo() did, and what the views drawn since drew (their
// sums), for the benchmark and tests. advanceTo() starts them again.
struct SWELL_API FrameCounters {
    long long waterTriangles = 0;
    long long worldTriangles = 0;
    long long causticsTriangles = 0; // the surface's triangles refracted into the caustics map (each to every slice)
    int drawCalls = 0;         // the views': every glDraw* call Swell made for them
    int views = 0;             // views drawn since the last advanceTo()
    int simulationSteps = 0;   // 1 when the last advanceTo() moved the simulation to a new time or viewpoint
    int floatingBodies = 0;  // rigid bodies in the scene (swell/floating_body.h)
    // Their integration steps taken for this frame (1/120 s each, all
    // bodies), and their wake's (1/30 s each), since the last advanceTo():
    // those anticipate() had taken ahead included.
    long long bodySteps = 0;
    long long wakeSteps = 0;
    double wakeSteps_ms = 0.0; // the wall time the wake's steps took, ms, on whichever thread took them
    // The CPU time the bodies' worker thread spent stepping ahead of this
    // frame (anticipate()) since the last advanceTo(), ms, its own clock:
    // Swell's CPU time, but not the calling thread's, so not in simulationCpu.
    double bodiesAheadCpu_ms = 0.0;
    int oceanTransforms = 0;   // the wave model's sets of inverse FFTs for this frame (spectral model)
    int foamSteps = 0;         // its foam's steps for this frame: more than one is a replay of its history
    // The frame's own queries of the water (each floating object's, the
    // viewpoint's side of it within the waves' reach): those answered on the
    // GPU from what it draws (WaveModelGpu::answersFrameQueries, the
    // spectral model), and those answered with the wave model's CPU queries
    // (every one of a model whose CPU queries are cheap; for the others,
    // a query whose drawn triangle lay beyond the GPU's block of vertices).
    int queriesOnGpu = 0;
    int queriesOnCpu = 0;
    // The boxes the views' culling of the water grid tested against their
    // frusta (blocks, quadtree nodes, tiles; part of views_ms): exact, the
    // same in every run, for a figure of the culling's work that no load
    // moves.
    long long cullBoxesTested = 0;
    // Every draw call of the views (the sky's bake and the anti-aliasing's
    // filter included) is drawCalls above; the rest of the GPU's work:
    GpuWork simulationGpu; // advanceTo()'s: the wave model's for the frame
    GpuWork viewsGpu;      // the views': the wave model's for each (none for Swell's own models), the caustics map's clear and mip chain where drawn
    SimulationCpuTime simulationCpu;
};

class SWELL_API Renderer {
public:
    // Needs a current OpenGL 4.5 core context. Throws swell::InputError when a
    // shader does not compile (naming the file and line) or an asset is bad.
    explicit Renderer(const Scene& scene, RendererOptions options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Switches to another scene; rebuilds only what its changes require, as
    // the parameter table declares (swell/scene_changes.h). On failure it
    // throws swell::InputError and keeps the scene it had.
    void setScene(const Scene& scene);
    const Scene& scene() const;

    // The ocean surface being drawn: the scene's wave model, or the one given
    // to setWaveModel(). Query it for heights and normals of what is drawn.
    const WaveModel& waveModel() const;
    // Draws `model` instead of the scene's waves until called with nullptr
    // (then the scene's waves again). Throws swell::InputError, keeping the
    // model it had, when the model's shaders do not build.
    void setWaveModel(std::shared_ptr<const WaveModel> model);

    // Adds a surface source of the host's (swell/surface_source.h): drawn in the
    // water, in drawnSurface() and under the floating bodies (which start
    // again from rest). Throws swell::InputError, keeping the sources it
    // had, when its GLSL does not build (naming surface_source_<i>.glsl and the
    // line), swell::Error when it is null, added already, or one too many
    // (SWELL_MAX_SURFACE_SOURCES, the wake's included). Shared: the host may
    // keep changing what it answers with time, not its GLSL.
    void addSurfaceSource(std::shared_ptr<const SurfaceSource> source);
    // Removes it (nothing when it is not there).
    void removeSurfaceSource(const std::shared_ptr<const SurfaceSource>& source);

    // The water exactly as render() draws it for this camera and time: the
    // grid's triangles (swell/drawn_surface.h), in absolute world
    // coordinates (the sea level added). Put things on the water the user
    // sees with it. Changes nothing drawn: at a time other than the
    // simulated one it steps bodies of the queries' own to find the wake
    // there. Valid until the next
    // setScene() or setWaveModel().
    DrawnSurface drawnSurface(const Camera& camera, double time_s) const;
    // The same for a view whose grid detail is centred at `lodViewpoint_m`
    // (View::lodViewpoint_m, or its eye), at the simulated time. Throws
    // swell::Error before the first advanceTo().
    DrawnSurface drawnSurface(glm::dvec3 lodViewpoint_m) const;
    // Each scene object's transform (object to absolute world, m) at the
    // simulated time: floating objects sit on drawnSurface().
    std::vector<glm::dmat4> objectTransforms() const;
    // The scene's camera at time_s (swell/camera.h's cameraAt), and for a
    // camera mounted on an object (camera.mount_object) that object's
    // transform at time_s applied (mountedCamera): a floating body's heave,
    // roll and pitch, stepped to time_s as advanceTo() steps it.
    Camera sceneCameraAt(double time_s);
    // Draws every pass at `scale` times the output's size (each side, rounded)
    // and scales the image to the output with a bilinear filter: 0.5 costs
    // about a quarter of the pixels, 2 supersamples. Throws
    // swell::InputError outside 0.1..2. Default 1.
    void setRenderScale(double scale);
    double renderScale() const;

    // The temporal resolve, for render() drawn again and again (a viewer;
    // docs/RENDERING.md "Temporal resolve"). On: each frame's projection
    // moves by a sub-pixel jitter that changes every frame (Halton 2, 3;
    // SWELL_TEMPORAL_JITTER_PHASES frames), the frame is drawn at the render
    // scale without the scene's antialiasing, and it is blended into a
    // history kept at the output's size: the history reprojected with the
    // camera's motion (each pixel's depth), clipped to what the frame shows
    // around the pixel, each new frame weighing about a tenth once the
    // history is full (SWELL_TEMPORAL_MAX_WEIGHT). A still camera converges
    // to an anti-aliased image at the output's full resolution whatever the
    // render scale. The waves' own motion is not reprojected: the clip
    // bounds how far a moving crest's history lags. Off (the default):
    // every frame stands alone, as stills and videos need. Turning it on
    // or off, a new output size, and resetTemporalHistory() start the
    // history again. draw() never uses it.
    void setTemporalResolve(bool on);
    bool temporalResolve() const;
    // Starts the history again: the next frame stands alone (a host's
    // camera cut; a jump the reprojection cannot follow).
    void resetTemporalHistory();
    // For tests: draw every frame unjittered (at the pixels' centres),
    // to show what the jitter brings. Default on.
    void setTemporalJitter(bool on);

    // For tests and the benchmark: the largest error, in each pass's own
    // pixels, that the built-in island's level of detail may show (docs/
    // RENDERING.md "The island's levels of detail"); 0 draws its full grid
    // in every pass. Default 0.5. Throws swell::InputError below 0.
    void setIslandTolerance(double tolerance_px);

    // Recompiles every shader from options.shaders (for hot reload). On failure
    // the old programs stay in use and the error is thrown.
    void reloadShaders();

    // The simulation: moves the ocean (the spectral model's fields and its
    // foam), the floating bodies and their wake to time_s (absolute, s; any
    // order, stills and videos reproduce it exactly), around `viewpoint_m`
    // (absolute world, m): where the foam's windows are centred and the
    // drawn surface that non-rigid floating objects sit on. Calling it again
    // with the same time and viewpoint does nothing.
    void advanceTo(double time_s, glm::dvec3 viewpoint_m);
    // The time the last advanceTo() reached; empty before the first, and
    // after any setScene(), setWaveModel() or change of the surface sources
    // (the next advanceTo() takes it again, at no cost where nothing moved).
    std::optional<double> simulatedTime_s() const;

    // Draws one view of the simulated time into the host's `framebuffer`
    // (0: the default one) at view.viewport, compositing: it clears nothing,
    // tests the water against the depth the host drew, and writes only
    // where water (or, if asked, sky) is. The reflection and refraction see
    // options.geometry through its callback. Restores the GL state it
    // changes (docs/LIBRARY.md lists it). Throws swell::Error, with the
    // host's framebuffer as it was, before any advanceTo(), for an empty
    // viewport, a projection that cannot be inverted, a framebuffer that is
    // incomplete or has no depth, or a callback that leaves a GL error.
    void draw(const View& view, unsigned framebuffer, const DrawOptions& options = {});

    // For a host that knows its next frame's time (a video, the benchmark):
    // the floating rigid bodies and their wake step towards nextTime_s on a
    // worker thread of their own while this frame is drawn, and the next
    // advanceTo() waits for them and takes the steps left. They take the
    // same steps in the same order either way, so every pose, wake and
    // query is the same bit for bit whether or when this was called. Times
    // before the simulated one are ignored; a next advanceTo() before
    // nextTime_s starts the bodies again from their start, as time going
    // back does. The bodies query the wave model and the host's surface
    // sources from that thread: their CPU queries must be thread-safe
    // (Swell's models' are).
    void anticipate(double nextTime_s);

    // Swell owns the frame: advances to time_s at the camera and draws one
    // frame of `size` pixels into `framebuffer` (0: the default one),
    // cleared first, with the scene's own world and sky, antialiasing and
    // render scale. A zero-sized frame draws nothing.
    void render(const Camera& camera, double time_s, glm::ivec2 size, unsigned framebuffer = 0);
    // Draws one frame offscreen and reads it back (top row first).
    Image renderImage(const Camera& camera, double time_s, glm::ivec2 size);

    // The ground truth of the frame render() draws for this camera at the
    // simulated time (swell/labels.h, docs/LABELS.md): per pixel range,
    // normal, class and instance, aligned with the colour image of `size`
    // pixels (at any render scale or antialiasing), each object's boxes,
    // the camera's calibration and the horizon. Throws swell::Error before
    // the first advanceTo() or render(), or for an empty size.
    FrameLabels renderLabels(const Camera& camera, glm::ivec2 size);

    const FrameCounters& counters() const;

    // For a viewer: a frame later than the last never replays the
    // simulation's history (the foam's), however long the frame or far the
    // camera moved; it takes one step, so a slow frame never makes the next
    // one slower. Off (the default): a frame more than a foam step (1 s)
    // after the last, or after a camera cut, replays it, as a still does.
    void setInteractive(bool interactive);

    // Observes the passes of later frames; nullptr stops. Not owned.
    void setPassObserver(PassObserver* observer);

    // For tests and the benchmark: binds the water program with transform
    // feedback capture of vRestPoint, vPosition and vNormal (8 floats per
    // vertex) for this frame setup, draws all the grid's vertices as points
    // into `buffer`, and returns the vertex count. Render origin: the camera's
    // x,z. drawnIndices, when given, receives the triangles (three vertex
    // indices each) a frame of this size would draw: the tiles in view.
    int captureWaterVertices(const Camera& camera, double time_s, unsigned buffer, glm::ivec2 size = {640, 480},
                             std::vector<std::uint32_t>* drawnIndices = nullptr);
    // The number of vertices captureWaterVertices writes.
    int waterVertexCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace swell
