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
#include "swell/dataset/labels.h"
#include "swell/dataset/platform.h"
#include "swell/drawn_surface.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/temporal.h"
#include "swell/gpu/variants.h"
#include "swell/image.h"
#include "swell/pass_observer.h"
#include "swell/scene/seabed.h"
#include "swell/scene/scene.h"
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

struct SWELL_API RendererOptions {
    // Where shaders come from: the embedded copies, or a folder for hot reload.
    gl::ShaderSources shaders = gl::ShaderSources::embedded();
};

// What the last advanceTo() and the views drawn since did (swell/debug.h).
struct FrameCounters;
class RendererTesting;

class SWELL_API Renderer {
public:
    // Needs a current OpenGL 4.5 core context. Throws swell::InputError when a
    // shader does not compile (naming the file and line) or an asset is bad.
    explicit Renderer(const Scene& scene, RendererOptions options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Switches to another scene; rebuilds only what its changes require, as
    // the parameter table declares (swell/scene/scene_changes.h). On failure it
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

    // The host's own terrain as heights on a grid (swell/scene/seabed.h,
    // SeabedHeights: row-major floats, world y, over a world rectangle),
    // joined to the scene's sea floor: where it is highest, it is the
    // floor the water's depth is measured to. Not drawn (the host draws its
    // own terrain). Throws swell::Error naming the fault (a size outside
    // 2..4096, a count other than columns x rows, a NaN or infinite height,
    // a rectangle with no area) and keeps the heights it had.
    void setSeabedHeights(const SeabedHeights& heights);
    // Forgets the host's heights: the scene's sea floor alone again.
    void clearSeabedHeights();
    // The sea floor the renderer holds: the scene's seabed, its island and
    // the host's heights (Seabed::elevation_m). Valid until the next
    // setScene() or change of the host's heights.
    const Seabed& seabed() const;

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
    // The platform that camera stands for (swell/dataset/platform.h), and how
    // it moves at time_s: on a body, the body's simulated state carried to
    // the camera's eye (its velocities, and their change over the body's
    // step for the acceleration); on a path, the path's derivatives; fixed,
    // at rest. Steps the bodies as sceneCameraAt() does.
    PlatformMotion platformAt(double time_s);
    // render()'s own view, drawn as DrawOptions::renderScale and
    // DrawOptions::temporal draw one of draw()'s (swell/view.h), with the
    // scene's antialiasing where it is not resolved over time. Scale:
    // throws swell::InputError outside 0.1..2. Default 1, and off.
    void setRenderScale(double scale);
    double renderScale() const;
    void setTemporalResolve(bool on);
    bool temporalResolve() const;
    // Starts every view's temporal history again, render()'s and draw()'s:
    // the next frame of each stands alone (a host's camera cut; a jump the
    // reprojection cannot follow).
    void resetTemporalHistory();
    // Gives back what Swell keeps for draw()'s view `viewId`
    // (DrawOptions::viewId): its passes' targets and its temporal history.
    // Nothing when it has none; a later draw() of it starts again.
    void releaseView(std::uint32_t viewId);

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
    // options.geometry through its callback. With a render scale,
    // antialiasing or the temporal resolve (DrawOptions), the view is drawn
    // through Swell's own target: the host's picture under the viewport is
    // copied in, the water drawn over it, and the result filtered back into
    // the viewport (the host's geometry with it), its depth written back.
    // Swell keeps each view's targets and history apart by
    // options.viewId. Restores the GL state it changes (docs/LIBRARY.md
    // lists it). Throws swell::Error, with the host's framebuffer as it was,
    // before any advanceTo(), for an empty viewport, a projection that
    // cannot be inverted, a framebuffer that is incomplete or has no depth,
    // a render scale outside 0.1..2, or a callback that leaves a GL error.
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
    // `simulatedAround_m`: where advanceTo() centres the simulation (the
    // camera's eye when empty); a rig's cameras give their platform's, so
    // that each is drawn from the one state simulated for the time.
    Image renderImage(const Camera& camera, double time_s, glm::ivec2 size,
                      std::optional<glm::dvec3> simulatedAround_m = std::nullopt);

    // The ground truth of the frame render() draws for this camera at the
    // simulated time (swell/dataset/labels.h, docs/LABELS.md): per pixel range,
    // normal, class and instance, aligned with the colour image of `size`
    // pixels (at any render scale or antialiasing), each object's boxes,
    // the camera's calibration and the horizon. Throws swell::Error before
    // the first advanceTo() or render(), or for an empty size.
    FrameLabels renderLabels(const Camera& camera, glm::ivec2 size);

    // What the last advanceTo() and the views drawn since did (swell/debug.h).
    const FrameCounters& counters() const;

    // For a viewer: a frame later than the last never replays the
    // simulation's history (the foam's), however long the frame or far the
    // camera moved; it takes one step, so a slow frame never makes the next
    // one slower. Off (the default): a frame more than a foam step (1 s)
    // after the last, or after a camera cut, replays it, as a still does.
    void setInteractive(bool interactive);

    // Observes the passes of later frames; nullptr stops. Not owned.
    void setPassObserver(PassObserver* observer);

private:
    friend class RendererTesting;
    // omittedWaterTerms: the benchmark's (RendererTesting::create).
    Renderer(const Scene& scene, RendererOptions options, unsigned omittedWaterTerms);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace swell
