// A shader that does not compile must name its file and line, through
// includes, and stop with an error instead of drawing a black frame.
#include "support/gl_test.h"
#include "swell/error.h"
#include "swell/gl/shader.h"

using swell::InputError;
using swell::gl::ShaderSources;

namespace {

class ShaderErrors : public swell::test::GlTest {};

InputError buildAndCatch(const ShaderSources& sources, const std::string& vertex, const std::string& fragment)
{
    try {
        swell::gl::buildProgram(sources, {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}});
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "the broken program was built";
    return InputError({}, "");
}

const std::string kVertex = "void main() { gl_Position = vec4(0.0); }\n";

TEST_F(ShaderErrors, NamesFileAndLineOfABrokenFragmentShader)
{
    const ShaderSources s = ShaderSources::fromMap({{"ok.vert", kVertex},
        {"broken.frag", "out vec4 c;\nvoid main() {\n  c = vec4(undefinedThing, 1.0);\n}\n"}});
    const InputError e = buildAndCatch(s, "ok.vert", "broken.frag");
    EXPECT_EQ(e.place().path, "broken.frag");
    EXPECT_EQ(e.place().line, 3);
    EXPECT_NE(std::string(e.what()).find("undefinedThing"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("broken.frag:3"), std::string::npos) << e.what();
}

TEST_F(ShaderErrors, NamesTheIncludedFileWhereTheErrorIs)
{
    const ShaderSources s = ShaderSources::fromMap({{"ok.vert", kVertex},
        {"lib.glsl", "// a helper\nfloat helper() {\n  return 1.0\n}\n"},
        {"main.frag", "#include \"lib.glsl\"\nout vec4 c;\nvoid main() { c = vec4(helper()); }\n"}});
    const InputError e = buildAndCatch(s, "ok.vert", "main.frag");
    EXPECT_EQ(e.place().path, "lib.glsl") << e.what();
    // The missing semicolon is reported on line 3 or where the parser notices it, line 4.
    EXPECT_GE(e.place().line, 3) << e.what();
    EXPECT_LE(e.place().line, 4) << e.what();
}

TEST_F(ShaderErrors, LinesAfterAnIncludeKeepTheirNumbers)
{
    const ShaderSources s = ShaderSources::fromMap({{"ok.vert", kVertex},
        {"lib.glsl", "float helper() { return 1.0; }\n// two\n// three\n"},
        {"main.frag", "#include \"lib.glsl\"\nout vec4 c;\nvoid main() {\n  c = vec4(nothingHere);\n}\n"}});
    const InputError e = buildAndCatch(s, "ok.vert", "main.frag");
    EXPECT_EQ(e.place().path, "main.frag") << e.what();
    EXPECT_EQ(e.place().line, 4) << e.what();
}

TEST_F(ShaderErrors, AMissingIncludeNamesTheIncludingLine)
{
    const ShaderSources s = ShaderSources::fromMap({{"ok.vert", kVertex},
        {"main.frag", "out vec4 c;\n#include \"nowhere.glsl\"\nvoid main() { c = vec4(1.0); }\n"}});
    const InputError e = buildAndCatch(s, "ok.vert", "main.frag");
    EXPECT_EQ(e.place().path, "main.frag");
    EXPECT_EQ(e.place().line, 2);
    EXPECT_NE(std::string(e.what()).find("nowhere.glsl"), std::string::npos);
}

TEST(ShaderLog, MapsMesaAndNvidiaStylePlaces)
{
    const std::vector<std::string> files{"a.frag", "b.glsl"};
    EXPECT_EQ(swell::gl::mapInfoLog("1:7(12): error: x", files), "b.glsl:7:12: error: x\n");
    EXPECT_EQ(swell::gl::mapInfoLog("0(3) : error C1008: y", files), "a.frag:3 : error C1008: y\n");
}

} // namespace
