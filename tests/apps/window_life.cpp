// The viewer's window through a hard life: a storm of resizes (hundreds of
// random sizes, 1x1 among them), minimising (a 0x0 framebuffer), and
// restoring. Drives the viewer's own Window (GLFW, a 4.5 core debug context)
// and a Renderer the way the viewer's loop does, under a virtual X server.
// Passes when no GL error or high-severity debug message was raised, the GL
// objects alive afterwards are the ones alive before, and the restored window
// still shows sky above water.
//
// Exit: 0 passed; 1 failed (saying why); 77 skipped (no display).
#include "sky_above_water.h"
#include "support/gl_objects.h"
#include "viewer/screenshot.h"
#include "viewer/window.h"

#include "swell/camera.h"
#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <utility>

namespace {

using swell::app::viewer::Window;

constexpr glm::ivec2 kHomeSize{320, 180};
// Window sizes of the storm, screen units. Every size is drawn, on software
// GL: up to 640x400 keeps the storm to about half a minute.
constexpr int kStormResizes = 300;
constexpr int kMaxStormWidth = 640, kMaxStormHeight = 400;

int failures = 0;

void fail(const char* what)
{
    std::printf("window_life: FAILED: %s\n", what);
    ++failures;
}

// Lets the X server apply a resize or state change and GLFW hear of it:
// events are pumped until `done` holds or `timeout_s` passes.
template <class Done>
bool pumpUntil(Done done, double timeout_s)
{
    const double end = glfwGetTime() + timeout_s;
    while (!done()) {
        if (glfwGetTime() > end)
            return false;
        glfwWaitEventsTimeout(0.01);
    }
    return true;
}

// One frame as the viewer's loop draws it: nothing while minimised.
void frame(const Window& window, swell::Renderer& renderer, double time_s)
{
    const glm::ivec2 size = window.framebufferSize();
    if (size.x > 0 && size.y > 0)
        renderer.render(swell::cameraAt(renderer.scene().camera, time_s), time_s, size);
}

bool showsSkyAboveWater(const swell::Image& image)
{
    const swell::test::SkyAboveWater seen = swell::test::skyAboveWater(image);
    std::printf("window_life: restored frame, right third: top quarter %.0f%% sky, bottom quarter %.0f%% water\n",
                100.0 * seen.sky, 100.0 * seen.water);
    return seen.shown();
}

int run()
{
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::printf("window_life: no DISPLAY: skipped\n");
        return 77;
    }
    // As `swell` without a subcommand does: ask, then open. (The question
    // once closed GLFW's X connection, Xvfb reset, and the window failed.)
    if (!swell::app::viewer::displayUsable()) {
        fail("DISPLAY is set but GLFW cannot start on it");
        return 1;
    }
    Window window("swell window life", kHomeSize, false);
    int glErrors = 0;
    swell::gl::DebugHandler handler = [&](const swell::gl::DebugMessage& m) {
        if (m.isError() && glErrors++ < 10)
            std::printf("window_life: %s\n", m.str().c_str());
    };
    if (!swell::gl::installDebugHandler(&handler)) {
        fail("the window's context has no debug output, so GL errors would go unseen");
        return 1;
    }
    std::printf("window_life: %s\n", window.description().c_str());
    GLFWwindow* w = window.handle();
    double time_s = 0.0;
    {
        swell::Scene scene = swell::defaultScene();
        // A coarser grid than the default's 256: hundreds of frames on software GL.
        scene.grid.resolution = 64;
        swell::Renderer renderer(scene);
        frame(window, renderer, time_s);
        glFinish();
        const swell::test::GlObjectCounts baseline = swell::test::countLiveGlObjects();

        // The storm: every size is asked for, drawn at whatever the window got, and swapped.
        std::mt19937 random(6);
        std::uniform_int_distribution<int> width(1, kMaxStormWidth), height(1, kMaxStormHeight);
        std::set<std::pair<int, int>> seen;
        for (int i = 0; i < kStormResizes; ++i) {
            const glm::ivec2 size = i % 10 == 0 ? glm::ivec2(1, 1) : glm::ivec2(width(random), height(random));
            glfwSetWindowSize(w, size.x, size.y);
            pumpUntil([&] { return window.framebufferSize() == size; }, 0.5);
            const glm::ivec2 got = window.framebufferSize();
            seen.insert({got.x, got.y});
            frame(window, renderer, time_s += 1.0 / 60.0);
            window.swapBuffers();
        }
        std::printf("window_life: %d resizes, %zu distinct framebuffer sizes, 1x1 %s\n", kStormResizes, seen.size(),
                    seen.count({1, 1}) ? "among them" : "never reached");
        // Without a window manager the server applies each resize at once; most must have landed.
        if (seen.size() < kStormResizes / 2)
            fail("the window did not follow the resizes; the storm tested little");
        if (!seen.count({1, 1}))
            fail("the framebuffer never became 1x1");

        // Minimised: the viewer draws nothing while the framebuffer is 0x0.
        // Without a window manager (bare Xvfb) iconifying may not happen; the
        // renderer's side of it, a zero-sized frame, is driven regardless.
        glfwIconifyWindow(w);
        const bool iconified =
            pumpUntil([&] { return glfwGetWindowAttrib(w, GLFW_ICONIFIED) == GLFW_TRUE; }, 1.0);
        std::printf("window_life: iconified: %s, framebuffer then %dx%d\n", iconified ? "yes" : "no (no window manager)",
                    window.framebufferSize().x, window.framebufferSize().y);
        for (int i = 0; i < 20; ++i) {
            frame(window, renderer, time_s += 1.0 / 60.0);
            const glm::ivec2 zero[] = {{0, 0}, {0, 180}, {320, 0}};
            renderer.render(swell::cameraAt(renderer.scene().camera, time_s), time_s, zero[i % 3]);
            window.swapBuffers();
            glfwPollEvents();
        }

        // Restored, at the first size.
        glfwRestoreWindow(w);
        glfwSetWindowSize(w, kHomeSize.x, kHomeSize.y);
        if (!pumpUntil([&] { return window.framebufferSize() == kHomeSize; }, 5.0))
            fail("the window did not come back to its first size");
        const glm::ivec2 size = window.framebufferSize();
        frame(window, renderer, time_s);
        glFinish();
        if (!showsSkyAboveWater(swell::app::viewer::readDefaultFramebuffer(size)))
            fail("the restored window does not show sky above water");
        window.swapBuffers();

        const swell::test::GlObjectCounts end = swell::test::countLiveGlObjects();
        std::printf("window_life: GL objects before the storm: %s\n", baseline.str().c_str());
        std::printf("window_life: GL objects after restoring:  %s\n", end.str().c_str());
        if (!(end == baseline))
            fail("GL objects after restoring differ from before the storm");
    }
    glFinish();
    if (glErrors > 0)
        fail("GL errors or high-severity debug messages (above)");
    if (failures == 0)
        std::printf("window_life: passed\n");
    return failures == 0 ? 0 : 1;
}

} // namespace

int main()
{
    try {
        return run();
    } catch (const std::exception& e) {
        std::printf("window_life: FAILED: %s\n", e.what());
        return 1;
    }
}
