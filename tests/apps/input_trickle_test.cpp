// The viewer's input trickling (apps/swell/viewer/input_queue.h) against
// Dear ImGui itself, without a window: taps shorter than a frame, queued as
// GLFW would report them, must each be seen by ImGui in some frame, with
// the modifiers held at the time. ImGui 1.86 alone (states sampled once a
// frame) sees neither the Enter tap nor the Ctrl of a quick Ctrl+click.
#include "viewer/input_queue.h"

#include "headless_imgui.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <deque>

static_assert(swell::test::HeadlessImGui::kEnterKey == GLFW_KEY_ENTER);

namespace {

using swell::app::viewer::InputEvent;
using swell::app::viewer::InputTrickle;
using Kind = InputEvent::Kind;

// An ImGui context that runs frames with no backend: what the viewer's Gui
// gives it apart from drawing.
class InputTrickleFrames : public ::testing::Test {
protected:
    InputTrickleFrames() { ImGui::GetIO().MousePos = ImVec2(100.0f, 100.0f); }

    swell::test::HeadlessImGui imgui{1.0f}; // a slow frame

    // One frame: this frame's step of the queue, then what ImGui saw.
    struct Seen {
        bool enterPressed = false, clicked = false, ctrlAtClick = false;
        int taken = 0;
    };
    Seen frame()
    {
        Seen seen;
        seen.taken = trickle.step(queue, ImGui::GetIO());
        ImGui::NewFrame();
        seen.enterPressed = ImGui::IsKeyPressed(GLFW_KEY_ENTER, false);
        seen.clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
        seen.ctrlAtClick = seen.clicked && ImGui::GetIO().KeyCtrl;
        ImGui::EndFrame();
        return seen;
    }

    void key(int code, bool down) { queue.push_back({.kind = Kind::Key, .code = code, .down = down}); }
    void button(bool down) { queue.push_back({.kind = Kind::MouseButton, .code = 0, .down = down}); }

    std::deque<InputEvent> queue;
    InputTrickle trickle;
};

TEST_F(InputTrickleFrames, AnEnterTapWithinOneFrameIsPressedInOneFrameAndReleasedInTheNext)
{
    frame();
    // Typed "5" and Enter, all between two frames.
    key(GLFW_KEY_5, true);
    queue.push_back({.kind = Kind::Char, .code = '5'});
    key(GLFW_KEY_5, false);
    key(GLFW_KEY_ENTER, true);
    key(GLFW_KEY_ENTER, false);
    int enterFrames = 0;
    for (int i = 0; i < 5; ++i)
        enterFrames += frame().enterPressed ? 1 : 0;
    EXPECT_EQ(enterFrames, 1);
    EXPECT_TRUE(queue.empty());
    EXPECT_FALSE(ImGui::GetIO().KeysDown[GLFW_KEY_ENTER]);
}

TEST_F(InputTrickleFrames, AQuickCtrlClickIsSeenWithCtrlHeld)
{
    frame();
    key(GLFW_KEY_LEFT_CONTROL, true);
    button(true);
    button(false);
    key(GLFW_KEY_LEFT_CONTROL, false);
    const Seen first = frame();
    EXPECT_TRUE(first.clicked);
    EXPECT_TRUE(first.ctrlAtClick);
    const Seen second = frame();
    EXPECT_FALSE(second.clicked);
    EXPECT_FALSE(ImGui::GetIO().KeyCtrl);
    EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);
    EXPECT_TRUE(queue.empty());
}

TEST_F(InputTrickleFrames, AClickIsSeenWhereItWasPressed)
{
    frame();
    queue.push_back({.kind = Kind::MousePos, .x = 200.0, .y = 50.0});
    button(true);
    queue.push_back({.kind = Kind::MousePos, .x = 400.0, .y = 300.0}); // moved away after the press
    button(false);
    frame();
    EXPECT_EQ(ImGui::GetIO().MouseClickedPos[0].x, 200.0f);
    EXPECT_EQ(ImGui::GetIO().MouseClickedPos[0].y, 50.0f);
}

} // namespace
