// The viewer's ImGui panel: frame times, the view (debug view, time, camera),
// scene files, shader reload, and every scene parameter edited live. Slider
// ranges, units and descriptions come from the parameter table
// (swell/scene/parameters.h), so nothing here repeats a range.
//
// Every accepted edit reaches the renderer through Session::apply(), since
// the renderer reads even per-frame values from its own copy of the scene.
// Parameters whose effect is Rebuild (grid size, target scale) are applied
// when their slider is released rather than on every step of a drag.
#pragma once

#include "viewer/fly_camera.h"
#include "viewer/frame_times.h"
#include "viewer/panel_widgets.h"
#include "viewer/session.h"
#include "viewer/view_quality.h"

#include "swell/debug.h"
#include "swell/renderer.h"
#include "swell/scene/parameters.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swell::app::viewer {

// How much of the panel shows; F1 goes through them in this order.
enum class PanelMode {
    Full,    // the sidebar with every section
    Overlay, // a small box in a corner: frame time, time and the keys
    Hidden,  // nothing over the ocean
};
PanelMode nextPanelMode(PanelMode mode);

// The clock advances at most this much per frame, s: time follows the real
// clock down to 0.5 frames a second (software GL at a large window), and a
// longer gap (a stall: a slow shader rebuild, a scene load) does not jump the
// sea ahead.
inline constexpr double kMaxFrameStep_s = 2.0;

// What the viewer loop and the panel share about the view (not the scene).
struct ViewState {
    double time_s = 0.0;           // simulation time, s
    bool paused = false;
    double timeRate = 1.0;         // simulated seconds per real second, as asked for
    // Simulated seconds per real second as they really went over the last
    // second: lower than timeRate only when frames are slower than the
    // clock's largest step (kMaxFrameStep_s), 0 while paused.
    double actualTimeRate = 1.0;
    // What the view asks for: when the temporal resolve is on, dynamic
    // resolution and its frame target, or a fixed render scale
    // (viewer/view_quality.h).
    QualitySettings quality;
    // How the last frame was drawn: every pass at drawn.renderScale of the
    // window's size, scaled up (bilinear) to the window
    // (swell::Renderer::setRenderScale), and with the temporal resolve or not.
    FrameQuality drawn;
    bool followSceneCamera = true; // the scene's camera (and its path); false: free flight
    FlyCamera fly;
    PanelMode panel = PanelMode::Full;
};

// The keys, as the panel's help lines and docs/VIEWER.md list them.
inline constexpr const char* kKeyHelp[] = {
    "Right drag: look   WASD: move   Q/E: down/up",
    "Shift: faster   wheel: fly speed   Space: pause",
    "F1: panel/overlay/none   F5: reload shaders",
    "F12: screenshot   Esc: quit",
};


// What the panel shows about the last frame.
struct FrameStats {
    FrameTimes times;
    FrameCounters counters;
    glm::ivec2 size{0};
    std::string context; // GL_RENDERER, GL_VERSION
    Camera camera;       // the camera the frame was drawn with
};

// What the panel asks of the loop (the same as some keys).
struct PanelRequests {
    bool reloadShaders = false;
    bool screenshot = false;
};

class Panel {
public:
    // presetFolder: the repository's scenes/, listed for loading.
    explicit Panel(std::filesystem::path presetFolder);

    // The full sidebar.
    PanelRequests draw(Session& session, ViewState& view, const FrameStats& stats);
    // The small overlay: frame time, simulation time and its real rate, the keys.
    PanelRequests drawOverlay(ViewState& view, const FrameStats& stats);

    // The outcome of the last screenshot, shown under the view section.
    void setScreenshotMessage(Message message) { screenshot_ = std::move(message); }
    // After a scene file is loaded: suggests NAME-edited.toml beside it as
    // the path to save to, and selects it in the presets when it is one.
    void sceneLoaded(const std::filesystem::path& sceneFile);

private:
    void drawStats(const FrameStats& stats);
    void drawView(Session& session, ViewState& view, const FrameStats& stats, Scene& edited, bool& changed,
                  PanelRequests& requests);
    void drawFiles(Session& session);
    void drawShaders(Session& session, PanelRequests& requests);
    void drawParameters(Session& session, Scene& edited, bool& changed);
    void drawList(Session& session, ParameterList list, Scene& edited, bool& changed);
    // One parameter's widget; writes an accepted change into `edited`. A
    // refused value's message shows under the widget that was edited.
    bool editParameter(Session& session, const Parameter& p, std::size_t item, Scene& edited);
    // The refused edit's message and a button to dismiss it.
    void refusedEditText(Session& session);
    void refreshPresets();

    float width_ = 0.0f; // of the panel, pixels; 0 until the first frame
    std::filesystem::path presetFolder_;
    std::vector<std::filesystem::path> presets_;
    int presetIndex_ = 0;
    std::string savePath_;
    std::optional<StagedValue> staged_; // a value held back while its widget is (heldUntilRelease)
    std::optional<WindSettings> lastWind_; // restored when the wind is switched back on
    std::optional<std::filesystem::path> loadRequest_;
    bool saveRequest_ = false;
    Message screenshot_;
    // The field the last accepted value came from, and the one whose edit
    // was refused (its message shows beside it): parameter key and item.
    struct Field {
        std::string_view key;
        std::size_t item = 0;
        bool operator==(const Field&) const = default;
    };
    std::optional<Field> lastEdited_, refused_;
    // The words under a field whose typed value was clamped to its range.
    struct Note {
        Field field;
        std::string text;
    };
    std::optional<Note> clamped_;
    // The height the last message under a field took, kept for that field
    // after the message goes (keepMessageRow).
    struct MessageRow {
        Field field;
        float height = 0.0f;
    };
    std::optional<MessageRow> messageRow_;
    void keepMessageRow(const Field& field, float messageHeight);
    // Whether the refused edit's message was drawn beside its field in the
    // last frame; when not (its section is closed), the top of the panel shows it.
    bool refusedShown_ = false;
};

} // namespace swell::app::viewer
