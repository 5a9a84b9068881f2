// The bodies' wake as a surface source (swell/surface_source.h): one frame of it
// (objects/wake_frame.h), its heights added at the grid's rest points on the
// CPU as shaders/wake.glsl adds them on the GPU. The renderer uploads the
// frame's cells for the GLSL side (render/wake_texture.h).
#pragma once

#include "objects/wake_frame.h"
#include "swell/surface_source.h"

#include <memory>

namespace swell::detail {

class WakeSurfaceSource final : public SurfaceSource {
public:
    // `frame` null: no wake (heights 0).
    explicit WakeSurfaceSource(std::shared_ptr<const WakeFrame> frame);

    glm::dvec3 heightAt(glm::dvec2 restPoint_m, double time_s) const override;
    double reach_m(double time_s) const override;
    std::string glsl() const override;
    SurfaceSourceParameters gpuParameters(double time_s, glm::dvec3 renderOrigin_m) const override;

    // The GLSL every wake source has: the source list's text depends on
    // whether there is a wake, never on its frame.
    static std::string code();

private:
    std::shared_ptr<const WakeFrame> frame_;
    double reach_m_ = 0.0;
};

} // namespace swell::detail
