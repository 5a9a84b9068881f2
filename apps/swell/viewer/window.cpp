// GLFW window and context creation for the viewer. GLFW's errors are kept
// for the exception message instead of being printed.
#include "viewer/window.h"

#include "swell/error.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <glm/common.hpp>

#include <cstdlib>

namespace swell::app::viewer {

namespace {

// GLFW reports errors through a callback without a user pointer; the last
// one is kept here until an exception message picks it up.
std::string& lastGlfwError()
{
    static std::string message;
    return message;
}

void keepGlfwError(int code, const char* description)
{
    lastGlfwError() = fmt::format("{} (GLFW error 0x{:x})", description ? description : "unknown", code);
}

std::string takeGlfwError()
{
    std::string message = std::move(lastGlfwError());
    lastGlfwError().clear();
    return message.empty() ? std::string("no reason given") : message;
}

bool environmentHasDisplay()
{
    auto set = [](const char* name) {
        const char* value = std::getenv(name);
        return value && *value;
    };
    return set("DISPLAY") || set("WAYLAND_DISPLAY");
}

} // namespace

bool displayUsable()
{
    if (!environmentHasDisplay())
        return false;
    glfwSetErrorCallback(keepGlfwError);
    // On success GLFW stays initialised for the Window that normally follows
    // (its glfwInit() is then a no-op; its destructor terminates GLFW).
    // Terminating here would close the X connection, and an X server whose
    // last client leaves resets (Xvfb under xvfb-run does), refusing the
    // Window's connection a moment later.
    const bool ok = glfwInit() == GLFW_TRUE;
    lastGlfwError().clear();
    return ok;
}

Window::Window(const std::string& title, glm::ivec2 size, bool vsync)
{
    glfwSetErrorCallback(keepGlfwError);
    if (!environmentHasDisplay())
        throw Error("no display for the viewer window (neither DISPLAY nor WAYLAND_DISPLAY is set); "
                    "use `swell render` to render without one");
    if (glfwInit() != GLFW_TRUE)
        throw Error("cannot open the viewer window: GLFW did not start: " + takeGlfwError());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = takeGlfwError();
        glfwTerminate();
        throw Error("cannot open the viewer window with an OpenGL 4.5 core context: " + reason);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(vsync ? 1 : 0);
}

Window::~Window()
{
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

glm::ivec2 Window::framebufferSize() const
{
    glm::ivec2 size(0);
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return glm::max(size, glm::ivec2(0));
}

void Window::swapBuffers() { glfwSwapBuffers(window_); }

std::string Window::description() const
{
    auto text = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

} // namespace swell::app::viewer
