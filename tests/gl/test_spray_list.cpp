// The spray's list of its living clumps (shaders/spray_list.comp,
// render/spray_passes.cpp): from every slot's record, the living slots in
// the slots' order and then the rest (a stable partition: the order the
// streaks are blended in, so a still reproduces), and the commands of the
// streaks' dispatch and draw sized by the living count. Run on records
// made by hand, crest and bow alike, with runs of the living and the dead
// across the workgroup's invocations' runs of slots.
#include "render/spray_buffers.h"
#include "support/gl_test.h"
#include "swell/gl/shader.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/spray.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace {

class SprayList : public swell::test::GlTest {};

struct Commands {
    std::uint32_t drawCount, drawInstances, drawFirst, drawBaseInstance;
    std::uint32_t groups[3];
    std::uint32_t living;
};
static_assert(sizeof(Commands) == swell::detail::kSprayCommandsBytes);

struct Listed {
    std::vector<std::uint32_t> list;
    Commands commands;
};

// Runs spray_list.comp over records of recordBytes whose opacities are
// `opacity` (the rest of each record zero).
Listed listOf(const std::vector<float>& opacity, long long recordBytes, bool bow)
{
    std::vector<std::string> defines;
    if (bow)
        defines.push_back("SWELL_BOW_SPRAY 1");
    const swell::gl::Program program = swell::gl::buildProgram(
        swell::gl::ShaderSources::embedded(), {{GL_COMPUTE_SHADER, "spray_list.comp"}}, defines);
    const std::size_t floats = std::size_t(recordBytes / 4);
    std::vector<float> records(opacity.size() * floats, 0.0f);
    for (std::size_t i = 0; i < opacity.size(); ++i)
        records[i * floats + 7] = opacity[i]; // windOpacity.w
    swell::gl::Buffer clumps = swell::gl::Buffer::create(), list = swell::gl::Buffer::create(),
                      commands = swell::gl::Buffer::create();
    glNamedBufferData(clumps.id(), GLsizeiptr(records.size() * 4), records.data(), GL_STATIC_DRAW);
    // Filled with a value the pass must overwrite everywhere.
    const std::vector<std::uint32_t> stale(opacity.size(), 0xdeadbeefu);
    glNamedBufferData(list.id(), GLsizeiptr(stale.size() * 4), stale.data(), GL_DYNAMIC_READ);
    glNamedBufferData(commands.id(), GLsizeiptr(sizeof(Commands)), nullptr, GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_CLUMPS, clumps.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_LIST, list.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_COMMANDS, commands.id());
    glUseProgram(program.id());
    glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "sprayListSlots"), GLint(opacity.size()));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    Listed out;
    out.list.resize(opacity.size());
    glGetNamedBufferSubData(list.id(), 0, GLsizeiptr(out.list.size() * 4), out.list.data());
    glGetNamedBufferSubData(commands.id(), 0, GLsizeiptr(sizeof(Commands)), &out.commands);
    for (GLuint b : {SWELL_STORAGE_SPRAY_CLUMPS, SWELL_STORAGE_SPRAY_LIST, SWELL_STORAGE_SPRAY_COMMANDS})
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
    glUseProgram(0);
    return out;
}

// Opacities with runs of the living and the dead of every length, some
// across the invocations' runs of slots, a few living at the very ends.
std::vector<float> opacities(std::size_t slots)
{
    std::vector<float> o(slots, 0.0f);
    std::uint32_t x = 12345u;
    for (std::size_t i = 0; i < slots; ++i) {
        x = x * 1664525u + 1013904223u;
        const bool lives = (i / 37) % 3 == 0 ? (x >> 28) < 12 : (x >> 28) < 2;
        o[i] = lives ? 0.01f + float(x >> 8) * 1e-8f : 0.0f;
    }
    o.front() = 0.5f;
    o.back() = 0.25f;
    return o;
}

void expectListed(const std::vector<float>& opacity, const Listed& got, int strips)
{
    std::vector<std::uint32_t> expected;
    for (std::size_t i = 0; i < opacity.size(); ++i)
        if (opacity[i] > 0.0f)
            expected.push_back(std::uint32_t(i));
    const std::uint32_t living = std::uint32_t(expected.size());
    for (std::size_t i = 0; i < opacity.size(); ++i)
        if (!(opacity[i] > 0.0f))
            expected.push_back(std::uint32_t(i));
    EXPECT_EQ(got.list, expected) << "the living in the slots' order, then the rest";
    const Commands& c = got.commands;
    EXPECT_EQ(c.living, living);
    EXPECT_EQ(c.drawCount, living * std::uint32_t(strips * SWELL_SPRAY_STRIP_VERTICES));
    EXPECT_EQ(c.drawInstances, 1u);
    EXPECT_EQ(c.drawFirst, 0u);
    EXPECT_EQ(c.drawBaseInstance, 0u);
    EXPECT_EQ(c.groups[0], (living * std::uint32_t(strips) + SWELL_SPRAY_GROUP - 1) / SWELL_SPRAY_GROUP);
    EXPECT_EQ(c.groups[1], 1u);
    EXPECT_EQ(c.groups[2], 1u);
}

TEST_F(SprayList, TheCrestsLivingInTheSlotsOrderThenTheRest)
{
    // The lattice's slots (their count a multiple of the group's), and
    // fewer than the group's invocations, and a count that leaves the last
    // invocations' runs short.
    for (std::size_t slots : {std::size_t(SWELL_SPRAY_CELLS * SWELL_SPRAY_CELLS * SWELL_SPRAY_SLOTS), std::size_t(100),
                              std::size_t(1000)}) {
        const std::vector<float> o = opacities(slots);
        expectListed(o, listOf(o, swell::detail::kSprayClumpBytes, false), SWELL_SPRAY_DROPS);
    }
}

TEST_F(SprayList, TheBowsLivingWithTheirSheetsStrips)
{
    const std::vector<float> o = opacities(2 * SWELL_BOW_SPRAY_SLOTS);
    expectListed(o, listOf(o, swell::detail::kBowSprayClumpBytes, true), SWELL_BOW_SPRAY_DROPS + 1);
}

TEST_F(SprayList, NoneLivingDrawsNothing)
{
    const std::vector<float> o(512, 0.0f);
    const Listed got = listOf(o, swell::detail::kSprayClumpBytes, false);
    EXPECT_EQ(got.commands.living, 0u);
    EXPECT_EQ(got.commands.drawCount, 0u);
    EXPECT_EQ(got.commands.groups[0], 0u);
    for (std::size_t i = 0; i < o.size(); ++i)
        ASSERT_EQ(got.list[i], std::uint32_t(i));
}

} // namespace
