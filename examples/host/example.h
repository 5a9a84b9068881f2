// One frame of the example host, the way an engine composes it:
//   1  the simulation: renderer.advanceTo(time, viewpoint)
//   2  the game's logic on the water: the ship and the loose crate placed
//      on renderer.drawnSurface(viewpoint), the camera on the ship
//   3  the host's opaque pass into its linear RGBA16F target, reversed-Z
//   4  renderer.draw(): the water composited into that target (its own
//      reflection and refraction passes call the host's boxes back), the
//      sky where the host drew nothing, linear output
//   5  the host's tone mapping into the display framebuffer.
#pragma once

#include "boxes.h"
#include "frame.h"
#include "harbour.h"

#include <swell/renderer.h>
#include <swell/scene/scene.h>

#include <memory>

namespace host {

// The scene the example shows: Swell's default ocean made a harbour's (a
// light breeze, a low swell), the sun ahead and to starboard so the pier's
// face is lit.
swell::Scene harbourScene();

class Example {
public:
    // Needs a current GL 4.5 core context with the host's functions loaded.
    explicit Example(const swell::Scene& scene);

    // Draws the frame at time_s into `framebuffer` (0: the window) of `size` pixels.
    void frame(double time_s, GLuint framebuffer, glm::ivec2 size);

    const Harbour& harbour() const { return harbour_; }

private:
    swell::Scene scene_;
    swell::Renderer renderer_;
    BoxRenderer boxes_;
    Harbour harbour_;
    ToneMapper toneMapper_;
    std::unique_ptr<Target> hdr_;
};

} // namespace host
