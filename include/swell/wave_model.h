// The ocean surface as every other part of Swell sees it: one interface, many
// wave models behind it (Gerstner sums, flat water, a spectral ocean). The
// grid, culling, the reflection bounds, floating objects, the benchmark and
// the viewer use only this; each model lives in its own folder under
// src/ocean/ with its GLSL twin under shaders/ocean/.
//
// A model maps a rest point x0 (world x,z, m) at time t (s) to a displaced
// point x0 + D(x0, t). Queries take a SurfaceFilter saying which part of the
// surface to evaluate: the exact one (the default), or the one the GPU draws
// at a place, where the grid's cells drop the waves they cannot resolve and
// wave heights fade towards the horizon.
#pragma once

#include "swell/export.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace swell {

class WaveModelGpu;
namespace gl {
class ShaderSources;
}

// How far a model can move the surface from its rest plane, m: up or down,
// and sideways. Culling pads the grid's tiles by it, and the reflection's
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

class SWELL_API WaveModel {
public:
    virtual ~WaveModel();

    // A short lower-case name, as scene files and the benchmark write it.
    virtual std::string_view name() const = 0;
    // One line for people: what this instance sums ("32 waves, 4.1 .. 212 m").
    virtual std::string summary() const = 0;

    // The largest displacement any rest point can get, at any time.
    virtual WaveReach reach() const = 0;
    // The standard deviation of the surface height over space and time, m
    // (a quarter of the significant wave height): the scale shading uses to
    // tell a crest. The default is a quarter of reach().vertical_m.
    virtual double heightDeviation_m() const;

    // The displacement and unit normal at a rest point and time.
    virtual SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const = 0;

    // The displacement alone: surfaceAt()'s, for models that can find it
    // without the normal more cheaply (the spectral model's CPU twin).
    virtual glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const;

    // The rest point whose displaced horizontal position is worldPoint_m.
    // The default solves x0 + Dxz(x0) = worldPoint_m by fixed-point steps;
    // models with analytic derivatives override it with Newton's method.
    virtual glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const;

    // Surface height, m, at world (x, z): the displacement's y at restPointUnder().
    double heightAt(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const;

    // The GPU half (swell/wave_model_gpu.h): what the model uploads each
    // frame and the GLSL file that defines oceanSurface() for the water
    // shaders (see shaders/ocean.glsl). Needs a current GL context; programs
    // of its own (compute shaders) are built from `shaders`.
    virtual std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const = 0;
};

struct Scene;

// The model a scene describes: the Gerstner sum of its waves (resolveWaves()
// with limitSteepness() applied). Throws swell::InputError when the waves are
// not usable.
SWELL_API std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene);

} // namespace swell
