// Every std140 uniform block C++ and GLSL share is declared in GLSL from
// its C++ description, at build time (render/gpu/glsl_files.h): for each,
// the driver's offset of every member, the C++ struct's (offsetof) and the
// generator's std140 layout agree, as do the block's size and binding
// point; the files the library embeds are what the generator writes from
// the structs compiled in; and no shader declares a block by hand.
#include "render/gpu/glsl_files.h"
#include "render/surface_sources.h"
#include "support/gl_test.h"
#include "swell/gl/shader.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace swell;

class UniformLayout : public test::GlTest {};

GLint resource(GLuint program, GLenum interface, const std::string& name, GLenum property)
{
    const GLuint index = glGetProgramResourceIndex(program, interface, name.c_str());
    if (index == GL_INVALID_INDEX)
        return -1;
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

// A GLSL expression that reads `path`, a member of type `m` (so that the
// block is referenced, which makes every member of a std140 block active).
std::string readOf(const gl::BlockMember& m, std::string path)
{
    if (m.count > 0)
        path += "[0]";
    if (m.structure) {
        const gl::BlockMember& inner = *std::find_if(m.structure->members.begin(), m.structure->members.end(),
                                                     [](const gl::BlockMember& s) { return !s.padding; });
        return readOf(inner, path + "." + std::string(inner.name));
    }
    if (m.type == "mat4")
        return path + "[0][0]";
    if (m.type.starts_with("vec") || m.type.starts_with("ivec"))
        return "float(" + path + ".x)";
    return "float(" + path + ")";
}

gl::Program probe(const gl::UniformBlock& block)
{
    std::map<std::string, std::string> files;
    const gl::ShaderSources embedded = gl::ShaderSources::embedded();
    for (const std::string& f : embedded.fileNames())
        files[f] = embedded.file(f);
    const gl::BlockMember& first = block.layout->members.front();
    files["probe.vert"] = "#include \"" + std::string(block.file) + "\"\nvoid main() { gl_Position = vec4(" +
                          readOf(first, std::string(first.name)) + "); }\n";
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    return gl::buildProgram(gl::ShaderSources::fromMap(files),
                            {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}});
}

// Each member's offset as the driver, the C++ struct and the generator have
// it, under `prefix` (a struct array's element) at `base` bytes; a struct
// array's second element too, which shows its stride.
void expectMembers(GLuint program, const gl::BlockStruct& s, const std::string& prefix, std::size_t base)
{
    const std::vector<std::size_t> generated = gl::std140Offsets(s);
    std::size_t i = 0;
    for (const gl::BlockMember& m : s.members) {
        if (m.padding)
            continue;
        const std::size_t at = base + m.offset;
        EXPECT_EQ(generated[i++] + base, at) << prefix << m.name;
        const std::string name = prefix + std::string(m.name);
        if (m.structure) {
            for (std::size_t element = 0; element < (m.count > 0 ? 2u : 1u); ++element)
                expectMembers(program, *m.structure,
                              m.count > 0 ? name + "[" + std::to_string(element) + "]." : name + ".",
                              at + element * m.structure->size);
            continue;
        }
        const std::string driverName = m.count > 0 ? name + "[0]" : name;
        EXPECT_EQ(resource(program, GL_UNIFORM, driverName, GL_OFFSET), GLint(at)) << driverName;
        if (m.count > 0) {
            EXPECT_EQ(resource(program, GL_UNIFORM, driverName, GL_ARRAY_STRIDE), GLint(m.cppSize / m.count))
                << driverName;
        }
    }
}

TEST_F(UniformLayout, EveryBlockIsWhereItsCppStructAndTheGeneratorPutIt)
{
    const std::vector<gl::UniformBlock> blocks = detail::glslBlocks();
    // The renderer's five, the two wave models' and the coast field's: a
    // list that lost its blocks would pass vacuously.
    ASSERT_EQ(blocks.size(), 8u);
    for (const gl::UniformBlock& block : blocks) {
        const gl::BlockStruct& s = *block.layout;
        SCOPED_TRACE(std::string(s.name));
        EXPECT_EQ(gl::std140Problems(s), "");
        const gl::Program p = probe(block);
        expectMembers(p.id(), s, "", 0);
        const std::string name(s.name);
        EXPECT_EQ(resource(p.id(), GL_UNIFORM_BLOCK, name, GL_BUFFER_DATA_SIZE), GLint(s.size));
        EXPECT_EQ(gl::std140Size(s), s.size);
        EXPECT_EQ(resource(p.id(), GL_UNIFORM_BLOCK, name, GL_BUFFER_BINDING), block.binding);
    }
}

TEST_F(UniformLayout, TheEmbeddedBlockFilesAreTheGeneratorsFromTheCompiledStructs)
{
    const gl::ShaderSources embedded = gl::ShaderSources::embedded();
    std::string problems;
    const std::vector<detail::GeneratedGlslFile> files = detail::generatedGlslFiles(problems);
    EXPECT_EQ(problems, "");
    for (const detail::GeneratedGlslFile& f : files)
        EXPECT_EQ(embedded.file(f.name), f.text) << f.name;
}

// Every block the shaders declare comes from the generator: no other file
// declares one, the renderer's code for the surface sources included.
TEST_F(UniformLayout, NoShaderDeclaresABlockByHand)
{
    gl::ShaderSources sources = gl::ShaderSources::embedded();
    detail::setSurfaceSourceFiles(sources, {"vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4]) { return vec4(0.0); }"});
    int generated = 0;
    for (const std::string& name : sources.fileNames()) {
        const bool declares = sources.file(name).find("layout(std140") != std::string::npos;
        if (name.starts_with("gpu/"))
            generated += declares ? 1 : 0;
        else
            EXPECT_FALSE(declares) << name;
    }
    EXPECT_EQ(generated, int(detail::glslBlocks().size()));
}

} // namespace
