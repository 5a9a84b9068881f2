// The spray's kinematics once in GLSL (shaders/spray.glsl) and once in C++
// (src/render/spray_kinematics.h): a compute probe runs the shader's
// functions for a set of seeds (cells, slots, times, foam) and the C++
// twin must give the same lives, keys and ages, and the same drop places
// within a millimetre (float's exp and rounding). The bow's spray likewise:
// the sample a life reads, whether it lives, its launch and its drops.
#include "render/spray_kinematics.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/gl/shader.h"
#include "swell/gpu/spray.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

class SprayKinematicsTwin : public swell::test::GlTest {};

using namespace swell::detail;

struct Seed {
    glm::ivec4 cellSlot; // x, y: world cell; z: slot
    glm::vec4 timeFoam;  // x, y: the period's time; z: foam; w: the wind's share
};

struct SprayKinematicsResult {
    glm::uvec4 keyLives; // x: key; y: lives
    glm::vec4 ageInCell; // x: age; y, z: in cell
    glm::vec4 drops[SWELL_SPRAY_DROPS];
    glm::vec4 launch[SWELL_SPRAY_DROPS];
    glm::vec4 air[SWELL_SPRAY_DROPS];
};

constexpr float kSprayKinematicsWind_mps = 20.0f;

std::uint32_t floatBitsOf(float x)
{
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}
constexpr float kYoungFoam = 0.6f;
const glm::vec2 kWindDirection(std::cos(200.0f * 0.0174532925f), std::sin(200.0f * 0.0174532925f));

const char* const kSprayKinematicsProbe = R"(
#include "spray.glsl"
layout(local_size_x = 1) in;
struct Seed { ivec4 cellSlot; vec4 timeFoam; };
struct Result { uvec4 keyLives; vec4 ageInCell; vec4 drops[SWELL_SPRAY_DROPS]; vec4 launch[SWELL_SPRAY_DROPS]; vec4 air[SWELL_SPRAY_DROPS]; };
layout(std430, binding = 0) readonly buffer Seeds { Seed seeds[]; };
layout(std430, binding = 1) writeonly buffer Results { Result results[]; };
uniform vec2 windDirection;
uniform float windSpeed_mps;
uniform float youngFoam;
void main()
{
    Seed s = seeds[gl_GlobalInvocationID.x];
    SprayLife l = sprayLife(s.cellSlot.xy, s.cellSlot.z, s.timeFoam.xy);
    Result r;
    r.keyLives = uvec4(l.key, sprayLives(l.key, s.timeFoam.z, youngFoam, s.timeFoam.w) ? 1u : 0u, 0u, 0u);
    r.ageInCell = vec4(l.age_s, l.inCell, 0.0);
    for (uint d = 0u; d < uint(SWELL_SPRAY_DROPS); ++d) {
        vec3 launch = sprayLaunch(l.key, d, windDirection, windSpeed_mps);
        vec3 air = sprayAir(l.key, d, windDirection, windSpeed_mps);
        r.drops[d] = vec4(sprayDropOffset(launch, air, sprayTau_s(l.key, d), l.age_s), sprayTau_s(l.key, d));
        r.launch[d] = vec4(launch, 0.0);
        r.air[d] = vec4(air, 0.0);
    }
    results[gl_GlobalInvocationID.x] = r;
}
)";

