// One frame step of the queued input (input_queue.h): which events a frame
// takes, and the key and button states they leave in ImGui. No window and
// no GLFW calls (only its key numbers), so a test can drive it directly.
#include "viewer/input_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cfloat>

namespace swell::app::viewer {

int InputTrickle::step(std::deque<InputEvent>& queue, ImGuiIO& io)
{
    bool keyChanged[kKeys] = {};
    bool buttonChanged[kButtons] = {};
    bool anyButtonChanged = false;
    int taken = 0;
    // Whether the front event waits for the next frame step.
    auto waits = [&](const InputEvent& e) {
        switch (e.kind) {
        case InputEvent::Kind::Key: return e.code >= 0 && e.code < kKeys && keyChanged[e.code];
        case InputEvent::Kind::MouseButton: return e.code >= 0 && e.code < kButtons && buttonChanged[e.code];
        case InputEvent::Kind::MousePos: return anyButtonChanged;
        default: return false;
        }
    };
    while (!queue.empty() && !waits(queue.front())) {
        const InputEvent& e = queue.front();
        switch (e.kind) {
        case InputEvent::Kind::Key:
            if (e.code >= 0 && e.code < kKeys) {
                if (keys_[e.code] != e.down)
                    keyChanged[e.code] = true;
                keys_[e.code] = e.down;
            }
            break;
        case InputEvent::Kind::Char:
            io.AddInputCharacter(unsigned(e.code));
            break;
        case InputEvent::Kind::MouseButton:
            if (e.code >= 0 && e.code < kButtons) {
                if (buttons_[e.code] != e.down)
                    buttonChanged[e.code] = anyButtonChanged = true;
                buttons_[e.code] = e.down;
            }
            break;
        case InputEvent::Kind::MousePos:
            havePos_ = true;
            x_ = e.x;
            y_ = e.y;
            break;
        case InputEvent::Kind::Scroll:
            io.MouseWheelH += float(e.x);
            io.MouseWheel += float(e.y);
            break;
        }
        queue.pop_front();
        ++taken;
    }
    restore(io);
    return taken;
}

void InputTrickle::restore(ImGuiIO& io) const
{
    for (int k = 0; k < kKeys; ++k)
        io.KeysDown[k] = keys_[k];
    for (int b = 0; b < kButtons; ++b)
        io.MouseDown[b] = buttons_[b];
    // The position only while the backend sees the pointer over the window
    // (it writes -FLT_MAX otherwise).
    if (havePos_ && io.MousePos.x > -FLT_MAX)
        io.MousePos = ImVec2(float(x_), float(y_));
    io.KeyCtrl = keys_[GLFW_KEY_LEFT_CONTROL] || keys_[GLFW_KEY_RIGHT_CONTROL];
    io.KeyShift = keys_[GLFW_KEY_LEFT_SHIFT] || keys_[GLFW_KEY_RIGHT_SHIFT];
    io.KeyAlt = keys_[GLFW_KEY_LEFT_ALT] || keys_[GLFW_KEY_RIGHT_ALT];
    io.KeySuper = keys_[GLFW_KEY_LEFT_SUPER] || keys_[GLFW_KEY_RIGHT_SUPER];
}

} // namespace swell::app::viewer
