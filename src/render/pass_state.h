// One pass's state as a value (Filament's per-pass parameters): where it
// draws, with which depth convention and frame uniforms, clipped and
// mirrored or not. begin() sets all the GL state the pass depends on, so
// passes can be reordered; after a host's callback, which may change any
// state, restore() sets it again. Library-internal.
#pragma once

#include "render/gpu/blocks.h"
#include "render/resources.h"
#include "render/telemetry.h"
#include "render/view_setup.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include <optional>

namespace swell::detail {

struct RenderContext;
class SceneWorld;

struct PassState {
    Pass slot = PassMain; // which of the frame uniform buffers it uploads into
    FrameUniforms frame{};
    GLuint framebuffer = 0;
    glm::ivec4 viewport{0};
    DepthConvention depth;
    bool clipped = false;  // GL_CLIP_DISTANCE0 on: the reflection and refraction keep one side of the surface
    bool mirrored = false; // the reflection: windings turned round on screen

    // Uploads the frame uniforms, binds the framebuffer and sets the state;
    // a clear colour clears colour and depth, none keeps both.
    void begin(const Resources& resources, Telemetry& telemetry, std::optional<glm::vec4> clear = std::nullopt) const;
    // Sets the pass's state again, its uniforms and the simulation's
    // bindings included, after a callback that may have changed any of it.
    void restore(RenderContext& context) const;
};

// The state every pass starts from, at `viewport` with `depth`'s convention.
void setPassState(glm::ivec4 viewport, const DepthConvention& depth);

// The geometry of a pass: Swell's own world (when `own` is not null) and
// the host's (when `host` is not null), each through the same callback, the
// pass's view in absolute world coordinates. `view`: the view drawn.
void drawGeometry(RenderContext& context, const PassState& pass, PassKind kind, SceneWorld* own, PassGeometry* host,
                  const View& view);

// The same for a pass whose view the caller made (the contact pass's, from
// above): Swell's world and the host's drawn with `view`, the host's GL
// error refused, and the pass's state put back after the host's drawing.
// The front face is the caller's to set.
void drawGeometryAs(RenderContext& context, const PassState& pass, const PassView& view, SceneWorld* own,
                    PassGeometry* host);

} // namespace swell::detail
