// A surface source: heights added to the water on top of the wave model, the
// same on the GPU (the drawn water) and in the CPU queries (DrawnSurface,
// the floating bodies). The bodies' wake is one; a host adds its own (an
// expanding ring from an explosion, a bow wave) with
// Renderer::addSurfaceSource(). Sources add up: heights and slopes sum, foam
// takes the largest.
//
// A source adds its height at the grid's rest point, as the wake does: the
// vertex over rest point x0 rises by h(x0), so a source moves the water up
// and down, never sideways.
#pragma once

#include "swell/export.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <string>

namespace swell {

// Parameters a source hands its GLSL function for one view: four vec4s.
using SurfaceSourceParameters = std::array<glm::vec4, 4>;

class SWELL_API SurfaceSource {
public:
    virtual ~SurfaceSource();

    // The CPU side: the height the source adds at rest point restPoint_m
    // (absolute world x, z, m) at time_s (s), and its slopes there:
    // (h m, dh/dx, dh/dz).
    virtual glm::dvec3 heightAt(glm::dvec2 restPoint_m, double time_s) const = 0;

    // The largest |h| it adds anywhere at time_s, m: culling and the near
    // plane's test pad the waves' reach by it.
    virtual double reach_m(double time_s) const = 0;

    // The GPU side: GLSL (4.50) that defines
    //   vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4])
    // returning (h m, dh/dx, dh/dz, foam 0..1) at p_m, a rest point relative
    // to the render origin (the eye's x, z, at the sea level), with the
    // parameters gpuParameters() gave. The foam is an amount, as the
    // whitecaps' is: 1 where the water breaks now, exp(-age /
    // SWELL_SOURCE_FOAM_LIFETIME_S, swell/gpu/ocean.h) after; the
    // renderer draws it with the whitecaps' look (a dense sheet above a
    // second's age, then lace and flecks), not as the share of the water it
    // covers.
    // SWELL_SOURCE_FUNCTION is a macro the renderer defines to a name of its
    // own for each source; anything else the code defines must be unique to
    // it. It may use the constants of swell/gpu/ocean.h and those of
    // swell/constants.h the shaders share (gpu/constants.glsl: SWELL_PI,
    // ...). It must compute what heightAt() does (a test of the host's
    // should hold them within 1 mm).
    virtual std::string glsl() const = 0;

    // The parameters the GLSL function reads for a view of time_s drawn
    // about renderOrigin_m (absolute world, m): positions relative to it
    // keep float precision near the eye.
    virtual SurfaceSourceParameters gpuParameters(double time_s, glm::dvec3 renderOrigin_m) const = 0;
};

} // namespace swell
