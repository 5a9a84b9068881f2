// The viewer's window: GLFW with an OpenGL 4.5 core context that has KHR_debug
// output, made current on construction. GL functions come through libepoxy,
// which resolves them for whichever context is current.
#pragma once

#include <glm/vec2.hpp>

#include <string>

struct GLFWwindow;

namespace swell::app::viewer {

// True when DISPLAY or WAYLAND_DISPLAY is set and GLFW can start on it.
// Prints nothing either way. When true, GLFW is left initialised for a Window.
bool displayUsable();

class Window {
public:
    // Opens a window of `size` screen units and makes its context current.
    // vsync: wait for the display between frames (off for scripted runs).
    // Throws swell::Error with GLFW's reason when no window or no 4.5 core
    // context can be had.
    Window(const std::string& title, glm::ivec2 size, bool vsync);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // True once the window's close button was pressed or requestClose() called.
    bool shouldClose() const;
    void requestClose();
    // In pixels; 0x0 while the window is minimised.
    glm::ivec2 framebufferSize() const;
    void swapBuffers();
    // GL_RENDERER and GL_VERSION of the context.
    std::string description() const;

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace swell::app::viewer
