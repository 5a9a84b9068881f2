// GL names are owned: moved, never copied, deleted with their owner, and a
// render target recreated on resize (down to 0x0 and back) leaks nothing;
// programs replaced by a scene change are gone, whatever was drawn before.
#include "render/render_target.h"
#include "support/gl_objects.h"
#include "support/gl_test.h"
#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/gl/handle.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <string>

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

// A program with a geometry stage (the caustics map's and the spray's,
// when they had one) may leave the driver keeping a reference for that stage to
// whichever program is used next (Mesa does), so a program used after the
// caustics and then replaced by a scene change lived on, deleted but not
// freed, until caustics were drawn again: found by the soak with shafts of
// light on. The caustics pass has no geometry stage now; the test holds
// whatever it draws to freeing what a scene change replaces. A
// frame under the water draws the caustics (the shafts read them); the
// scene changes twice, rebuilding every program; frames in the air, with
// nothing under the water to light, draw no caustics. The programs alive must be those of the first state.
TEST_F(GlResources, AProgramDrawnAfterTheCausticsIsFreedWhenReplaced)
{
    swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/underwater.toml");
    scene.water.shafts = true;
    // Nothing under the caustics map, so the frames in the air draw none.
    scene.objects.clear();
    scene.showTerrain = false;
    const glm::ivec2 size{64, 36};
    swell::detail::RenderTarget target;
    target.resize(size);
    swell::Renderer renderer(scene);
    const swell::Camera below = swell::cameraAt(scene.camera, 1.0);
    ASSERT_LT(below.position_m.y, -1.0) << "the preset's camera is under the water";
    swell::Camera above = below;
    above.position_m.y = 20.0; // above the waves' vertical reach

    renderer.render(above, 1.0, size, target.framebuffer());
    glFinish();
    const int programsBefore = swell::test::countLiveGlObjects().programs;

    renderer.render(below, 1.0, size, target.framebuffer());
    ASSERT_GT(renderer.counters().causticsTriangles, 0) << "the frame under the water drew the caustics";
    swell::Scene changed = scene;
    changed.debugView = swell::DebugView::Normals;
    renderer.setScene(changed);
    renderer.render(above, 1.0, size, target.framebuffer());
    renderer.setScene(scene);
    renderer.render(above, 1.0, size, target.framebuffer());
    ASSERT_EQ(renderer.counters().causticsTriangles, 0) << "a frame in the air drew caustics";
    glFinish();
    EXPECT_EQ(swell::test::countLiveGlObjects().programs, programsBefore);
}

} // namespace
