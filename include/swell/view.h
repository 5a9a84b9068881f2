// What a host gives Swell to draw the water into its own frame: the view
// (its matrices, its viewport, its depth convention) and the geometry it
// wants to see reflected and refracted (a callback per pass). Swell's own
// sky, island and scene objects are one client of the same callback.
// docs/LIBRARY.md shows a whole host (examples/host/).
#pragma once

#include "swell/export.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>

namespace swell {

struct Camera;

// The smallest and largest render scale: below 0.1 a 1280x720 frame is
// 128x72, too coarse to see anything; 2 draws 4 pixels per output pixel
// (supersampling), beyond it the linear filter that scales the image down
// skips pixels and memory grows with the square.
inline constexpr double kMinRenderScale = 0.1;
inline constexpr double kMaxRenderScale = 2.0;

// The size every pass draws at for an output of `outputSize` at
// `renderScale` (each side rounded, at least 1 pixel).
SWELL_API glm::ivec2 scaledFrameSize(glm::ivec2 outputSize, double renderScale);

// How the main pass's edges (objects, terrain, the horizon) are smoothed.
enum class Antialiasing {
    Off,   // one sample a pixel: hard steps
    Msaa4, // 4 samples a pixel for coverage and depth, resolved after the pass
    Fxaa,  // a post-process that blends along luminance edges (FXAA-style; the
           // scene's default: on llvmpipe it costs a fifth of what MSAA does,
           // docs/RENDERING.md)
};

// How the host's depth buffer maps distance. Swell draws its passes the same
// way, tests the water against the host's depth with the matching function,
// and sets glClipControl to match for its own draws (restoring the host's).
enum class DepthMode {
    // GL's default: clip z in -w..w (GL_NEGATIVE_ONE_TO_ONE), the near
    // plane at depth 0, the far plane at 1; GL_LESS, cleared to 1.
    Standard,
    // Clip z in 0..w (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)), near at
    // 0, far at 1; GL_LESS, cleared to 1.
    ZeroToOne,
    // Reversed-Z: clip z in 0..w (GL_ZERO_TO_ONE), the near plane at depth 1
    // and the far plane (or infinity) at 0; GL_GREATER, cleared to 0.
    Reversed,
};

// One view of the water: where the eye is, what it sees, and where in the
// framebuffer the picture goes.
struct SWELL_API View {
    // World (absolute, m; y up) to eye space, in double: the renderer draws
    // relative to the eye so precision does not depend on where it is. Any
    // rotation (roll included); no scale or shear.
    glm::dmat4 view{1.0};
    // Eye to clip space: any invertible projection (off-axis, jittered,
    // infinite far plane), written for `depth`'s convention.
    glm::dmat4 projection{1.0};
    // x, y, width, height in the framebuffer, pixels (GL's lower-left origin).
    glm::ivec4 viewport{0};
    DepthMode depth = DepthMode::Standard;
    // Where the water grid's detail is centred (absolute world, m): by
    // default the eye; a host may keep the detail around a player while the
    // camera orbits, or share one viewpoint across the two eyes of a stereo
    // pair.
    std::optional<glm::dvec3> lodViewpoint_m;