std::vector<SprayKinematicsResult> runShader(const std::vector<Seed>& seeds)
{
    const swell::gl::Program program = swell::test::buildShaderProbe(kSprayKinematicsProbe);
    swell::gl::Buffer in = swell::gl::Buffer::create(), out = swell::gl::Buffer::create();
    glNamedBufferData(in.id(), GLsizeiptr(seeds.size() * sizeof(Seed)), seeds.data(), GL_STATIC_DRAW);
    glNamedBufferData(out.id(), GLsizeiptr(seeds.size() * sizeof(SprayKinematicsResult)), nullptr, GL_DYNAMIC_READ);
    const GLuint id = program.id();
    glUseProgram(id);
    glProgramUniform2f(id, glGetUniformLocation(id, "windDirection"), kWindDirection.x, kWindDirection.y);
    glProgramUniform1f(id, glGetUniformLocation(id, "windSpeed_mps"), kSprayKinematicsWind_mps);
    glProgramUniform1f(id, glGetUniformLocation(id, "youngFoam"), kYoungFoam);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint(seeds.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<SprayKinematicsResult> results(seeds.size());
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(results.size() * sizeof(SprayKinematicsResult)), results.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
    return results;
}

TEST_F(SprayKinematicsTwin, ShaderAndCppAgreeForEverySeed)
{
    static_assert(sizeof(SprayKinematicsResult) == 32 + 3 * 16 * SWELL_SPRAY_DROPS, "std430 layout");
    std::vector<Seed> seeds;
    // Cells on both sides of the origin, every slot, times within the first
    // period and in later ones, foam from none to a crest breaking now, the
    // wind's share from a near gale's to all.
    const double times_s[] = {0.37, 20.0, 611.3, 6600.25, 40000.8};
    const float foams[] = {0.0f, 0.15f, 0.25f, 0.33f, 0.7f};
    const float amounts[] = {0.05f, 0.5f, 1.0f};
    int n = 0;
    for (int cx = -3; cx <= 3; ++cx)
        for (int cz = -2; cz <= 2; ++cz)
            for (int slot = 0; slot < SWELL_SPRAY_SLOTS; ++slot, ++n) {
                const glm::vec2 t = sprayPeriodTime(times_s[n % 5]);
                seeds.push_back({glm::ivec4(cx * 977, cz * 31 - 5, slot, 0),
                                 glm::vec4(t, foams[(n / 5) % 5], amounts[n % 3])});
            }
    const std::vector<SprayKinematicsResult> gpu = runShader(seeds);
    int compared = 0, living = 0;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        const Seed& s = seeds[i];
        const SprayLife l = sprayLife(glm::ivec2(s.cellSlot), s.cellSlot.z, glm::vec2(s.timeFoam));
        // At a life's very start or end a last-bit difference in the age
        // picks the neighbouring life: such seeds are left out.
        if (l.age_s < 1e-4f || l.age_s > float(SWELL_SPRAY_LIFETIME_S) - 1e-4f)
            continue;
        ++compared;
        const SprayKinematicsResult& g = gpu[i];
        ASSERT_EQ(g.keyLives.x, l.key) << "seed " << i;
        EXPECT_NEAR(g.ageInCell.x, l.age_s, 1e-5f) << "seed " << i;
        EXPECT_EQ(glm::vec2(g.ageInCell.y, g.ageInCell.z), l.inCell) << "seed " << i;
        const bool lives = sprayLives(l.key, s.timeFoam.z, kYoungFoam, s.timeFoam.w);
        living += lives;
        EXPECT_EQ(g.keyLives.y != 0u, lives) << "seed " << i;
        for (std::uint32_t d = 0; d < SWELL_SPRAY_DROPS; ++d) {
            const glm::vec3 launch = sprayLaunch(l.key, d, kWindDirection, kSprayKinematicsWind_mps);
            const glm::vec3 air = sprayAir(l.key, d, kWindDirection, kSprayKinematicsWind_mps);
            EXPECT_LT(glm::length(glm::vec3(g.launch[d]) - launch), 1e-5f) << "seed " << i << " drop " << d;
            EXPECT_LT(glm::length(glm::vec3(g.air[d]) - air), 1e-5f) << "seed " << i << " drop " << d;
            const float tau_s = sprayTau_s(l.key, d);
            EXPECT_NEAR(g.drops[d].w, tau_s, 1e-6f * tau_s) << "seed " << i << " drop " << d;
            const glm::vec3 offset = sprayDropOffset(launch, air, tau_s, l.age_s);
            EXPECT_LT(glm::length(glm::vec3(g.drops[d]) - offset), 1e-3f)
                << "seed " << i << " drop " << d << ": shader " << g.drops[d].x << " " << g.drops[d].y << " "
                << g.drops[d].z << ", C++ " << offset.x << " " << offset.y << " " << offset.z;
        }
    }
    // Most seeds compared, and both outcomes of the crest signal met.
    EXPECT_GT(compared, int(seeds.size()) * 9 / 10);
    EXPECT_GT(living, 10);
    EXPECT_LT(living, compared - 10);
}

struct BowSeed {
    glm::vec4 forwardOutward; // x, y: heading; z, w: outward
    glm::vec4 motion;         // x: speed m/s; y: plunge m/s; z: share; w: the history's lag, s
    glm::uvec4 keyAge;        // x: key; y: the age's bits; z: the flare's cotangent's bits
};

