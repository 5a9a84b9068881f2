// The spectral model's GPU half (SpectralModel::createGpu): each frame at a
// new time, compute shaders transform rows, evolving the spectra as they read
// them, then columns (shaders/ocean/spectral_fft.comp), which also write the
// slopes and their second moments in half floats for shading, and mipmap
// those; then the whitecaps' foam steps. On a software rasteriser in an
// interactive frame the fields come from the CPU twin's FFTs instead.
// In a gpu/ folder, so it builds with the GL half (src/CMakeLists.txt).
#include "ocean/spectral/gpu/spectral_gpu.h"

#include "core/worker.h"
#include "gl/mip_downsample.h"
#include "gl/uniform_location.h"
#include "ocean/coast/gpu/coast_gpu.h"
#include "ocean/spectral/field_texels.h"
#include "ocean/foam/foam_texture.h"
#include "ocean/spectral/foam_replay.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/gpu/spectral_formats.h"
#include "ocean/spectral/gpu/spectral_uniforms.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/constants.h"
#include "swell/gl/context.h"
#include "swell/gl/shader.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
#include "swell/wave_model_gpu.h"

#include <fmt/format.h>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

namespace swell {

using namespace spectral;

namespace {

// A window that moves by more than this many texels since the foam's last
// step (a camera cut) replays the foam's history, as a cut in time does.
constexpr int kLongestFoamShift = kFoamSize / 4;

// The foam step's workgroups (spectral_foam.comp): tiles of kTile x kTile
// texels.
constexpr int kTile = SWELL_FOAM_STEP_GROUP;


class SpectralGpu final : public WaveModelGpu {
public:
    SpectralGpu(std::shared_ptr<const SpectralField> field, const CoastTrains* coast, const SpectralSettings& settings,
                const BreakingRamps& ramps, const gl::ShaderSources& shaders)
        : field_(std::move(field)), settings_(settings), ramps_(ramps), downsampler_(shaders),
          coast_(coast ? coast->trains.coast : nullptr, coast ? coast->trains : WaveSet{},
                 coast ? coast->depths : CoastTrainDepths{})
    {
        fftRows_ = gl::buildProgram(shaders, {{GL_COMPUTE_SHADER, "ocean/spectral_fft.comp"}}, {"SWELL_FFT_VERTICAL 0"});
        fftColumns_ = gl::buildProgram(shaders, {{GL_COMPUTE_SHADER, "ocean/spectral_fft.comp"}}, {"SWELL_FFT_VERTICAL 1"});
        foamStep_ = gl::buildProgram(shaders, {{GL_COMPUTE_SHADER, "ocean/spectral_foam.comp"}},
                                     {"SWELL_OCEAN_FILE \"ocean/spectral.glsl\""});
        const char* fft = "ocean/spectral_fft.comp";
        timeLocation_ = gl::requiredUniform(fftRows_, "time_s", fft);
        choppinessLocation_ = gl::requiredUniform(fftRows_, "choppiness", fft);
        patchLocation_ = gl::requiredUniform(fftRows_, "patchSize_m", fft);
        const char* foam = "ocean/spectral_foam.comp";
        decayLocation_ = gl::requiredUniform(foamStep_, "decay", foam);
        startLocation_ = gl::requiredUniform(foamStep_, "breakingStart", foam);
        spanLocation_ = gl::requiredUniform(foamStep_, "breakingSpan", foam);
        foamCascadesLocation_ = gl::requiredUniform(foamStep_, "foamCascades", foam);
        windowOriginLocation_ = gl::requiredUniform(foamStep_, "windowOrigin", foam);
        previousOriginLocation_ = gl::requiredUniform(foamStep_, "previousOrigin", foam);
        centreIndexLocation_ = gl::requiredUniform(foamStep_, "centreIndex", foam);
        centreFractionLocation_ = gl::requiredUniform(foamStep_, "centreFraction", foam);
        texelLocation_ = gl::requiredUniform(foamStep_, "texel_m", foam);

        const int n = kSize;
        auto array = [n](GLenum format, int levels, int layers = kCascades) {
            gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
            glTextureStorage3D(t.id(), levels, format, n, n, layers);
            return t;
        };
        initial_ = array(kInitialFormat, 1);
        omega_ = array(kOmegaFormat, 1);
        // With its mip chain: a far vertex reads a cascade's displacement
        // averaged over its footprint (spectral_cpu.h, filteredCascadeWeight).
        displacement_ = array(kSpectrumFormat, kFieldLevels);
        derivatives_ = array(kSpectrumFormat, 1);
        slopes_ = array(kSlopeFormat, kFieldLevels, kSlopeLayers);
        foam_ = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
        glTextureStorage3D(foam_.id(), kFoamFieldLevels, kFoamFormat, kFoamSize, kFoamSize, kFoamLevels);
        glTextureParameteri(foam_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(foam_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        clearFoam();
        work_ = {}; // not a frame's work
        glTextureParameteri(displacement_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTextureParameteri(displacement_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(derivatives_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(derivatives_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(slopes_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(slopes_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (const gl::Texture* t : {&displacement_, &derivatives_, &slopes_, &foam_}) {
            glTextureParameteri(t->id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTextureParameteri(t->id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        }
        std::vector<float> h0(size_t(n) * n * 4);
        std::vector<std::uint32_t> omegaBits(size_t(n) * n * 2);
        for (int c = 0; c < kCascades; ++c) {
            for (size_t i = 0; i < size_t(n) * n; ++i) {
                h0[4 * i + 0] = field_->h0[size_t(c)][i].real();
                h0[4 * i + 1] = field_->h0[size_t(c)][i].imag();
                h0[4 * i + 2] = field_->h0MinusConj[size_t(c)][i].real();
                h0[4 * i + 3] = field_->h0MinusConj[size_t(c)][i].imag();
                // The double's bits, low word first, as unpackDouble2x32 reads them.
                std::memcpy(&omegaBits[2 * i], &field_->omega_radps[size_t(c)][i], sizeof(double));
            }
            glTextureSubImage3D(initial_.id(), 0, 0, 0, c, n, n, 1, GL_RGBA, GL_FLOAT, h0.data());
            glTextureSubImage3D(omega_.id(), 0, 0, 0, c, n, n, 1, GL_RG_INTEGER, GL_UNSIGNED_INT, omegaBits.data());
        }
        uniforms_ = gl::Buffer::create();
        glNamedBufferStorage(uniforms_.id(), sizeof(SpectralUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        // A software rasteriser runs the GPU's replay steps on the CPU at
        // about 18 times the cost of FoamReplay's (0.19 s against 0.011 s
        // a step on llvmpipe); a GPU keeps them.
        if (gl::isSoftwareRasterizer())
            cpuReplay_ = std::make_unique<FoamReplay>(field_, ramps_);
    }

    std::string shaderFile() const override { return "ocean/spectral.glsl"; }

    void prepareFrame(glm::dvec2 gridCenter_m, double time_s) override
    {
        work_ = {};
        gridCenter_m_ = gridCenter_m;
        bool moved = false, cut = !foamStepped_;
        for (int level = 0; level < kFoamLevels; ++level) {
            windows_[size_t(level)] = foamWindowAt(gridCenter_m, foamTexel_m(*field_, level));
            const glm::ivec2 shift = windows_[size_t(level)].origin - previousOrigin_[size_t(level)];
            moved = moved || shift != glm::ivec2(0);
            cut = cut || std::abs(shift.x) > kLongestFoamShift || std::abs(shift.y) > kLongestFoamShift;
        }
        // The uniforms before any foam step: it samples the cascades through them.
        updateUniforms(gridCenter_m);
        const bool foam = settings_.foamLifetime_s > 0.0;
        if (!transformed_ || time_s != time_s_)
            advance(time_s, cut);
        else if (cut && foam && !interactive_)
            replayFoam(time_s);
        else if (moved && foam)
            stepFoam(time_s, 1.0f); // the same time: only the texels entering the windows are new
        buildMipmaps();
        coast_.prepareView(gridCenter_m, time_s);
    }

    void prepareView(glm::dvec2 gridCenter_m) override
    {
        earlier_ = false;
        updateUniforms(gridCenter_m);
        coast_.prepareView(gridCenter_m, time_s_);
    }

    // The displacements of the step before the last, when kept
    // (keepPrevious(); transform() copies them) and of that time.
    bool prepareEarlierView(glm::dvec2 gridCenter_m, double earlier_s) override
    {
        if (!keepPrevious_ || !previous_ || previousTime_s_ != earlier_s)
            return false;
        earlier_ = true;
        updateUniforms(gridCenter_m);
        coast_.prepareView(gridCenter_m, earlier_s);
        return true;
    }

    // The CPU twin's queries transform every cascade at each new time.
    bool answersFrameQueries() const override { return true; }

    // Its whitecaps are where crests break, torn by the wind it was made for.
    std::optional<CrestSpray> crestSpray() const override { return CrestSpray{settings_.wind.windSpeed_mps}; }

    void updateUniforms(glm::dvec2 gridCenter_m)
    {
        SpectralUniforms u{};
        for (int c = 0; c < kCascades; ++c) {
            const Cascade& cascade = field_->cascades[size_t(c)];
            const double scale = kSize / cascade.patch_m;
            // In double: the centre may be far from the origin.
            const glm::dvec2 origin = gridCenter_m - cascade.patch_m * glm::floor(gridCenter_m / cascade.patch_m);
            CascadeUniform& uc = u.cascades[c];
            uc.originTexels = glm::vec2(origin * scale);
            uc.texelsPerMetre = float(scale);
            uc.shortestWavelength_m = float(cascade.shortestWavelength_m());
            double shortestWarp_m = std::numeric_limits<double>::infinity();
            for (int i = 0; i < kWarpWaves; ++i) {
                const WarpWave& w = field_->warps[size_t(c)][size_t(i)];
                uc.warp[i] = {glm::vec2(w.wavevector_radpm), glm::vec2(w.amplitude_m), float(warpPhaseAt(w, gridCenter_m))};
                const double k = glm::length(w.wavevector_radpm);
                if (k > 0.0)
                    shortestWarp_m = std::min(shortestWarp_m, kTwoPi / k);
            }
            uc.vertexWarpCell_m = float(std::min(shortestWarp_m / SWELL_FFT_WARP_CELLS_PER_WAVELENGTH, 1e30));
        }
        const double wind_rad = settings_.wind.windDirection_deg * kPi / 180.0;
        u.windDirection = glm::vec2(std::cos(wind_rad), std::sin(wind_rad));
        // Wind-driven streaks of foam appear from about Beaufort 6 and are
        // marked from Beaufort 8 (10.8 and 17.2 m/s; WMO Beaufort scale).
        const double u10 = settings_.wind.windSpeed_mps;
        const double streak = std::clamp((u10 - 10.8) / (17.2 - 10.8), 0.0, 1.0);
        u.foamStreak = float(1.0 + 3.0 * streak * streak * (3.0 - 2.0 * streak));
        u.unresolvedSlopeVariance = float(field_->unresolvedSlopeVariance);
        for (int level = 0; level < kFoamLevels; ++level)
            u.foamLevels[level] = {windows_[size_t(level)].originTexels, float(1.0 / foamTexel_m(*field_, level)), 0.0f};
        const auto noise = foam::foamNoiseMaps(gridCenter_m, glm::dvec2(u.windDirection), double(u.foamStreak));
        for (int i = 0; i < foam::kFoamNoiseMaps; ++i) {
            const foam::FoamNoiseMap& m = noise[size_t(i)];
            u.foamNoise[i] = {glm::vec4(m.map[0], m.map[1]), m.offset_cells, m.cyclesPerMetre};
        }
        // Foam decays as exp(-age / lifetime) from 1 where the crest folds.
        const double lifetime = settings_.foamLifetime_s > 0.0 ? settings_.foamLifetime_s : 1.0;
        u.breakingFoamAmount = float(std::exp(-foam::kBreakingFoamAge_s / lifetime));
        glNamedBufferSubData(uniforms_.id(), 0, sizeof(u), &u);
    }

    void bind() const override
    {
        coast_.bind();
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_OCEAN, uniforms_.id());
        glBindTextureUnit(SWELL_UNIT_OCEAN0, earlier_ ? previous_.id() : displacement_.id());
        glBindTextureUnit(SWELL_UNIT_OCEAN1, slopes_.id());
        glBindTextureUnit(SWELL_UNIT_OCEAN2, foam_.id());
        glBindTextureUnit(SWELL_UNIT_OCEAN3, derivatives_.id());
    }

private:
    // Moves the fields to time_s and the foam with them; after a cut (in
    // time, or of the camera), the foam's history is replayed first, except
    // that an interactive model goes on from any earlier frame in one step.
    void advance(double time_s, bool cut)
    {
        const double lifetime = settings_.foamLifetime_s;
        const bool foam = lifetime > 0.0;
        const bool continues = transformed_ && time_s >= time_s_ &&
                               (interactive_ || (!cut && time_s - time_s_ <= kLongestFoamStep_s));
        if (foam && !continues) {
            replayFoam(time_s);
        } else {
            const double dt = transformed_ ? time_s - time_s_ : 0.0;
            transform(time_s);
            if (foam)
                stepFoam(time_s, float(std::exp(-dt / lifetime)));
        }
    }

    // The foam's recent history on a fixed lattice of steps ending at time_s
    // (foamReplayOffsets_s), starting from none (or from the history's
    // start, when that is later), so a still shows the foam a sequence
    // arriving there would (the same for every still at that time and
    // place); leaves the fields at time_s.
    void replayFoam(double time_s)
    {
        const double lifetime = settings_.foamLifetime_s;
        std::vector<double> offsets = foamReplayOffsets_s(lifetime);
        // Nothing from before the history's start: the first step on or after it starts afresh.
        std::erase_if(offsets, [&](double offset_s) { return offset_s > 0.0 && time_s - offset_s < settings_.historyStart_s; });
        if (cpuReplay_ && offsets.size() > 1) {
            // The steps before the last on the CPU (the same steps, the same
            // fields), the last on the GPU with every field, as below.
            std::vector<double> times_s;
            for (size_t i = 0; i + 1 < offsets.size(); ++i)
                times_s.push_back(time_s - offsets[i]);
            const auto& foam = cpuReplay_->run(gridCenter_m_, windows_, times_s, lifetime);
            for (int level = 0; level < kFoamLevels; ++level) {
                glTextureSubImage3D(foam_.id(), 0, 0, 0, level, kFoamSize, kFoamSize, 1, GL_RED, GL_FLOAT,
                                    foam[size_t(level)].data());
                work_.bytesWritten += texelBytes(kFoamFormat) * kFoamSize * kFoamSize;
                previousOrigin_[size_t(level)] = windows_[size_t(level)].origin;
            }
            foamStepped_ = true;
            work_.foamSteps += int(times_s.size());
            transform(time_s, kCascades);
            stepFoam(time_s, float(std::exp(-offsets[offsets.size() - 2] / lifetime)));
            return;
        }
        for (size_t i = 0; i < offsets.size(); ++i) {
            // The steps before the last need only what a foam step reads:
            // the folding cascades' fields, without mipmaps (half the
            // transforms' work, and most of a replay's time on llvmpipe).
            const bool last = i + 1 == offsets.size();
            transform(time_s - offsets[i], last ? kCascades : kFoamCascades);
            const float decay = i == 0 ? 0.0f : float(std::exp(-(offsets[i - 1] - offsets[i]) / lifetime));
            stepFoam(time_s - offsets[i], decay, last);
        }
    }

    // One step of the foam in every level's window: decay what was there
    // (what the window still holds), make foam where the surface folds.
    // The mipmaps are for drawing (the far foam's mean); a step reads only
    // the base level.
    // Before the history's start there is no foam: the windows are cleared.
    void stepFoam(double time_s, float decay, bool mipmaps = true)
    {
        if (time_s < settings_.historyStart_s) {
            clearFoam();
            for (int level = 0; level < kFoamLevels; ++level)
                previousOrigin_[size_t(level)] = windows_[size_t(level)].origin;
            foamStepped_ = true;
            return;
        }
        ++work_.foamSteps;
        glUseProgram(foamStep_.id());
        glUniform1f(decayLocation_, decay);
        std::array<float, kFoamLevels> start{}, span{};
        for (int level = 0; level < kFoamLevels; ++level) {
            start[size_t(level)] = ramps_[size_t(level)].start;
            span[size_t(level)] = ramps_[size_t(level)].span;
        }
        glUniform1fv(startLocation_, kFoamLevels, start.data());
        glUniform1fv(spanLocation_, kFoamLevels, span.data());
        glUniform1i(foamCascadesLocation_, kFoamCascades);
        std::array<glm::ivec2, kFoamLevels> origin{}, centre{};
        std::array<glm::vec2, kFoamLevels> fraction{};
        std::array<float, kFoamLevels> texel_m{};
        for (int level = 0; level < kFoamLevels; ++level) {
            const FoamWindow& w = windows_[size_t(level)];
            origin[size_t(level)] = w.origin;
            centre[size_t(level)] = w.centreIndex;
            fraction[size_t(level)] = w.centreFraction;
            texel_m[size_t(level)] = float(foamTexel_m(*field_, level));
        }
        glUniform2iv(windowOriginLocation_, kFoamLevels, &origin[0].x);
        glUniform2iv(previousOriginLocation_, kFoamLevels, &previousOrigin_[0].x);
        glUniform2iv(centreIndexLocation_, kFoamLevels, &centre[0].x);
        glUniform2fv(centreFractionLocation_, kFoamLevels, &fraction[0].x);
        glUniform1fv(texelLocation_, kFoamLevels, texel_m.data());
        // The cascades, read through the samplers spectral.glsl declares.
        bind();
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_FOAM, foam_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, kFoamFormat);
        // Writes every texel of each level's window (the base level).
        beginStage("foam");
        dispatch(kFoamSize / kTile, kFoamSize / kTile, kFoamLevels, texelBytes(kFoamFormat) * kTile * kTile);
        barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        endStage("foam");
        foamMipmapsStale_ = foamMipmapsStale_ || mipmaps;
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_FOAM, 0, 0, GL_FALSE, 0, GL_READ_ONLY, kFoamFormat);
        glUseProgram(0);
        previousOrigin_ = origin;
        foamStepped_ = true;
    }

    // A software rasteriser's interactive view takes the fields from the
    // CPU's FFTs (field_texels.h: the column pass's texels, within its float
    // rounding; tests/gl/test_spectral_fields.cpp), at about a third of the
    // passes' CPU there. Stills, videos and the benchmark keep the passes.
    // The rasteriser's threads are idle meanwhile, so the cascades' FFTs and
    // texels are shared with one persistent worker (CpuSurface::fieldsAt
    // with a Worker: the same floats as on one thread, bit for bit);
    // the uploads stay on this thread, the context's.
    void uploadFields(double time_s, int cascades)
    {
        beginStage("fields on the cpu");
        if (!fieldTwin_) {
            fieldTwin_ = std::make_unique<CpuSurface>(field_);
            fieldWorker_ = std::make_unique<detail::Worker>();
        }
        sizeFieldTexels(cascades, texels_);
        fieldTwin_->fieldsAt(time_s, *fieldWorker_, [&](const CpuSurface::Fields& fields, int c) {
            if (c < cascades)
                cascadeTexels(fields, c, texels_);
        });
        const GLsizei n = kSize;
        glTextureSubImage3D(displacement_.id(), 0, 0, 0, 0, n, n, cascades, GL_RGBA, GL_FLOAT, texels_.displacement.data());
        glTextureSubImage3D(derivatives_.id(), 0, 0, 0, 0, n, n, cascades, GL_RGBA, GL_FLOAT, texels_.derivatives.data());
        glTextureSubImage3D(slopes_.id(), 0, 0, 0, 0, n, n, cascades, GL_RGBA, GL_FLOAT, texels_.derivatives.data());
        glTextureSubImage3D(slopes_.id(), 0, 0, 0, kCascades, n, n, cascades, GL_RGBA, GL_FLOAT,
                            texels_.slopeMoments.data());
        work_.bytesWritten += (2 * texelBytes(kSpectrumFormat) + 2 * texelBytes(kSlopeFormat)) * n * n * cascades;
        ++work_.transforms;
        slopeMipmapsStale_ = slopeMipmapsStale_ || cascades == kCascades;
        transformed_ = true;
        time_s_ = time_s;
        endStage("fields on the cpu");
    }

    // The fields of cascades 0 .. cascades - 1 at time_s; their derivatives'
    // mipmaps only when every cascade is transformed (a full frame's fields).
    void transform(double time_s, int cascades = kCascades)
    {
        keepFields(time_s, cascades);
        if (interactive_ && cpuReplay_) {
            uploadFields(time_s, cascades);
            return;
        }
        // The row pass evolves the spectra as it reads them (no image of
        // them is written first), then transforms every row in place.
        glUseProgram(fftRows_.id());
        glUniform1d(timeLocation_, time_s);
        glUniform1f(choppinessLocation_, float(field_->choppiness));
        float patches[kCascades];
        for (int c = 0; c < kCascades; ++c)
            patches[c] = float(field_->cascades[size_t(c)].patch_m);
        glUniform1fv(patchLocation_, kCascades, patches);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_INITIAL, initial_.id(), 0, GL_TRUE, 0, GL_READ_ONLY, kInitialFormat);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_OMEGA, omega_.id(), 0, GL_TRUE, 0, GL_READ_ONLY, kOmegaFormat);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_DISPLACEMENT, displacement_.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           kSpectrumFormat);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_DERIVATIVES, derivatives_.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           kSpectrumFormat);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_SLOPES, slopes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, kSlopeFormat);
        ++work_.transforms;
        // One workgroup per row (then column) of each cascade, writing the
        // line of both images (displacement, derivatives).
        const long long twoSpectra = 2 * texelBytes(kSpectrumFormat);
        beginStage("fft rows");
        dispatch(kSize, GLuint(cascades), 1, twoSpectra * kSize);
        barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        endStage("fft rows");
        // The columns also write the shading's copy of the derivatives and
        // the slopes' second moments.
        beginStage("fft columns");
        glUseProgram(fftColumns_.id());
        dispatch(kSize, GLuint(cascades), 1, (twoSpectra + 2 * texelBytes(kSlopeFormat)) * kSize);
        barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        endStage("fft columns");
        slopeMipmapsStale_ = slopeMipmapsStale_ || cascades == kCascades;
        for (GLuint unit = SWELL_IMAGE_SPECTRAL_INITIAL; unit <= SWELL_IMAGE_SPECTRAL_DERIVATIVES; ++unit)
            glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(SWELL_IMAGE_SPECTRAL_SLOPES, 0, 0, GL_FALSE, 0, GL_READ_ONLY, kSlopeFormat);
        glUseProgram(0);
        transformed_ = true;
        time_s_ = time_s;
    }

    // The GL calls that do the GPU's work, each counted in work_ where it is
    // made. A dispatch of groups x * y * z writes `bytesPerGroup` each.
    void dispatch(GLuint x, GLuint y, GLuint z, long long bytesPerGroup)
    {
        glDispatchCompute(x, y, z);
        ++work_.dispatches;
        work_.bytesWritten += (long long)x * y * z * bytesPerGroup;
    }
    void barrier(GLbitfield bits)
    {
        glMemoryBarrier(bits);
        ++work_.barriers;
    }
    // The mipmaps of what the frame's steps changed: the slopes' (every
    // cascade transformed) and the foam's (a step that keeps them), built
    // after the last step (a foam step reads only the fields' base level),
    // both in the same dispatches where the pass can (gl/mip_downsample.h:
    // a compute pass, from shared memory on a GPU, by blocks on a software
    // rasteriser).
    void buildMipmaps()
    {
        const gl::MipDownsampler::Chain slopes{&slopes_, kSlopeFormat, kSize, kFieldLevels, kSlopeLayers};
        const gl::MipDownsampler::Chain foam{&foam_, kFoamFormat, kFoamSize, kFoamFieldLevels, kFoamLevels};
        if (!slopeMipmapsStale_ && !foamMipmapsStale_)
            return;
        const char* stage = !foamMipmapsStale_ ? "slope mipmaps" : !slopeMipmapsStale_ ? "foam mipmaps" : "mipmaps";
        beginStage(stage);
        const gl::MipDownsampler::Work work = slopeMipmapsStale_ && foamMipmapsStale_ ? downsampler_.run(slopes, foam)
                                              : slopeMipmapsStale_                   ? downsampler_.run(slopes)
                                                                                     : downsampler_.run(foam);
        work_.dispatches += work.dispatches;
        work_.barriers += work.barriers;
        // The displacement's chain changes with the slopes' (every cascade
        // transformed): the layers far vertices read filtered.
        if (slopeMipmapsStale_) {
            const gl::MipDownsampler::Work moved =
                downsampler_.run({&displacement_, kSpectrumFormat, kSize, kFieldLevels, kFilteredCascades});
            work_.dispatches += moved.dispatches;
            work_.barriers += moved.barriers;
        }
        endStage(stage);
        // Levels 1 and up of each chain built, in its own format.
        if (slopeMipmapsStale_)
            work_.bytesWritten += texelBytes(kSlopeFormat) * mipTexels(kSize, kFieldLevels, kSlopeLayers, 1) +
                                  texelBytes(kSpectrumFormat) * mipTexels(kSize, kFieldLevels, kFilteredCascades, 1);
        if (foamMipmapsStale_)
            work_.bytesWritten += texelBytes(kFoamFormat) * mipTexels(kFoamSize, kFoamFieldLevels, kFoamLevels, 1);
        slopeMipmapsStale_ = foamMipmapsStale_ = false;
    }
    // Before a transform to time_s: the fields there now copied for
    // prepareEarlierView() when asked to keep them and they are of one
    // time (the foam's replay transforms some cascades alone).
    void keepFields(double time_s, int cascades)
    {
        if (keepPrevious_ && std::isfinite(fieldsTime_s_)) {
            if (!previous_) {
                previous_ = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
                glTextureStorage3D(previous_.id(), kFieldLevels, kSpectrumFormat, kSize, kSize, kCascades);
                glTextureParameteri(previous_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
                glTextureParameteri(previous_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            }
            // Every cascade's base, and the chain of those far vertices read
            // filtered (the fields of one time have theirs, built with the
            // last step's mipmaps).
            for (int level = 0; level < kFieldLevels; ++level)
                glCopyImageSubData(displacement_.id(), GL_TEXTURE_2D_ARRAY, level, 0, 0, 0, previous_.id(),
                                   GL_TEXTURE_2D_ARRAY, level, 0, 0, 0, kSize >> level, kSize >> level,
                                   level == 0 ? kCascades : kFilteredCascades);
            work_.bytesWritten += texelBytes(kSpectrumFormat) * (mipTexels(kSize, 1, kCascades) +
                                                                 mipTexels(kSize, kFieldLevels, kFilteredCascades, 1));
        }
        previousTime_s_ = keepPrevious_ ? fieldsTime_s_ : kNoTime;
        fieldsTime_s_ = cascades == kCascades ? time_s : kNoTime;
    }

    // Every level of the foam's windows to none.
    void clearFoam()
    {
        const float zero = 0.0f;
        for (int level = 0; level < kFoamFieldLevels; ++level)
            glClearTexImage(foam_.id(), level, GL_RED, GL_FLOAT, &zero);
        work_.bytesWritten += texelBytes(kFoamFormat) * mipTexels(kFoamSize, kFoamFieldLevels, kFoamLevels);
    }

    // Mip levels of the cascades' fields and of the foam's windows.
    static constexpr int kFieldLevels = SWELL_FFT_LOG2_SIZE + 1;
    // The displacement's layers whose chain is built (the rest: their base).
    static constexpr int kFilteredCascades = SWELL_FFT_FILTERED_CASCADES;
    // The slopes' image: each cascade's derivatives, then each one's slope moments.
    static constexpr int kSlopeLayers = 2 * kCascades;
    static constexpr int kFoamFieldLevels = SWELL_FOAM_LOG2_SIZE + 1;

    std::shared_ptr<const SpectralField> field_;
    SpectralSettings settings_;
    BreakingRamps ramps_;
    // Each foam level's window now, and where it was at the foam's last step.
    std::array<FoamWindow, kFoamLevels> windows_{};
    std::array<glm::ivec2, kFoamLevels> previousOrigin_{};
    bool foamStepped_ = false;
    // Base levels changed since their mipmaps were built (buildMipmaps()).
    bool slopeMipmapsStale_ = false, foamMipmapsStale_ = false;
    glm::dvec2 gridCenter_m_{0.0}; // this frame's
    // The replay's steps before the last on the CPU: only on a software rasteriser.
    std::unique_ptr<FoamReplay> cpuReplay_;
    // uploadFields()'s own twin (the model's serves the bodies' worker
    // thread meanwhile), the thread it shares the transforms with, and
    // texels, made when first used.
    std::unique_ptr<CpuSurface> fieldTwin_;
    std::unique_ptr<detail::Worker> fieldWorker_;
    FieldTexels texels_;
    gl::Program fftRows_, fftColumns_, foamStep_;
    gl::MipDownsampler downsampler_;
    // Its trains' coast field, or an empty one (ocean/coast/gpu/coast_gpu.h).
    detail::CoastGpu coast_;
    // Uniform locations, looked up once.
    GLint timeLocation_ = -1, choppinessLocation_ = -1, patchLocation_ = -1;
    GLint decayLocation_ = -1, startLocation_ = -1, spanLocation_ = -1, foamCascadesLocation_ = -1;
    GLint windowOriginLocation_ = -1, previousOriginLocation_ = -1, centreIndexLocation_ = -1;
    GLint centreFractionLocation_ = -1, texelLocation_ = -1;
    gl::Texture initial_, omega_, displacement_, derivatives_, slopes_, foam_;
    gl::Buffer uniforms_;
    bool transformed_ = false;
    double time_s_ = 0.0;
    // The displacements' time (NaN where cascades of other times are
    // mixed), and the kept copy of the step before's and its time.
    static constexpr double kNoTime = std::numeric_limits<double>::quiet_NaN();
    double fieldsTime_s_ = kNoTime, previousTime_s_ = kNoTime;
    gl::Texture previous_;
    bool earlier_ = false; // bind() binds previous_: prepareEarlierView() was last
};

} // namespace

namespace spectral {

std::unique_ptr<WaveModelGpu> makeSpectralGpu(std::shared_ptr<const SpectralField> field,
                                              std::shared_ptr<const CoastTrains> coast,
                                              const SpectralSettings& settings, const BreakingRamps& ramps,
                                              const gl::ShaderSources& shaders)
{
    return std::make_unique<SpectralGpu>(std::move(field), coast.get(), settings, ramps, shaders);
}

} // namespace spectral

} // namespace swell
