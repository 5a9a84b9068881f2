// The ocean surface as the CPU asks it: where the water is at a place and a
// time. The floating bodies, their wake, DrawnSurface, culling and the
// reflection's bounds, the benchmark and the Python package ask only this;
// none of them needs the GPU. A wave model (swell/wave_model.h) is one, with
// a GPU half besides; swell/composed_surface.h adds surface sources to one.
//
// A surface maps a rest point x0 (world x,z, m) at time t (s) to a displaced
// point x0 + D(x0, t). Queries take a SurfaceFilter saying which part of the
// surface to evaluate: the exact one (the default), or the one the GPU draws
// at a place, where the grid's cells drop the waves they cannot resolve and
// wave heights fade towards the horizon.
#pragma once

#include "swell/export.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell {

// How far a surface can move from its rest plane, m: up or down, and
// sideways. Culling pads the grid's tiles by it, and the reflection's
// bounds pad floating objects by it.
struct SWELL_API WaveReach {
    double vertical_m = 0.0, horizontal_m = 0.0;
};

// Which surface a query evaluates. The default is the exact surface.
struct SWELL_API SurfaceFilter {
    // The spacing of the samples that carry the surface, m: components that
    // such samples cannot resolve are faded out exactly as the GPU fades them
    // (for the grid's vertices, their cell size; for a pixel's normal, its
    // footprint). 0 keeps every component.
    double footprint_m = 0.0;
    // The horizon fade, 0..1: every height is scaled by it.
    double heightScale = 1.0;
};

// The displaced surface at one rest point.
struct SWELL_API SurfacePoint {
    glm::dvec3 displacement_m{0.0}; // from the rest point (x0.x, 0, x0.z)
    glm::dvec3 normal{0.0, 1.0, 0.0}; // unit, pointing up
};

class SWELL_API SurfaceQuery {
public:
    virtual ~SurfaceQuery();

    // The largest displacement any rest point can get, at any time.
    virtual WaveReach reach() const = 0;
    // The standard deviation of the surface height over space and time, m
    // (a quarter of the significant wave height): the scale shading uses to
    // tell a crest. The default is a quarter of reach().vertical_m.
    virtual double heightDeviation_m() const;

    // The displacement and unit normal at a rest point and time.
    virtual SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const = 0;

    // The displacement alone: surfaceAt()'s, for surfaces that can find it
    // without the normal more cheaply (the spectral model's CPU twin).
    virtual glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const;

    // The rest point whose displaced horizontal position is worldPoint_m.
    // The default solves x0 + Dxz(x0) = worldPoint_m by fixed-point steps;
    // surfaces with analytic derivatives override it with Newton's method.
    virtual glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const;

    // Surface height, m, at world (x, z): the displacement's y at restPointUnder().
    double heightAt(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const;
};

} // namespace swell
