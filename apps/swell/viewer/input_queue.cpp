// GLFW's input events queued between frames and fed to Dear ImGui one frame
// step at a time (input_queue.h says why).
#include "viewer/input_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

namespace swell::app::viewer {

struct InputQueue::Previous {
    GLFWkeyfun key = nullptr;
    GLFWcharfun character = nullptr;
    GLFWmousebuttonfun button = nullptr;
    GLFWcursorposfun cursor = nullptr;
    GLFWscrollfun scroll = nullptr;
    GLFWwindowfocusfun focus = nullptr;
    GLFWcursorenterfun enter = nullptr;
};

namespace {

// GLFW's callbacks carry no pointer of ours (the window's user pointer
// belongs to the viewer loop); ImGui's io.UserData, in the context Gui
// owns, points at the queue.
InputQueue& queueOf() { return *static_cast<InputQueue*>(ImGui::GetIO().UserData); }

} // namespace

InputQueue::InputQueue(GLFWwindow* window) : window_(window), previous_(std::make_unique<Previous>())
{
    ImGui::GetIO().UserData = this;
    // Each callback calls the one installed before it first (the viewer's
    // own key presses), then queues the event. Focus and the pointer
    // entering the window go to the backend at once: they are not taps.
    previous_->key = glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        InputQueue& q = queueOf();
        if (q.previous_->key)
            q.previous_->key(w, key, scancode, action, mods);
        if (action == GLFW_PRESS || action == GLFW_RELEASE)
            q.push({.kind = InputEvent::Kind::Key, .code = key, .down = action == GLFW_PRESS});
    });
    previous_->character = glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) {
        InputQueue& q = queueOf();
        if (q.previous_->character)
            q.previous_->character(w, c);
        q.push({.kind = InputEvent::Kind::Char, .code = int(c)});
    });
    previous_->button = glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        InputQueue& q = queueOf();
        if (q.previous_->button)
            q.previous_->button(w, button, action, mods);
        q.push({.kind = InputEvent::Kind::MouseButton, .code = button, .down = action == GLFW_PRESS});
    });
    previous_->cursor = glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        InputQueue& q = queueOf();
        if (q.previous_->cursor)
            q.previous_->cursor(w, x, y);
        q.push({.kind = InputEvent::Kind::MousePos, .x = x, .y = y});
    });
    previous_->scroll = glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
        InputQueue& q = queueOf();
        if (q.previous_->scroll)
            q.previous_->scroll(w, x, y);
        q.push({.kind = InputEvent::Kind::Scroll, .x = x, .y = y});
    });
    previous_->focus = glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) {
        InputQueue& q = queueOf();
        if (q.previous_->focus)
            q.previous_->focus(w, focused);
        ImGui_ImplGlfw_WindowFocusCallback(w, focused);
    });
    previous_->enter = glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
        InputQueue& q = queueOf();
        if (q.previous_->enter)
            q.previous_->enter(w, entered);
        ImGui_ImplGlfw_CursorEnterCallback(w, entered);
    });
}

InputQueue::~InputQueue()
{
    glfwSetKeyCallback(window_, previous_->key);
    glfwSetCharCallback(window_, previous_->character);
    glfwSetMouseButtonCallback(window_, previous_->button);
    glfwSetCursorPosCallback(window_, previous_->cursor);
    glfwSetScrollCallback(window_, previous_->scroll);
    glfwSetWindowFocusCallback(window_, previous_->focus);
    glfwSetCursorEnterCallback(window_, previous_->enter);
    ImGui::GetIO().UserData = nullptr;
}

void InputQueue::feed()
{
    ImGuiIO& io = ImGui::GetIO();
    if (queue_.empty())
        trickle_.restore(io);
    else
        trickle_.step(queue_, io);
}

} // namespace swell::app::viewer
