// Every GLSL file generated at build time from C++ (src/render/gpu/
// generate_glsl.cpp writes them next to the shaders, which include them):
// each uniform block's declaration (gl/block_layout.h), the structs blocks
// share, and the constants of swell/constants.h the shaders read. One list,
// read by the generator and by the tests that check it.
#pragma once

#include "gl/block_layout.h"
#include "ocean/foam/gpu/foam_noise_block.h"
#include "ocean/gpu/model_blocks.h"
#include "render/gpu/blocks.h"
#include "swell/constants.h"
#include "swell/gpu/bindings.h"

#include <fmt/format.h>

#include <string>
#include <string_view>
#include <vector>

namespace swell::detail {

template <class T>
const gl::BlockStruct& blockStructFor()
{
    return blockStructOf(static_cast<const T*>(nullptr));
}

// The renderer's uniform blocks, each in its own file. A new block adds its
// line here (a wave model's, in the model's folder: ocean/gpu/model_blocks.h).
inline std::vector<gl::UniformBlock> rendererGlslBlocks()
{
#define SWELL_BINDING(macro) #macro, macro
    return {
        {&blockStructFor<FrameUniforms>(), SWELL_BINDING(SWELL_BINDING_FRAME), "gpu/frame_block.glsl",
         "src/render/gpu/blocks.h"},
        {&blockStructFor<WakeUniforms>(), SWELL_BINDING(SWELL_BINDING_WAKE), "gpu/wake_block.glsl",
         "src/render/gpu/blocks.h"},
        {&blockStructFor<SurfaceSourcesUniforms>(), SWELL_BINDING(SWELL_BINDING_SURFACE_SOURCES),
         "gpu/surface_sources_block.glsl", "src/render/gpu/blocks.h"},
        {&blockStructFor<CausticsUniforms>(), SWELL_BINDING(SWELL_BINDING_CAUSTICS), "gpu/caustics_block.glsl",
         "src/render/gpu/blocks.h"},
        {&blockStructFor<CloudShadowUniforms>(), SWELL_BINDING(SWELL_BINDING_CLOUD_SHADOW),
         "gpu/cloud_shadow_block.glsl", "src/render/gpu/blocks.h"},
    };
#undef SWELL_BINDING
}

// Every uniform block: the renderer's and the wave models' own.
inline std::vector<gl::UniformBlock> glslBlocks()
{
    std::vector<gl::UniformBlock> blocks = rendererGlslBlocks();
    for (const std::vector<gl::UniformBlock>& model : {gerstnerGlslBlocks(), spectralGlslBlocks(), coastGlslBlocks()})
        blocks.insert(blocks.end(), model.begin(), model.end());
    return blocks;
}

// The structs several blocks and shader files share, each in its own file.
inline std::vector<const gl::BlockStruct*> glslSharedStructs() { return {&blockStructFor<FoamNoiseUniform>()}; }

// The constants of swell/constants.h the shaders read, as #defines of
// these names (gpu/constants.glsl).
struct GlslConstant {
    std::string_view name;
    double value;
};

inline std::vector<GlslConstant> glslConstants()
{
    return {
        {"SWELL_PI", kPi},
        {"SWELL_WATER_IOR", kWaterIor},
        {"SWELL_SUN_ANGULAR_DIAMETER_RAD", kSunAngularDiameter_rad},
        {"SWELL_ATMOSPHERE_BOTTOM_RADIUS_M", kAtmosphereBottomRadius_m},
        {"SWELL_ATMOSPHERE_TOP_RADIUS_M", kAtmosphereTopRadius_m},
        {"SWELL_RAYLEIGH_SCATTERING_R", kRayleighScatteringRed_per_m},
        {"SWELL_RAYLEIGH_SCATTERING_G", kRayleighScatteringGreen_per_m},
        {"SWELL_RAYLEIGH_SCATTERING_B", kRayleighScatteringBlue_per_m},
        {"SWELL_RAYLEIGH_SCALE_HEIGHT_M", kRayleighScaleHeight_m},
        {"SWELL_MIE_EXTINCTION", kMieExtinction_per_m},
        {"SWELL_MIE_SCATTERING", kMieScattering_per_m},
        {"SWELL_MIE_SCALE_HEIGHT_M", kMieScaleHeight_m},
        {"SWELL_MIE_ASYMMETRY", kMieAsymmetry},
        {"SWELL_OZONE_ABSORPTION_R", kOzoneAbsorptionRed_per_m},
        {"SWELL_OZONE_ABSORPTION_G", kOzoneAbsorptionGreen_per_m},
        {"SWELL_OZONE_ABSORPTION_B", kOzoneAbsorptionBlue_per_m},
        {"SWELL_OZONE_PEAK_ALTITUDE_M", kOzonePeakAltitude_m},
        {"SWELL_OZONE_HALF_WIDTH_M", kOzoneHalfWidth_m},
        {"SWELL_CLOUD_ASYMMETRY", kCloudDropletAsymmetry},
        {"SWELL_WATER_SCATTERING_PER_M", kWaterScattering_per_m},
        {"SWELL_WATER_PHASE_G", kWaterPhaseG},
        {"SWELL_SEA_WATER_SURFACE_TENSION_N_PER_M", kSeaWaterSurfaceTension_N_per_m},
        {"SWELL_SEA_WATER_DENSITY_KG_PER_M3", kSeaWaterDensity_kg_per_m3},
        {"SWELL_BREAKER_INDEX", kBreakerIndex},
    };
}

// A double as a GLSL float literal: the shortest text that reads back as
// the same double (so the float GLSL makes of it is the one the C++
// literal gives), with a decimal point where it has none.
inline std::string glslFloatLiteral(double value)
{
    std::string text = fmt::format("{}", value);
    if (text.find_first_of(".en") == std::string::npos)
        text += ".0";
    return text;
}

inline std::string glslConstantsFile()
{
    std::string text = "// Generated at build time from include/swell/constants.h (which gives each\n"
                       "// value's reason) by src/render/gpu/generate_glsl.cpp: do not edit.\n"
                       "#ifndef SWELL_GPU_CONSTANTS_GLSL\n#define SWELL_GPU_CONSTANTS_GLSL\n";
    for (const GlslConstant& c : glslConstants())
        text += fmt::format("#define {} {}\n", c.name, glslFloatLiteral(c.value));
    return text + "#endif\n";
}

struct GeneratedGlslFile {
    std::string name; // as the shaders include it, e.g. "gpu/frame_block.glsl"
    std::string text;
};

// Every generated file; a block or struct whose C++ layout std140 does not
// reproduce is a problem the generator reports instead of writing it.
inline std::vector<GeneratedGlslFile> generatedGlslFiles(std::string& problems)
{
    std::vector<GeneratedGlslFile> files;
    for (const gl::UniformBlock& block : glslBlocks()) {
        problems += gl::std140Problems(*block.layout);
        files.push_back({std::string(block.file), gl::glslFile(block)});
    }
    for (const gl::BlockStruct* shared : glslSharedStructs()) {
        problems += gl::std140Problems(*shared);
        files.push_back({std::string(shared->file), gl::glslFile(*shared)});
    }
    files.push_back({"gpu/constants.glsl", glslConstantsFile()});
    return files;
}

} // namespace swell::detail
