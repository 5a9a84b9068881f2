// GL names are owned: moved, never copied, deleted with their owner, and a
// render target recreated on resize (down to 0x0 and back) leaks nothing.
#include "render/render_target.h"
#include "support/gl_objects.h"
#include "support/gl_test.h"
#include "swell/gl/handle.h"

#include <type_traits>

namespace {

class GlResources : public swell::test::GlTest {};

static_assert(!std::is_copy_constructible_v<swell::gl::Buffer>);
static_assert(std::is_nothrow_move_constructible_v<swell::gl::Texture>);

// Texture, framebuffer and buffer names alive right now (every live name,
// however high the driver's names have climbed).
int liveNames()
{
    const swell::test::GlObjectCounts c = swell::test::countLiveGlObjects();
    return c.textures + c.framebuffers + c.buffers;
}

TEST_F(GlResources, HandleDeletesItsNameAndMovesOwnership)
{
    GLuint name = 0;
    {
        swell::gl::Buffer a = swell::gl::Buffer::create();
        name = a.id();
        ASSERT_TRUE(glIsBuffer(name));
        swell::gl::Buffer b = std::move(a);
        EXPECT_EQ(a.id(), 0u);
        EXPECT_EQ(b.id(), name);
        EXPECT_TRUE(glIsBuffer(name));
    }
    EXPECT_FALSE(glIsBuffer(name));
}

TEST_F(GlResources, ReleaseHandsOwnershipOut)
{
    swell::gl::Texture t = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    GLuint name = t.release();
    EXPECT_EQ(t.id(), 0u);
    EXPECT_TRUE(glIsTexture(name));
    glDeleteTextures(1, &name);
}

TEST_F(GlResources, RenderTargetResizeStormLeaksNothing)
{
    const int before = liveNames();
    {
        swell::detail::RenderTarget target;
        const glm::ivec2 sizes[] = {{64, 32}, {0, 0}, {128, 128}, {1, 1}, {0, 17}, {300, 200}, {64, 32}};
        for (int round = 0; round < 20; ++round)
            for (glm::ivec2 s : sizes) {
                target.resize(s);
                EXPECT_EQ(target.framebuffer() != 0, s.x > 0 && s.y > 0);
            }
        EXPECT_EQ(liveNames(), before + 3) << "one framebuffer and two textures while sized";
    }
    EXPECT_EQ(liveNames(), before);
}

} // namespace
