// The contact foam's map (docs/RENDERING.md "Foam where water meets what
// stands in it"; shaders/contact.glsl): each view, the solid geometry that
// stands at or above the sea level within the waves' reach (Swell's island,
// sea floor, objects and floating hulls, and the host's PassGeometry), drawn
// from straight above into a depth target in a window around the camera,
// then the distance from every texel to the nearest texel it covers, in two
// compute passes (shaders/contact_distance.comp). The water's shading lays
// the surf's foam in a band round the contact, as wide as the waves' orbits.
// Library-internal.
#pragma once

#include "render/gpu/blocks.h"
#include "swell/debug.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/contact.h"
#include "swell/view.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell::detail {

struct RenderContext;
struct ViewFrame;
class SceneWorld;

// The narrowest foam band, m: the ring round a hull or a pile in a light sea
// (the churn of a body's own heave and of the ripples against it).
inline constexpr double kContactBandMin_m = 0.3;
// The band round the contact (m, e-folding) for a sea of significant height
// hs_m: the significant wave's amplitude hs/2, which in deep water is the
// radius of the orbits its water particles run at the surface (linear
// theory: the horizontal semi-axis at the surface is a cosh(kh) / sinh(kh),
// which tends to a as kh grows; Dean & Dalrymple 1991, ch. 4, water
// particle displacements). The water churned at a structure's face is
// carried that far to and fro as each wave passes, and the flow round a
// pile separates and sheds its vortices over that excursion (Sumer &
// Fredsoe 2006, ch. 3: the Keulegan-Carpenter number KC = 2 pi a / D). No
// less than kContactBandMin_m.
double contactBand_m(double significantHeight_m);
// The band above the sea level in which geometry counts as meeting the
// water (m), for a sea of significant height hs_m: the significant wave's
// crest, hs / 2, at least 1 cm (a pier's deck 1.85 m over a 2 m sea, the
// example host's, is not washed: only the rare crest reaches it, and foam
// under the whole deck would be wrong; a box 5 cm over ripples whose
// crests reach 2.7 cm stays dry).
double contactTop_m(double significantHeight_m);
// The window's side (m) for an eye `height_m` above the sea level: the
// smallest, SWELL_CONTACT_MIN_EXTENT_M, doubled until it holds
// SWELL_CONTACT_EXTENT_PER_HEIGHT times the height, at most
// SWELL_CONTACT_MAX_EXTENT_M (powers of two, so the texels do not change
// size, and the pattern swim, as the eye climbs).
double contactExtent_m(double height_m);

// The window's place and the pass's projection, relative to the render
// origin (x, z at the eye, y at the sea level).
struct ContactPlacement {
    glm::dvec2 corner_m{0.0}; // texel (0, 0)'s outer corner, x, z
    double size_m = SWELL_CONTACT_MIN_EXTENT_M;
    double top_m = 0.5;       // contactTop_m
    // Render-origin-relative points to clip space: x, z over the window
    // (x, z to the map's s, t), y from the top of the band (near) to the sea
    // level (far, clipped below), and x, z moved by up to a texel each way
    // with the height (a shear along (1, 0.6)), so that a vertical wall
    // facing x or z covers one or two texels rather than none.
    glm::dmat4 viewProj{1.0};
};

// Where the window lies for an eye at `eye` (sea frame, m) with the render
// origin at `origin` (the eye's x, z at the sea level), for a band `top_m`
// high: the corner snapped to whole texels of the world, so the map's
// texels stay put as the eye moves.
ContactPlacement placeContact(glm::dvec3 eye, glm::dvec3 origin, double top_m);

class ContactMap {
public:
    // Off: no contact foam anywhere, and no pass (RendererTesting::setContactFoam).
    void setEnabled(bool on) { enabled_ = on; }
    bool enabled() const { return enabled_; }

    // The depth target the pass draws into (created on first use), with
    // the distance passes' programs built from `sources`.
    GLuint framebuffer(const gl::ShaderSources& sources);
    // The distance from every texel to the nearest one the pass covered:
    // two dispatches and their barriers.
    void computeDistance();
    // What computeDistance() writes: its dispatches, barriers and bytes.
    static GpuWork distanceWork();
    // Binds the distance map for the water's shading (the unit keeps it
    // while nothing else is bound there: PassState::restore binds it again).
    void bind() const;

private:
    bool enabled_ = true;
    gl::Texture depth_, rows_, distance_;
    gl::Framebuffer framebuffer_;
    gl::Program rowsPass_, columnsPass_;
};

// The contact pass of one view, before its other passes: decides whether
// anything may meet the water in the window (Swell's world's boxes, or any
// host geometry; the sea must have waves), draws `own` (may be null) and
// `host` (may be null) from above, computes the distance and binds it. Writes the Frame block's contact fields of v.base
// (contactOn 0 when the pass was left out or drew nothing).
void drawContact(RenderContext& context, ViewFrame& v, SceneWorld* own, PassGeometry* host, const View& view);

} // namespace swell::detail
