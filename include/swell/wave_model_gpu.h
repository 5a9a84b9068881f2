// The GPU half of a wave model (swell/wave_model.h), apart from its CPU
// queries: what WaveModel::createGpu() returns. A model of a host's own
// implements both: the queries there, the uploads and bindings here. The water shaders call
// oceanSurface() and oceanShading(), defined by the model's GLSL file; the
// renderer builds the water programs with that file as SWELL_OCEAN_FILE
// (shaders/ocean.glsl includes it), so no shader names a model. A host's
// model adds its GLSL file to the renderer's gl::ShaderSources.
//
// A model's GLSL file defines, under an include guard:
//   SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
// where restOffset_m is the rest point relative to the grid centre (m),
// footprint_m and heightScale mean what swell::SurfaceFilter's fields mean,
// and SurfacePoint (shaders/ocean.glsl) holds the displacement and the unit
// normal (with the partial derivatives it came from), and oceanShading() as
// shaders/ocean.glsl describes. It reads only what prepareFrame() uploaded
// and bind() bound, at binding points of its own from swell/gpu/bindings.h.
#pragma once

#include "swell/export.h"
#include "swell/pass_observer.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace swell {

class SWELL_API WaveModelGpu {
public:
    virtual ~WaveModelGpu() = default;

    // The GLSL file under shaders/ that defines oceanSurface(), e.g. "ocean/gerstner.glsl".
    virtual std::string shaderFile() const = 0;

    // The spray the wind tears from the model's breaking crests. The
    // renderer's crest spray (shaders/spray_clumps.comp) finds where crests
    // broke lately through the model's GLSL file, which must then define
    //   float worldFoam(vec2 restOffset_m, float footprint_m, bool bSpline)
    // (the whitecap foam at a rest point, 0..1), and breakingFoamAmount
    // (foam above it was made by a crest breaking now) and windDirection
    // (unit, x, z) among its uniforms, as ocean/spectral.glsl does.
    struct CrestSpray {
        double windSpeed_mps = 0.0; // at 10 m: how much spray (none below Beaufort 7)
    };
    // None (the default): the model's crests do not break, and it draws no
    // crest spray.
    virtual std::optional<CrestSpray> crestSpray() const { return std::nullopt; }

    // The simulation's step (Renderer::advanceTo): moves what the model
    // simulates to time_s (s) around gridCenter_m (absolute world x,z, m;
    // the spectral model's foam windows), and uploads what the shaders read
    // for a view of that centre.
    virtual void prepareFrame(glm::dvec2 gridCenter_m, double time_s) = 0;

    // One view of the time prepareFrame() reached, whose grid is centred at
    // gridCenter_m: uploads what its shaders read (phases referenced to that
    // centre, so float precision is spent near the camera). Simulates
    // nothing.
    virtual void prepareView(glm::dvec2 gridCenter_m) = 0;

    // Binds the buffers and textures prepareFrame() filled.
    virtual void bind() const = 0;
    // The host's motion vectors (DrawOptions::motionVectors) need the
    // surface of the view's previous draw: uploads what the shaders read so
    // that, once bound, oceanSurface() answers for earlier_s (earlier than
    // the time prepareFrame() reached) on the grid centred at gridCenter_m,
    // and says whether it could. prepareView() brings the shaders back to
    // the current time. Simulates nothing. The default cannot (the motion
    // vectors then leave the water's own motion out); the Gerstner sum and
    // the flat sea can at any time, the spectral sea at the time of its step
    // before the last, whose fields it keeps once keepPreviousStep(true).
    virtual bool prepareEarlierView(glm::dvec2 gridCenter_m, double earlier_s)
    {
        (void)gridCenter_m;
        (void)earlier_s;
        return false;
    }
    // Asks a model that simulates to keep the fields of its step before the
    // last from now on (a copy a step), for prepareEarlierView(). Off by
    // default: nothing is kept or copied.
    void keepPreviousStep(bool keep) { keepPrevious_ = keep; }
    // Whether the renderer answers its frame's own water queries (its
    // floating objects', its eye's side of the water) on the GPU from this
    // model's fields, reading the answers back in the frame, rather than
    // through the model's CPU queries. Worth it where those are costly (the
    // spectral model's CPU twin transforms every cascade at each new time);
    // not where they are cheap (a sum of Gerstner waves), since reading
    // back makes the CPU wait for the GPU.
    virtual bool answersFrameQueries() const { return false; }

    // An interactive model (the viewer's) never replays its history on a
    // frame later than the last, however long the frame or far the camera
    // moved: it steps once, so a slow frame does not make the next one
    // slower. Only its first frame and a frame earlier than the last replay.
    void setInteractive(bool interactive) { interactive_ = interactive; }

    // The simulation work done since the last call (for the frame counters,
    // the tests that hold the interactive rule, and those that hold that a
    // view simulates nothing), and forgets it.
    struct Work {
        int transforms = 0; // sets of inverse FFTs (one time, some cascades)
        int foamSteps = 0;  // steps of the foam
        // What it asked of the GPU, counted where it makes the calls: exact,
        // the same in every run and on every machine (the benchmark's
        // machine-independent figures). A model of a host's counts its own.
        int dispatches = 0; // glDispatchCompute calls
        int barriers = 0;   // glMemoryBarrier calls
        int mipmaps = 0;    // glGenerateTextureMipmap calls
        // Bytes of GPU memory written: each texel its dispatches write times
        // the size of the image's format (an image read and written in place
        // counts once per dispatch that writes it), the mipmap levels
        // generated, textures cleared, and images uploaded from the CPU (the
        // spectral model's foam replayed there). Not the uniforms it uploads.
        long long bytesWritten = 0;
        Work& operator+=(const Work& other)
        {
            transforms += other.transforms;
            foamSteps += other.foamSteps;
            dispatches += other.dispatches;
            barriers += other.barriers;
            mipmaps += other.mipmaps;
            bytesWritten += other.bytesWritten;
            return *this;
        }
    };
    Work takeWork()
    {
        const Work work = work_;
        work_ = {};
        return work;
    }

    // Told of the stages of the model's GPU work within the "ocean" pass
    // (swell/pass_observer.h), for the benchmark's timing; the renderer
    // sets it. Null: no one is told.
    void setStageObserver(PassObserver* observer) { stageObserver_ = observer; }

protected:
    void beginStage(const char* name) const
    {
        if (stageObserver_)
            stageObserver_->beginPass(name);
    }
    void endStage(const char* name) const
    {
        if (stageObserver_)
            stageObserver_->endPass(name);
    }

    bool interactive_ = false;
    bool keepPrevious_ = false;
    Work work_;

private:
    PassObserver* stageObserver_ = nullptr;
};

} // namespace swell
