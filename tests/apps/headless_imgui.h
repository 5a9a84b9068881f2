// A Dear ImGui context that runs frames with no backend and no window: what
// the viewer's Gui gives it apart from drawing (no imgui.ini, a display
// size, Enter mapped as GLFW reports it, the font atlas built), for tests of
// the viewer's input and widgets against ImGui itself.
#pragma once

#include <imgui.h>

namespace swell::test {

class HeadlessImGui {
public:
    // frame_s: the time each frame stands for.
    explicit HeadlessImGui(float frame_s)
    {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(640.0f, 360.0f);
        io.DeltaTime = frame_s;
        io.KeyMap[ImGuiKey_Enter] = kEnterKey;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;

    static constexpr int kEnterKey = 257; // GLFW_KEY_ENTER
};

} // namespace swell::test
