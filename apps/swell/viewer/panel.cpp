// The panel's sidebar and its overlay: frame statistics, the view (debug
// view, time, camera), scene files and shader reload. The parameter sections
// are in panel_parameters.cpp, the widgets in panel_widgets.cpp.
#include "viewer/panel.h"

#include "viewer/panel_widgets.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

namespace swell::app::viewer {

namespace fs = std::filesystem;

PanelMode nextPanelMode(PanelMode mode)
{
    switch (mode) {
    case PanelMode::Full: return PanelMode::Overlay;
    case PanelMode::Overlay: return PanelMode::Hidden;
    case PanelMode::Hidden: return PanelMode::Full;
    }
    return PanelMode::Full;
}

namespace {

// wrap: at the sidebar's edge, which is narrower than the longest line (the
// overlay sizes itself to the lines instead).
void keyHelp(bool wrap)
{
    if (wrap)
        ImGui::PushTextWrapPos(0.0f);
    for (const char* line : kKeyHelp)
        ImGui::TextDisabled("%s", line);
    if (wrap)
        ImGui::PopTextWrapPos();
}

// The rate time really runs at, beside the one asked for: time follows the
// real clock, except that a frame slower than the clock's largest step
// (a stall, or software GL at a large window) advances it by that step only.
void actualRateText(const ViewState& view)
{
    const bool slower = !view.paused && view.actualTimeRate < view.timeRate * 0.98;
    if (slower)
        ImGui::TextWrapped("time runs at %.2fx, slower than the %.2fx asked: frames take longer than the clock's "
                           "%.0f s step",
                           view.actualTimeRate, view.timeRate, kMaxFrameStep_s);
    else
        ImGui::Text("time runs at %.2fx", view.actualTimeRate);
}

} // namespace

Panel::Panel(fs::path presetFolder) : presetFolder_(std::move(presetFolder)), savePath_("swell-scene.toml")
{
    refreshPresets();
}

void Panel::refreshPresets()
{
    const fs::path selected = presets_.empty() ? fs::path() : presets_[std::size_t(presetIndex_)];
    presets_.clear();
    std::error_code ec;
    for (fs::directory_iterator it(presetFolder_, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".toml")
            presets_.push_back(it->path());
    std::sort(presets_.begin(), presets_.end());
    const auto found = std::find(presets_.begin(), presets_.end(), selected);
    presetIndex_ = found == presets_.end() ? 0 : int(found - presets_.begin());
}

void Panel::sceneLoaded(const fs::path& sceneFile)
{
    if (sceneFile.empty())
        return;
    savePath_ = (sceneFile.parent_path() / (sceneFile.stem().string() + "-edited.toml")).string();
    std::error_code ec;
    const fs::path loaded = fs::weakly_canonical(sceneFile, ec);
    for (std::size_t i = 0; i < presets_.size(); ++i)
        if (fs::weakly_canonical(presets_[i], ec) == loaded)
            presetIndex_ = int(i);
}

void Panel::drawStats(const FrameStats& stats)
{
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", stats.context.c_str());
    ImGui::PopTextWrapPos();
    const float average = stats.times.average();
    // One decimal, as the overlay: at software GL's fractions of a frame a
    // second, "0 fps" said nothing.
    ImGui::Text("%d x %d px   %.1f ms   %.1f fps", stats.size.x, stats.size.y, stats.times.latest(),
                average > 0.0f ? 1000.0f / average : 0.0f);
    ImGui::TextWrapped("water %lld triangles, world %lld, caustics %lld, %d draw calls", stats.counters.waterTriangles,
                stats.counters.worldTriangles, stats.counters.causticsTriangles, stats.counters.drawCalls);
    const std::string overlay = fmt::format("avg {:.1f} ms, max {:.1f} ms", average, stats.times.maximum());
    ImGui::PlotLines("##frame times", stats.times.values(), stats.times.count(), stats.times.offset(), overlay.c_str(),
                     0.0f, std::max(1.0f, stats.times.maximum() * 1.2f), ImVec2(ImGui::GetContentRegionAvail().x, 48.0f));
}

void Panel::drawView(Session& session, ViewState& view, const FrameStats& stats, Scene& edited, bool& changed,
                     PanelRequests& requests)
{
    if (!ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    if (const Parameter* debugView = findParameter("debug_view"))
        changed |= editParameter(session, *debugView, 0, edited);
    if (const Parameter* antialiasing = findParameter("antialiasing"))
        changed |= editParameter(session, *antialiasing, 0, edited);
    const char* temporalModes[] = {"while still", "always", "off"};
    int temporalMode = int(view.quality.temporal);
    if (ImGui::Combo("temporal resolve", &temporalMode, temporalModes, IM_ARRAYSIZE(temporalModes)))
        view.quality.temporal = TemporalMode(temporalMode);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Jitter each frame and blend it into the history at the window's full resolution, in "
                          "place of the antialiasing: while the camera rests (it dithers a moving view), always, or "
                          "never (--temporal auto, on or off on the command line)");
    ImGui::Checkbox("dynamic resolution", &view.quality.dynamicScale);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The render scale follows the frame time towards the target (--frame-target)");
    if (view.quality.dynamicScale) {
        const double minTarget = 10.0, maxTarget = 1000.0;
        ImGui::SliderScalar("frame target ms", ImGuiDataType_Double, &view.quality.frameTarget_ms, &minTarget,
                            &maxTarget, "%.0f");
        view.quality.frameTarget_ms = std::clamp(view.quality.frameTarget_ms, minTarget, maxTarget);
        ImGui::Text("render scale %.2f, temporal resolve %s", view.drawn.renderScale,
                    view.drawn.temporal ? "on" : "off");
    } else {
        const double minScale = kMinRenderScale, maxScale = kMaxRenderScale;
        ImGui::SliderScalar("render scale", ImGuiDataType_Double, &view.quality.fixedScale, &minScale, &maxScale,
                            "%.2f");
        // Ctrl+click may type anything.
        view.quality.fixedScale = std::clamp(view.quality.fixedScale, minScale, maxScale);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Draw the frame at this fraction of the window's size and scale it up: 0.5 draws a "
                              "quarter of the pixels (--scale on the command line)");
    }

    // Time.
    constexpr double kStep_s = 1.0 / 60.0;
    ImGui::Checkbox("paused (Space)", &view.paused);
    ImGui::SameLine();
    if (ImGui::ArrowButton("##back", ImGuiDir_Left)) {
        view.time_s = std::max(0.0, view.time_s - kStep_s);
        view.paused = true;
    }
    ImGui::SameLine();
    if (ImGui::ArrowButton("##forward", ImGuiDir_Right)) {
        view.time_s += kStep_s;
        view.paused = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("restart"))
        view.time_s = 0.0;
    const double pathEnd = edited.camera.path.empty() ? 0.0 : edited.camera.path.back().time_s;
    const double zero = 0.0, scrubEnd = std::max({60.0, pathEnd, std::ceil(view.time_s / 60.0) * 60.0});
    ImGui::SliderScalar("time", ImGuiDataType_Double, &view.time_s, &zero, &scrubEnd, "%.2f s");
    view.time_s = std::max(0.0, view.time_s);
    const double maxRate = 4.0;
    ImGui::SliderScalar("time rate", ImGuiDataType_Double, &view.timeRate, &zero, &maxRate, "%.2fx asked");
    actualRateText(view);

    // Camera.
    ImGui::Separator();
    const Camera& camera = stats.camera;
    if (view.followSceneCamera) {
        ImGui::TextUnformatted(edited.camera.path.empty() ? "Camera: the scene's" : "Camera: the scene's path");
    } else {
        ImGui::TextUnformatted("Camera: free flight");
        ImGui::SameLine();
        if (ImGui::SmallButton("back to the scene's"))
            view.followSceneCamera = true;
    }
    ImGui::TextWrapped("at (%.1f, %.1f, %.1f) m, heading %.1f deg, pitch %.1f deg", camera.position_m.x,
                       camera.position_m.y, camera.position_m.z, camera.yaw_deg, camera.pitch_deg);
    double speed = view.fly.speed_mps();
    const double minSpeed = FlyCamera::kMinSpeed_mps, maxSpeed = FlyCamera::kMaxSpeed_mps;
    if (ImGui::SliderScalar("fly speed", ImGuiDataType_Double, &speed, &minSpeed, &maxSpeed, "%.1f m/s",
                            ImGuiSliderFlags_Logarithmic))
        view.fly.setSpeed(speed);
    if (ImGui::Button("use this view as the scene camera")) {
        setCameraPose(edited.camera, camera);
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Sets camera.position_m, yaw_deg and pitch_deg; a camera path still takes over while it has keys");
    keyHelp(true);

    ImGui::Separator();
    if (ImGui::Button("screenshot (F12)"))
        requests.screenshot = true;
    message(screenshot_);
}

void Panel::drawFiles(Session& session)
{
    if (!ImGui::CollapsingHeader("Scene file", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    const fs::path& file = session.sceneFile();
    ImGui::TextWrapped("Scene: %s", file.empty() ? "the built-in default" : file.string().c_str());
    if (!file.empty()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("reload"))
            loadRequest_ = file;
    }

    const std::string preview = presets_.empty() ? std::string("(no scenes found)")
                                                 : presets_[std::size_t(presetIndex_)].filename().string();
    if (ImGui::BeginCombo("preset", preview.c_str())) {
        if (ImGui::IsWindowAppearing())
            refreshPresets();
        for (std::size_t i = 0; i < presets_.size(); ++i) {
            const std::string name = presets_[i].filename().string();
            if (ImGui::Selectable(name.c_str(), int(i) == presetIndex_))
                presetIndex_ = int(i);
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", presetFolder_.string().c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(presets_.empty());
    if (ImGui::Button("load"))
        loadRequest_ = presets_[std::size_t(presetIndex_)];
    ImGui::EndDisabled();

    ImGui::InputText("##save path", &savePath_);
    ImGui::SameLine();
    if (ImGui::Button("save"))
        saveRequest_ = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Writes the scene as TOML; in free flight the current view becomes its camera.\n"
                          "Relative object paths must still resolve from the new folder.");
    message(session.fileMessage());
}

void Panel::drawShaders(Session& session, PanelRequests& requests)
{
    if (!ImGui::CollapsingHeader("Shaders"))
        return;
    const std::string folder = session.shaderFolders().shaders.string();
    if (session.shadersFromDisk())
        ImGui::TextWrapped("From %s", folder.c_str());
    else
        ImGui::TextWrapped("The embedded copies; a reload reads %s", folder.c_str());
    if (ImGui::Button("reload shaders (F5)"))
        requests.reloadShaders = true;
    if (!session.shaderMessage().error)
        message(session.shaderMessage());
}

void Panel::refusedEditText(Session& session)
{
    errorText("Not applied: " + session.editMessage().text);
    if (ImGui::SmallButton("dismiss")) {
        session.clearEditMessage();
        refused_.reset();
    }
}

PanelRequests Panel::draw(Session& session, ViewState& view, const FrameStats& stats)
{
    PanelRequests requests;
    // A sidebar along the left edge, the height of the window whatever its
    // size; only its width is the user's to change.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    constexpr float kMargin = 8.0f;
    // A quarter of the window (320 of 1280 px), at least room for a slider
    // and its key's name; the title bar's arrow folds it to a bar, F1 to an
    // overlay.
    if (width_ <= 0.0f)
        width_ = std::clamp(viewport->WorkSize.x * 0.25f, 280.0f, 360.0f);
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + kMargin, viewport->WorkPos.y + kMargin), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width_, std::max(1.0f, viewport->WorkSize.y - 2.0f * kMargin)), ImGuiCond_Always);
    const bool visible = ImGui::Begin("Swell");
    width_ = std::max(200.0f, ImGui::GetWindowWidth());
    // A message's kept row closes once the pointer is off the panel, where
    // the rows moving up disturbs no one (keepMessageRow).
    if (!ImGui::IsWindowHovered(ImGuiHoveredFlags_RootAndChildWindows | ImGuiHoveredFlags_AllowWhenBlockedByActiveItem))
        messageRow_.reset();
    Scene edited = session.scene();
    bool changed = false;
    if (visible) {
        // Room on the right of each widget for the longest key name.
        ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.5f);
        if (ImGui::SmallButton("collapse to an overlay (F1)"))
            view.panel = PanelMode::Overlay;
        drawStats(stats);
        // A refused edit shows beside its field; here only when that field
        // was not drawn in the last frame (its section closed).
        if (session.editMessage().error && !refusedShown_)
            refusedEditText(session);
        refusedShown_ = false;
        if (session.shaderMessage().error)
            errorText("Shader reload failed; the previous shaders stay in use.\n" + session.shaderMessage().text);
        drawView(session, view, stats, edited, changed, requests);
        drawFiles(session);
        drawShaders(session, requests);
        drawParameters(session, edited, changed);
        ImGui::PopItemWidth();
    }
    ImGui::End();