    // The eye's position (absolute world, m), from the view matrix.
    glm::dvec3 eye_m() const;
};

// The view of a Swell Camera (yaw, pitch, roll, lens) over a whole target of
// `size` pixels: its matrices, the viewport (0, 0, size), standard depth.
SWELL_API View viewOf(const Camera& camera, glm::ivec2 size);

// Which of Swell's passes a callback is asked to draw into.
enum class PassKind {
    // The world mirrored about the sea level, for the water's reflections:
    // keep what lies above the clip plane. The mirror turns windings round
    // (glFrontFace is GL_CW while it draws).
    Reflection,
    // The world below the sea level (above it when the eye is under the
    // water), which the water refracts: keep what the clip plane keeps.
    Refraction,
    // The main pass, when Swell owns the frame (Renderer::render): the
    // world seen directly, before the water.
    Main,
    // Depth only, just before the water is drawn (colour writes are off):
    // closed volumes the water must not show inside, such as the lid of an
    // open hull at its gunwale. Renderer::render only: before draw(), a
    // host draws its own volumes into its depth with its scene.
    WaterMask,
    // Depth only, from straight above, before the other passes (colour
    // writes are off): what stands in the water, whose meeting with it
    // foams (docs/RENDERING.md "Foam where water meets what stands in it").
    // Draw the solid geometry that may reach the water (piles, walls,
    // hulls, rocks) as in any pass; the projection keeps only the band
    // from the sea level up to the waves' reach, and is sheared a little
    // with height so that vertical walls cover texels. Called first in each
    // draw, only while the sea has waves.
    Contact,
};

// What a pass's callback draws with: the host draws its objects with its
// own shaders, transforming world positions by projection * view, and
// writes gl_ClipDistance[0] = dot(clipPlane_m, vec4(worldPosition, 1)).
struct SWELL_API PassView {
    PassKind pass = PassKind::Main;
    // World (absolute, m) to eye, mirrored about the sea level in the
    // reflection pass; and the pass's projection (the view's own).
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    // World plane (a, b, c, d): keep points with a x + b y + c z + d >= 0.
    // GL_CLIP_DISTANCE0 is enabled in the reflection and refraction passes;
    // in the others the plane keeps everything (0, 0, 0, 1).
    glm::dvec4 clipPlane_m{0.0, 0.0, 0.0, 1.0};
    // The pass's viewport, already set (glViewport), pixels.
    glm::ivec4 viewport{0};
    DepthMode depth = DepthMode::Standard;
    // The eye's position in this pass (mirrored in the reflection), absolute world, m.
    glm::dvec3 eye_m{0.0};
};

// Geometry a host wants in Swell's passes. drawPass() is called with the
// pass's framebuffer bound, its viewport, depth function and clip distance
// set; it may change any GL state but must leave no GL error (Swell checks,
// and throws swell::Error naming the pass). An exception it throws leaves
// the host's framebuffer as it was and propagates.
class SWELL_API PassGeometry {
public:
    virtual ~PassGeometry() = default;
    virtual void drawPass(const PassView& pass) = 0;
};

// How the water's colour is written.
enum class OutputEncoding {
    // Display-ready, sRGB-encoded (GL_FRAMEBUFFER_SRGB is turned off for
    // Swell's draws); for an RGBA8 target shown as is.
    Srgb,
    // Linear radiance, for a floating-point target (e.g. RGBA16F) that the
    // host tone-maps and post-processes itself.
    Linear,
};

// How Renderer::draw composites into the host's frame, and how the view is
// drawn (Filament's per-view settings). Render scale, antialiasing and the
// temporal resolve draw the view through Swell's own target
// (Renderer::draw); the defaults draw straight into the host's framebuffer.
struct SWELL_API DrawOptions {
    // The host's geometry for the reflection, refraction and water-mask
    // passes; null for none. Not owned.
    PassGeometry* geometry = nullptr;
    // Whether Swell's own world (the scene's island and objects) is drawn
    // too: into the passes and into the host's frame.
    bool sceneWorld = false;
    // Whether Swell draws its sky where the host's depth is still cleared
    // (at the far plane), after the water.
    bool sky = true;
    OutputEncoding encoding = OutputEncoding::Srgb;
    // Which of the host's views this is: Swell keeps each id's own targets
    // and temporal history (split screen: one id a side; a stereo pair: one
    // an eye). Renderer::releaseView gives an id's back.
    std::uint32_t viewId = 0;
    // Draws every pass at this fraction of the viewport's size (each side,
    // rounded; kMinRenderScale..kMaxRenderScale) and filters the picture
    // into the viewport: 0.5 costs about a quarter of the pixels, 2
    // supersamples.
    double renderScale = 1.0;
    Antialiasing antialiasing = Antialiasing::Off;
    // The temporal resolve (docs/RENDERING.md "Temporal resolve"), for a
    // view drawn again and again: each frame's projection moves by a
    // sub-pixel jitter that changes every frame (Halton 2, 3;
    // SWELL_TEMPORAL_JITTER_PHASES frames), the frame is drawn at the
    // render scale without antialiasing, and it is blended into the view's
    // history kept at the viewport's size: reprojected with the camera's
    // motion (each pixel's depth), clipped to what the frame shows around
    // the pixel, each new frame weighing about a tenth once the history is
    // full (SWELL_TEMPORAL_MAX_WEIGHT). A still camera converges to an
    // anti-aliased picture at the viewport's full resolution whatever the
    // render scale. The waves' own motion is not reprojected: the clip
    // bounds how far a moving crest's history lags. Off: every frame stands
    // alone, as stills and videos need. Turning it on or off and a new
    // viewport size start the view's history again.
    bool temporal = false;
    // Motion vectors for the host's own TAA or motion blur (docs/LIBRARY.md
    // "Motion vectors"): 0 for none (nothing written, nothing computed),
    // else a colour attachment of the framebuffer draw() is given
    // (GL_COLOR_ATTACHMENT0 + i, not framebuffer 0): a float texture of
    // two or more channels (GL_RG16F, GL_RG32F) with the framebuffer's
    // samples. Into its red and green channels, at each pixel of the
    // viewport that Swell draws (the water, its sky, its own world with
    // sceneWorld), depth-tested against the host's depth as the water is:
    // where the pixel's point lay in this viewId's previous draw less the
    // pixel's centre, in framebuffer pixels (GL's lower-left origin: x
    // right, y up), so the previous place is the pixel plus the vector. The
    // host's own pixels keep what the host wrote. The first draw of a
    // viewId, and a draw after a time earlier than its last or more than
    // kMotionVectorLongestGap_s later, writes zero.
    std::uint32_t motionVectors = 0;
};

// The longest gap between two draws of one view across which motion
// vectors are written (a longer one starts the view's motion again, s):
// a TAA's history is no use after a cut or a pause this long.
inline constexpr double kMotionVectorLongestGap_s = 0.5;

} // namespace swell
