// The ocean renderer: draws a Scene with a Camera at a simulation time into a
// framebuffer of the current OpenGL 4.5 context. Passes:
//   1  reflection: sky and world mirrored about the water plane (colour + depth)
//   1b refraction: the world below the water plane (colour + depth)
//   2  main: the world, the closed volumes of open hulls into depth only,
//      the water depth-tested against both, then the sky where nothing is
//   present: when the scene's antialiasing is on or the render scale is not
//      1, the main pass drew into its own target: resolved (MSAA), filtered
//      (FXAA) and scaled (bilinear) into the output framebuffer
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/drawn_surface.h"
#include "swell/gl/shader_sources.h"
#include "swell/image.h"
#include "swell/scene.h"
#include "swell/wave_model.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
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
    // the terms left out, a bitwise or of SWELL_TERM_* (swell/shader_constants.h),
    // each replaced by its cheapest stand-in. 0 draws the water in full.
    unsigned omittedWaterTerms = 0;
};

// Triangles and draw calls of the last frame, for the benchmark and tests.
struct SWELL_API FrameCounters {
    long long waterTriangles = 0;
    long long worldTriangles = 0;
    int drawCalls = 0;
    int floatingBodies = 0;  // rigid bodies in the scene (swell/floating_body.h)
    long long bodySteps = 0; // their integration steps taken for this frame (1/120 s each, all bodies)
    long long wakeSteps = 0; // steps of their wake field taken for this frame (1/30 s each)
    double wakeSteps_ms = 0.0; // the wall time those steps took, ms (part of the "bodies" pass)
    int oceanTransforms = 0;   // the wave model's sets of inverse FFTs for this frame (spectral model)
    int foamSteps = 0;         // its foam's steps for this frame: more than one is a replay of its history
};

// Told when each pass of a frame begins and ends (for timing and counters).
// Passes: "ocean" (the wave model's simulation for the frame), "bodies" (the
// floating bodies and their wake stepped on the CPU to the frame's time),
// "wake" (the wake's frame blended and uploaded), "reflection",
// "refraction", "main"; within "main", "water" for the water draw; then
// "present" when the main pass's image is resolved, filtered or scaled.
class SWELL_API PassObserver {
public:
    virtual ~PassObserver() = default;
    virtual void beginPass(const char* name) = 0;
    virtual void endPass(const char* name) = 0;
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

    // The water exactly as render() draws it for this camera and time: the
    // grid's triangles (swell/drawn_surface.h). Put things on the water the
    // user sees with it. Valid until the next setScene() or setWaveModel().
    DrawnSurface drawnSurface(const Camera& camera, double time_s) const;
    // Each scene object's transform (object to absolute world, m) in the last
    // frame drawn or captured: floating objects sit on drawnSurface().
    std::vector<glm::dmat4> objectTransforms() const;
    // Draws every pass at `scale` times the output's size (each side, rounded)
    // and scales the image to the output with a bilinear filter: 0.5 costs
    // about a quarter of the pixels, 2 supersamples. Throws
    // swell::InputError outside 0.1..2. Default 1.
    void setRenderScale(double scale);
    double renderScale() const;

    // Recompiles every shader from options.shaders (for hot reload). On failure
    // the old programs stay in use and the error is thrown.
    void reloadShaders();

    // Draws one frame into `framebuffer` (0: the default one) of `size` pixels.
    // A zero-sized frame draws nothing.
    void render(const Camera& camera, double time_s, glm::ivec2 size, unsigned framebuffer = 0);
    // Draws one frame offscreen and reads it back (top row first).
    Image renderImage(const Camera& camera, double time_s, glm::ivec2 size);

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