    // The refused edit's message goes with the next action that succeeds.
    if (changed) {
        if (session.apply(edited))
            refused_.reset();
        else
            refused_ = lastEdited_;
    }
    if (saveRequest_) {
        saveRequest_ = false;
        Scene toSave = session.scene();
        if (!view.followSceneCamera)
            setCameraPose(toSave.camera, view.fly.camera());
        if (session.save(toSave, savePath_))
            session.clearEditMessage();
    }
    if (loadRequest_) {
        const fs::path file = *loadRequest_;
        loadRequest_.reset();
        if (session.load(file)) {
            view.time_s = 0.0;
            view.followSceneCamera = true;
            staged_.reset();
            lastWind_.reset();
            refused_.reset();
            sceneLoaded(file);
        }
    }
    return requests;
}


PanelRequests Panel::drawOverlay(ViewState& view, const FrameStats& stats)
{
    PanelRequests requests;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    constexpr float kMargin = 8.0f;
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + kMargin, viewport->WorkPos.y + kMargin), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("Swell overlay", nullptr, flags)) {
        const float average = stats.times.average();
        ImGui::Text("%.1f ms  %.1f fps   t %.2f s%s", stats.times.latest(), average > 0.0f ? 1000.0f / average : 0.0f,
                    view.time_s, view.paused ? " (paused)" : "");
        actualRateText(view);
        keyHelp(false);
        if (ImGui::SmallButton("full panel (F1)"))
            view.panel = PanelMode::Full;
        ImGui::SameLine();
        if (ImGui::SmallButton("screenshot (F12)"))
            requests.screenshot = true;
        message(screenshot_);
    }
    ImGui::End();
    return requests;
}

} // namespace swell::app::viewer
