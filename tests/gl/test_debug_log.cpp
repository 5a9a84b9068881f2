// What the apps print for the driver's debug messages (logOnceDebugHandler):
// a shader that does not compile is reported once, by buildProgram's error
// with the file and line; the driver's own copy of the log ("GL error 1:
// 0:17(15): error: ...") must not be printed beside it.
#include "support/gl_test.h"

#include "swell/error.h"
#include "swell/gl/shader.h"

#include <epoxy/gl.h>

#include <string>

namespace {

using swell::test::GlTest;

class DebugLog : public GlTest {};

TEST_F(DebugLog, ShaderCompileErrorIsNotRepeatedAsARawGlMessage)
{
    swell::gl::DebugHandler log = swell::gl::logOnceDebugHandler();
    ASSERT_TRUE(swell::gl::installDebugHandler(&log));
    const auto sources = swell::gl::ShaderSources::fromMap({
        {"broken.frag", "out vec4 colour;\nvoid main() { colour = undefinedThing; }\n"},
    });
    testing::internal::CaptureStderr();
    bool threw = false;
    try {
        swell::gl::buildProgram(sources, {{GL_FRAGMENT_SHADER, "broken.frag"}});
    } catch (const swell::InputError& e) {
        threw = true;
        EXPECT_NE(std::string(e.what()).find("broken.frag:2:"), std::string::npos) << e.what();
    }
    // A real driver error still reaches stderr, in words a user can read.
    glBindBuffer(GL_ARRAY_BUFFER, 123456);
    // Its flag taken too: left pending, the next test of this process to
    // call Renderer::draw() (which refuses to start with one) failed.
    glGetError();
    const std::string printed = testing::internal::GetCapturedStderr();
    // The fixture's handler fails tests on GL errors: put it back (the error
    // above, caused on purpose, went to `log` only).
    restoreDebugHandler();

    EXPECT_TRUE(threw);
    EXPECT_EQ(printed.find("undefinedThing"), std::string::npos) << printed;
    EXPECT_EQ(printed.find("GL error"), std::string::npos) << printed;
    EXPECT_NE(printed.find("swell: OpenGL driver error: "), std::string::npos) << printed;
}

} // namespace
