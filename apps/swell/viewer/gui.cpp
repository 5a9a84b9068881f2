// Dear ImGui's context and its GLFW and OpenGL 3 backends, set up and torn
// down in pairs; the input through the viewer's own queue.
#include "viewer/gui.h"

#include "swell/error.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace swell::app::viewer {

Gui::Gui(GLFWwindow* window, GuiTesting testing) : testing_(testing)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // No imgui.ini in whatever folder the viewer was started from.
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 4.0f;
    style.Colors[ImGuiCol_WindowBg].w = 0.88f;
    // Without the backend's callbacks: it would write key and button states
    // straight into ImGui, losing a tap shorter than a frame. The queue
    // installs its own (and forwards focus and pointer enter/leave).
    if (!ImGui_ImplGlfw_InitForOpenGL(window, false)) {
        ImGui::DestroyContext();
        throw Error("cannot start the viewer's panel: Dear ImGui's GLFW backend did not start");
    }
    // GLSL 4.10+ shaders with explicit locations; the context is 4.5 core.
    if (!ImGui_ImplOpenGL3_Init("#version 450 core")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw Error("cannot start the viewer's panel: Dear ImGui's OpenGL backend did not start");
    }
    input_ = std::make_unique<InputQueue>(window);
}

Gui::~Gui()
{
    input_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void Gui::beginFrame()
{
    ImGui_ImplOpenGL3_NewFrame();
    // The backend samples the live pointer and buttons; the queue's step
    // then sets what this frame sees.
    ImGui_ImplGlfw_NewFrame();
    input_->feed();
    ImGui::NewFrame();
    ++frame_;
    if (testing_.logInput) {
        const ImGuiIO& io = ImGui::GetIO();
        auto modifiers = [&io] {
            std::string text;
            if (io.KeyCtrl)
                text += " with Ctrl";
            if (io.KeyShift)
                text += " with Shift";
            if (io.KeyAlt)
                text += " with Alt";
            return text;
        };
        for (const auto& [key, name] : {std::pair{ImGuiKey_Enter, "Enter"}, std::pair{ImGuiKey_Escape, "Escape"}})
            if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false))
                std::fprintf(stderr, "swell view: input: frame %lld: %s pressed%s\n", frame_, name, modifiers().c_str());
        for (int button = 0; button < 3; ++button)
            if (ImGui::IsMouseClicked(button))
                std::fprintf(stderr, "swell view: input: frame %lld: %s click at (%.0f, %.0f)%s\n", frame_,
                             button == 0 ? "left" : button == 1 ? "right" : "middle", io.MousePos.x, io.MousePos.y,
                             modifiers().c_str());
        std::fflush(stderr);
    }
}

void Gui::endFrame()
{
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (testing_.slowFrame_ms > 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(testing_.slowFrame_ms));
}

} // namespace swell::app::viewer
