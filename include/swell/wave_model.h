// A wave model: the ocean surface that the renderer draws. Its CPU queries
// are a SurfaceQuery (swell/surface_query.h), which is all the rest of Swell
// asks of it; what it adds is its GPU half (createGpu), and a name. Each of
// Swell's models lives in its own folder under src/ocean/, its CPU queries
// apart from its GPU half (src/ocean/<model>/gpu/), with its GLSL twin under
// shaders/ocean/. A host's model implements both in one class.
#pragma once

#include "swell/export.h"
#include "swell/surface_query.h"

#include <memory>
#include <string>
#include <string_view>

namespace swell {

class WaveModelGpu;
namespace gl {
class ShaderSources;
}

// SurfaceQuery is a virtual base: a model may inherit its queries from a
// CPU class of its own (GerstnerModel from GerstnerSurface, which the CPU
// tests and anything without a GPU use alone) and its GPU half from here.
class SWELL_API WaveModel : public virtual SurfaceQuery {
public:
    ~WaveModel() override;

    // A short lower-case name, as scene files and the benchmark write it.
    virtual std::string_view name() const = 0;
    // One line for people: what this instance sums ("32 waves, 4.1 .. 212 m").
    virtual std::string summary() const = 0;

    // The GPU half (swell/wave_model_gpu.h): what the model uploads each
    // frame and the GLSL file that defines oceanSurface() for the water
    // shaders (see shaders/ocean.glsl). Needs a current GL context; programs
    // of its own (compute shaders) are built from `shaders`.
    virtual std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const = 0;
};

struct Scene;
class Seabed;

// The model a scene describes: the Gerstner sum of its waves (resolveWaves()
// with limitSteepness() applied), over the scene's sea floor (Seabed(scene):
// the waves shoal, turn and break where it rises, swell/coast_field.h), or
// the spectral ocean of its wind (waves.model = "spectral"), which does not
// feel the floor. Throws swell::InputError when the waves or the floor are
// not usable.
SWELL_API std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene);
// The same over a floor of the caller's (the scene's joined by a host's
// heights: Renderer::setSeabedHeights).
SWELL_API std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene, const Seabed& seabed);

} // namespace swell
