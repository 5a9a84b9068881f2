// The viewer's input to Dear ImGui, queued between frames. The ImGui of
// Debian 12 (1.86) reads keys and buttons as states sampled once a frame, so
// on software GL, at a few frames a second or less, a key pressed and
// released within one frame was never seen (an Enter ending a typed value),
// and a modifier was released before the click it modified was read (a
// Ctrl+click became a plain click). Here GLFW's callbacks append every event
// to a queue, and each frame takes events from it in order only until one
// would change a key or button that already changed in this frame; the rest
// waits for the next frame, as ImGui 1.87's input trickling does. A tap
// then shows as pressed in one frame and released in the next, however slow
// the frames.
#pragma once

#include <deque>
#include <memory>

struct GLFWwindow;
struct ImGuiIO;

namespace swell::app::viewer {

struct InputEvent {
    enum class Kind { Key, Char, MouseButton, MousePos, Scroll };
    Kind kind = Kind::Key;
    int code = 0;       // Key: GLFW key; Char: code point; MouseButton: GLFW button
    bool down = false;  // Key, MouseButton: pressed (true) or released
    double x = 0.0, y = 0.0; // MousePos: window coordinates; Scroll: offsets
};

// The events of one frame step, applied to ImGui's input state: what a frame
// takes from the front of a queue. Pure logic, so it can be tested without a
// window.
class InputTrickle {
public:
    // Takes events from the front of `queue` while none of them changes a
    // key or button that an earlier one of this step already changed, and
    // while no pointer move follows a button change (the click is seen where
    // it happened). Applies them to `io`: KeysDown and the modifier flags,
    // MouseDown, MousePos, the wheel and typed characters. Returns the number
    // of events taken (at least one when the queue is not empty).
    int step(std::deque<InputEvent>& queue, ImGuiIO& io);
    // Writes the states the queue has reached into `io` again, after a
    // backend overwrote them from the live device state.
    void restore(ImGuiIO& io) const;

private:
    static constexpr int kKeys = 512;    // ImGuiIO::KeysDown in 1.86
    static constexpr int kButtons = 5;   // ImGuiIO::MouseDown
    bool keys_[kKeys] = {};
    bool buttons_[kButtons] = {};
    bool havePos_ = false;
    double x_ = 0.0, y_ = 0.0;
};

// Installs GLFW's input callbacks on `window` (keeping those already there,
// which it calls first) and feeds ImGui from the queue. Needs ImGui's GLFW
// backend initialised without its own callbacks.
class InputQueue {
public:
    explicit InputQueue(GLFWwindow* window);
    ~InputQueue();
    InputQueue(const InputQueue&) = delete;
    InputQueue& operator=(const InputQueue&) = delete;

    // Call after ImGui_ImplGlfw_NewFrame() (which samples the live mouse)
    // and before ImGui::NewFrame(): applies this frame's step of the queue.
    void feed();

    void push(const InputEvent& event) { queue_.push_back(event); }

private:
    GLFWwindow* window_;
    std::deque<InputEvent> queue_;
    InputTrickle trickle_;
    struct Previous; // the callbacks installed before ours
    std::unique_ptr<Previous> previous_;
};

} // namespace swell::app::viewer
