// Dear ImGui inside the viewer: its context and the GLFW and OpenGL 3
// backends, created together and destroyed together. The OpenGL backend
// saves and restores the GL state it touches, so it can draw after the
// ocean renderer in the same frame.
#pragma once

struct GLFWwindow;

namespace swell::app::viewer {

class Gui {
public:
    // Needs the window's context current. Installs ImGui's GLFW callbacks.
    // Throws swell::Error when a backend cannot start.
    explicit Gui(GLFWwindow* window);
    ~Gui();
    Gui(const Gui&) = delete;
    Gui& operator=(const Gui&) = delete;

    // Starts a frame: reads input and the window size.
    void beginFrame();
    // Draws what the frame built into the current default framebuffer.
    void endFrame();
};

} // namespace swell::app::viewer
