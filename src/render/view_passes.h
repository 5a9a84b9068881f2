// The passes of one view, each a small object drawn with a PassState
// (render/pass_state.h), in the order Renderer::Impl::drawView lists them
// (after the view's maps: the caustics, and the contact foam's map of what
// stands in the water, render/contact_map.h):
//   MirrorPass{Reflection}  the world mirrored about the sea level, then the sky
//   MirrorPass{Refraction}  the world beyond the surface as the eye sees it
//   MainPass                the waterline mask (WaterlinePass), then the
//                           world, the water, the sky and the spray into the
//                           output or the view's own target
//   PresentPass             the view's target into the output: the temporal
//                           resolve, or the MSAA resolve, FXAA and the render
//                           scale's filter
// Library-internal.
#pragma once

#include "render/pass_state.h"
#include "render/view_frame.h"
#include "render/view_state.h"
#include "render/waterline.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <glm/mat4x4.hpp>

#include <optional>
#include <utility>

namespace swell::detail {

class SceneWorld;

// How one view is drawn: what draw() or render() asked of it.
struct ViewRequest {
    // The view, its projection moved by this frame's jitter when resolved
    // over time; and, then, the unmoved view and projection (absolute world
    // to clip) the resolve reprojects with.
    View view;
    std::optional<glm::dmat4> unjitteredViewProj;
    DrawOptions options;
    GLuint output = 0;         // the framebuffer the picture goes into
    glm::ivec4 outputViewport{0}; // where in it, pixels
    glm::ivec2 size{0};        // every pass's size: the viewport's at the render scale
    // render()'s frame: cleared, Swell's world and the host's geometry drawn
    // in the main pass; else draw()'s, over what the host drew.
    bool ownsFrame = false;

    glm::ivec2 outputSize() const { return {outputViewport.z, outputViewport.w}; }
    bool temporal() const { return unjitteredViewProj.has_value(); }
    // Whether the main pass draws into the view's own target, which
    // PresentPass then brings into the output.
    bool throughTarget() const
    {
        return temporal() || options.antialiasing != Antialiasing::Off || size != outputSize();
    }
};

struct MirrorPass {
    PassKind kind; // PassKind::Reflection or PassKind::Refraction
    void draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request,
              SceneWorld* own) const;
};

// The waterline mask for the main pass (render/waterline.h): drawn from the
// water grid when the near plane can lie on either side of the waves, else
// filled with the side it lies on. Draws into its own target with its own
// frame uniforms (the viewport at its origin).
struct WaterlinePass {
    NearPlaneMedium medium;
    void draw(RenderContext& context, WaterlineMask& mask, const ViewFrame& v) const;
};

// The world (render(): Swell's and the host's; draw(): Swell's, the host
// drew its own), the water depth-tested against it so objects crossing the
// surface meet it cleanly, the sky last where nothing else was drawn (its
// depth test passes at the far plane alone, so its shader runs on the
// visible sky's pixels only), then the spray.
struct MainPass {
    void draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request,
              SceneWorld& own) const;

private:
    // The framebuffer and viewport the pass draws into.
    std::pair<GLuint, glm::ivec4> target(ViewState& state, const ViewRequest& request) const;
    // The water, in one pass or two (render/water_visibility.h; water_pass.cpp).
    void drawWater(RenderContext& context, ViewState& state, const PassState& pass, bool inAir) const;
    // What both ways of drawing it bind for its shading.
    void bindWaterShading(const RenderContext& context, const ViewState& state, bool deferred, bool inAir) const;
    // The grid shaded in its own fragments.
    void drawWaterInOnePass(RenderContext& context, const ViewState& state, bool inAir) const;
    // The grid's visibility, then one shading run per water pixel.
    void drawWaterInTwoPasses(RenderContext& context, ViewState& state, const PassState& pass, bool inAir) const;
};

// The view's target into the output (when the main pass drew into it).
struct PresentPass {
    void draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request) const;
};

// draw()'s picture under the view's viewport brought into the view's own
// target before the water is drawn over it (render/host_copy.h), and the
// target's depth written back into the host's after it is presented, so
// the host's later passes (transparent ones) are tested against the water.
void copyHostPictureIn(RenderContext& context, ViewState& state, const PassState& main, const ViewRequest& request);
void writeDepthBack(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request);

// The sky: in the passes' empty pixels, behind everything.
void drawSky(RenderContext& context, bool inAir, const DepthConvention& depth);

} // namespace swell::detail
