#include "support/gl_test.h"

#include <epoxy/gl.h>

#include <memory>

namespace swell::test {

namespace {

std::unique_ptr<gl::HeadlessContext>& context()
{
    static std::unique_ptr<gl::HeadlessContext> c;
    return c;
}

gl::DebugHandler& handler()
{
    static gl::DebugHandler h = [](const gl::DebugMessage& m) { GlTest::messages().push_back(m); };
    return h;
}

} // namespace

std::vector<gl::DebugMessage>& GlTest::messages()
{
    static std::vector<gl::DebugMessage> m;
    return m;
}

void GlTest::SetUpTestSuite()
{
    if (!context()) {
        context() = std::make_unique<gl::HeadlessContext>(true);
        ASSERT_TRUE(gl::installDebugHandler(&handler())) << "the test context has no debug output";
    }
}

void GlTest::SetUp() { messages().clear(); }

void GlTest::restoreDebugHandler() { gl::installDebugHandler(&handler()); }

void GlTest::TearDown()
{
    glFinish();
    for (const gl::DebugMessage& m : messages())
        if (m.isError())
            ADD_FAILURE() << m.str();
    messages().clear();
}

} // namespace swell::test
