// A number typed into a panel slider (Ctrl+click, keys, Enter) against Dear
// ImGui itself, without a window: the value typed is the one taken, not its
// first keystroke ("2" on the way to "25": once taken, then "25" refused,
// it left 2.00), a value past the slider within the documented range is
// kept, and one past the documented range is clamped to it with words that
// say so (apps/swell/viewer/panel_widgets.h).
#include "viewer/panel_widgets.h"

#include "headless_imgui.h"

#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

namespace {

using namespace swell::app::viewer;
using swell::ParameterValue;

constexpr int kEnter = swell::test::HeadlessImGui::kEnterKey;

class PanelTyping : public ::testing::Test {
protected:
    PanelTyping() { ImGui::GetIO().MousePos = ImVec2(-1.0f, -1.0f); }

    // The parameter `key` at `start` in the scene.
    void startAt(const char* key, double start)
    {
        p = swell::findParameter(key);
        ASSERT_NE(p, nullptr);
        p->set(scene, 0, start);
    }

    // One frame of the panel's loop for parameter p (item 0): its widget
    // shows the held value or the scene's; what takeEdit passes is set in
    // the scene, after clampToRange, and recorded.
    void frame()
    {
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
        ImGui::SetNextWindowSize(ImVec2(600.0f, 300.0f));
        ImGui::Begin("panel");
        ParameterValue value = shownValue(*p, 0, scene, staged);
        const WidgetResult r = editValue(*p, "value", value);
        box = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
        if (takeEdit(*p, 0, r, value, staged)) {
            if (std::optional<std::string> words = clampToRange(*p, value, p->key))
                note = *words;
            p->set(scene, 0, value);
            taken.push_back(std::get<double>(value));
        }
        ImGui::End();
        ImGui::EndFrame();
    }

    // Ctrl+click on the slider, then each character in its own frame, then Enter.
    void type(const std::string& text)
    {
        frame(); // the widget's place
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2((box.first.x + box.second.x) / 2.0f, (box.first.y + box.second.y) / 2.0f);
        io.KeyCtrl = true;
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        io.KeyCtrl = false;
        frame();
        for (char c : text) {
            io.AddInputCharacter(static_cast<unsigned>(c));
            frame();
        }
        io.KeysDown[kEnter] = true;
        frame();
        io.KeysDown[kEnter] = false;
        frame();
    }

    double sceneValue() const { return std::get<double>(p->get(scene, 0)); }

    swell::test::HeadlessImGui imgui{1.0f / 30.0f};
    const swell::Parameter* p = nullptr;
    swell::Scene scene;
    std::optional<StagedValue> staged;
    std::pair<ImVec2, ImVec2> box;
    std::vector<double> taken;
    std::string note;
};

// sky.exposure: slider 1..100, allowed 0.01..1000. "250" is taken whole.
TEST_F(PanelTyping, AValueTypedPastTheSliderWithinTheRangeIsTakenWhole)
{
    startAt("sky.exposure", 3.5);
    type("250");
    EXPECT_EQ(sceneValue(), 250.0);
    EXPECT_EQ(taken, std::vector<double>{250.0}) << "a keystroke on the way was taken as a value";
    EXPECT_EQ(note, "");
}

// sun.intensity: allowed 0..20. "25" over 3.50 is clamped to 20, and says so.
TEST_F(PanelTyping, AValueTypedPastTheRangeIsClampedWithWords)
{
    startAt("sun.intensity", 3.5);
    type("25");
    EXPECT_EQ(sceneValue(), 20.0);
    EXPECT_EQ(taken, std::vector<double>{20.0});
    EXPECT_NE(note.find("25 is above sun.intensity's range 0..20: clamped to 20"), std::string::npos) << note;
}

TEST(PanelClamp, OnlyNumbersOutOfRangeAreClamped)
{
    const swell::Parameter& depth = *swell::findParameter("waves.depth_m"); // > 0, inf allowed
    ParameterValue v = 0.0;
    EXPECT_FALSE(clampToRange(depth, v, "waves.depth_m")) << "an excluded end is the range check's to refuse";
    ParameterValue deep = 5.0;
    EXPECT_FALSE(clampToRange(depth, deep, "waves.depth_m"));
    const swell::Parameter& seed = *swell::findParameter("camera.noise_seed");
    ParameterValue negative = std::int64_t(-3);
    ASSERT_TRUE(clampToRange(seed, negative, "camera.noise_seed"));
    EXPECT_EQ(std::get<std::int64_t>(negative), 0);
}

} // namespace