struct BowResult {
    glm::ivec4 sampleLives; // x: sample; y: lives
    glm::vec4 sheet;        // x, y, z: the piece of sheet's place; w: its share torn
    glm::vec4 sheetLaunch;  // x, y, z: its launch; w: its response time
    glm::vec4 drops[SWELL_BOW_SPRAY_DROPS];
    glm::vec4 launch[SWELL_BOW_SPRAY_DROPS];
};

const char* const kBowProbe = R"(
#include "spray.glsl"
layout(local_size_x = 1) in;
struct BowSeed { vec4 forwardOutward; vec4 motion; uvec4 keyAge; };
struct BowResult { ivec4 sampleLives; vec4 sheet; vec4 sheetLaunch; vec4 drops[SWELL_BOW_SPRAY_DROPS]; vec4 launch[SWELL_BOW_SPRAY_DROPS]; };
layout(std430, binding = 0) readonly buffer Seeds { BowSeed seeds[]; };
layout(std430, binding = 1) writeonly buffer Results { BowResult results[]; };
uniform vec2 windDirection;
uniform float windSpeed_mps;
void main()
{
    BowSeed s = seeds[gl_GlobalInvocationID.x];
    uint key = s.keyAge.x;
    float age_s = uintBitsToFloat(s.keyAge.y);
    BowResult r;
    float flareCot = uintBitsToFloat(s.keyAge.z);
    r.sampleLives = ivec4(bowSpraySample(age_s, s.motion.w), bowSprayLives(key, s.motion.z) ? 1 : 0, 0, 0);
    vec3 sheetLaunch = bowSheetLaunch(key, s.forwardOutward.xy, s.forwardOutward.zw, s.motion.x, s.motion.y, flareCot);
    vec3 sheetAir = sprayAir(key, uint(SWELL_SPRAY_MIST_DROPS), windDirection, windSpeed_mps);
    r.sheet = vec4(sprayDropOffset(sheetLaunch, sheetAir, bowSheetTau_s(), age_s), bowSheetTorn(key, age_s));
    r.sheetLaunch = vec4(sheetLaunch, bowSheetTau_s());
    for (uint d = 0u; d < uint(SWELL_BOW_SPRAY_DROPS); ++d) {
        vec3 launch = bowSprayLaunch(key, d, s.forwardOutward.xy, s.forwardOutward.zw, s.motion.x, s.motion.y, flareCot);
        vec3 air = sprayAir(key, d, windDirection, windSpeed_mps);
        float tau_s = bowSprayTau_s(key, d);
        r.drops[d] = vec4(sprayDropOffset(launch, air, tau_s, age_s), tau_s);
        r.launch[d] = vec4(launch, 0.0);
    }
    results[gl_GlobalInvocationID.x] = r;
}
)";

