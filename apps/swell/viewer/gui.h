// Dear ImGui inside the viewer: its context and the GLFW and OpenGL 3
// backends, created together and destroyed together. The OpenGL backend
// saves and restores the GL state it touches, so it can draw after the
// ocean renderer in the same frame. Input reaches ImGui through an
// InputQueue (input_queue.h), so that no key tap is lost in a slow frame.
#pragma once

#include "viewer/input_queue.h"

#include <memory>

struct GLFWwindow;

namespace swell::app::viewer {

// For tests (tests/apps/test_viewer_input.sh) and for trying the viewer as a
// slow machine would run it.
struct GuiTesting {
    // Each frame ends with a wait this long, ms: a deliberately slow frame,
    // in which a quick key tap falls between two polls of the input.
    int slowFrame_ms = 0;
    // Prints on stderr what ImGui saw pressed each frame: Enter, Escape,
    // and clicks with their modifiers ("swell view: input: ...").
    bool logInput = false;
};

class Gui {
public:
    // Needs the window's context current. Installs the input callbacks.
    // Throws swell::Error when a backend cannot start.
    explicit Gui(GLFWwindow* window, GuiTesting testing = {});
    ~Gui();
    Gui(const Gui&) = delete;
    Gui& operator=(const Gui&) = delete;

    // Starts a frame: reads the window size and this frame's step of the
    // queued input.
    void beginFrame();
    // Draws what the frame built into the current default framebuffer.
    void endFrame();

private:
    std::unique_ptr<InputQueue> input_;
    GuiTesting testing_;
    long long frame_ = 0;
};

} // namespace swell::app::viewer