TEST_F(SprayKinematicsTwin, BowShaderAndCppAgreeForEverySeed)
{
    static_assert(sizeof(BowResult) == 48 + 2 * 16 * SWELL_BOW_SPRAY_DROPS, "std430 layout");
    static_assert(sizeof(BowSeed) == 48, "std430 layout");
    std::vector<BowSeed> seeds;
    // Headings all round, either side, speeds from a crawl to 8 m/s,
    // plunges from none to a slam's, shares from none to all, ages over a
    // life (the sheet whole, torn and gone), lags over a sample, flares
    // from wall sided past the jet's limit.
    for (int n = 0; n < 240; ++n) {
        const float heading = 0.37f * float(n);
        const glm::vec2 forward(std::cos(heading), std::sin(heading));
        const float side = n % 2 == 0 ? 1.0f : -1.0f;
        const glm::vec2 outward = glm::normalize(side * glm::vec2(-forward.y, forward.x) + 0.3f * float(n % 3) * forward);
        const float age_s = float(SWELL_SPRAY_LIFETIME_S) * float((n * 37) % 101) / 101.0f + 0.003f;
        seeds.push_back({glm::vec4(forward, outward),
                         glm::vec4(0.5f + 0.03f * float(n), 0.02f * float(n % 90), float(n % 11) / 10.0f,
                                   float(n % 7) / 7.0f / float(SWELL_BOW_SPRAY_SAMPLES_PER_S)),
                         glm::uvec4(sprayHash(std::uint32_t(n) * 2654435761u), floatBitsOf(age_s),
                                    floatBitsOf(0.25f * float(n % 13)), 0u)});
    }
    const swell::gl::Program program = swell::test::buildShaderProbe(kBowProbe);
    swell::gl::Buffer in = swell::gl::Buffer::create(), out = swell::gl::Buffer::create();
    glNamedBufferData(in.id(), GLsizeiptr(seeds.size() * sizeof(BowSeed)), seeds.data(), GL_STATIC_DRAW);
    glNamedBufferData(out.id(), GLsizeiptr(seeds.size() * sizeof(BowResult)), nullptr, GL_DYNAMIC_READ);
    const GLuint id = program.id();
    glUseProgram(id);
    glProgramUniform2f(id, glGetUniformLocation(id, "windDirection"), kWindDirection.x, kWindDirection.y);
    glProgramUniform1f(id, glGetUniformLocation(id, "windSpeed_mps"), kSprayKinematicsWind_mps);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint(seeds.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<BowResult> gpu(seeds.size());
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(BowResult)), gpu.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
    int living = 0, whole = 0, gone = 0;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        const BowSeed& s = seeds[i];
        const std::uint32_t key = s.keyAge.x;
        float age_s;
        std::memcpy(&age_s, &s.keyAge.y, sizeof age_s);
        const glm::vec2 forward(s.forwardOutward.x, s.forwardOutward.y), outward(s.forwardOutward.z, s.forwardOutward.w);
        EXPECT_EQ(gpu[i].sampleLives.x, bowSpraySample(age_s, s.motion.w)) << "seed " << i;
        const bool lives = bowSprayLives(key, s.motion.z);
        living += lives;
        EXPECT_EQ(gpu[i].sampleLives.y != 0, lives) << "seed " << i;
        float flareCot;
        std::memcpy(&flareCot, &s.keyAge.z, sizeof flareCot);
        const glm::vec3 sheetLaunch = bowSheetLaunch(key, forward, outward, s.motion.x, s.motion.y, flareCot);
        EXPECT_LT(glm::length(glm::vec3(gpu[i].sheetLaunch) - sheetLaunch), 1e-5f * (1.0f + glm::length(sheetLaunch)))
            << "seed " << i;
        EXPECT_NEAR(gpu[i].sheetLaunch.w, bowSheetTau_s(), 1e-6f * bowSheetTau_s());
        const glm::vec3 sheet = sprayDropOffset(
            sheetLaunch, sprayAir(key, SWELL_SPRAY_MIST_DROPS, kWindDirection, kSprayKinematicsWind_mps), bowSheetTau_s(), age_s);
        EXPECT_LT(glm::length(glm::vec3(gpu[i].sheet) - sheet), 1e-3f) << "seed " << i;
        const float torn = bowSheetTorn(key, age_s);
        EXPECT_NEAR(gpu[i].sheet.w, torn, 1e-5f) << "seed " << i;
        whole += torn < 0.5f;
        gone += torn >= 1.0f;
        for (std::uint32_t d = 0; d < SWELL_BOW_SPRAY_DROPS; ++d) {
            const glm::vec3 launch = bowSprayLaunch(key, d, forward, outward, s.motion.x, s.motion.y, flareCot);
            EXPECT_LT(glm::length(glm::vec3(gpu[i].launch[d]) - launch), 1e-5f * (1.0f + glm::length(launch)))
                << "seed " << i << " drop " << d;
            const float tau_s = bowSprayTau_s(key, d);
            EXPECT_NEAR(gpu[i].drops[d].w, tau_s, 1e-6f * tau_s) << "seed " << i << " drop " << d;
            const glm::vec3 air = sprayAir(key, d, kWindDirection, kSprayKinematicsWind_mps);
            const glm::vec3 offset = sprayDropOffset(launch, air, tau_s, age_s);
            EXPECT_LT(glm::length(glm::vec3(gpu[i].drops[d]) - offset), 1e-3f) << "seed " << i << " drop " << d;
        }
    }
    // Both outcomes of the share met.
    EXPECT_GT(living, 20);
    EXPECT_LT(living, int(seeds.size()) - 20);
    // Sheets whole and sheets torn through among them.
    EXPECT_GT(whole, 20);
    EXPECT_GT(gone, 20);
}

} // namespace
