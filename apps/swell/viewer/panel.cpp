// The panel's widgets. Parameters are walked from the table in its order and
// grouped into sections by the first part of their key.
#include "viewer/panel.h"

#include "swell/shader_constants.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace swell::app::viewer {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Frame times.

void FrameTimes::add(float ms)
{
    values_[std::size_t(next_)] = ms;
    next_ = (next_ + 1) % kCount;
    filled_ = std::min(filled_ + 1, kCount);
}

float FrameTimes::average() const
{
    if (filled_ == 0)
        return 0.0f;
    float sum = 0.0f;
    for (float v : values_)
        sum += v;
    return sum / float(filled_);
}

float FrameTimes::maximum() const { return *std::max_element(values_.begin(), values_.end()); }

float FrameTimes::latest() const { return values_[std::size_t((next_ + kCount - 1) % kCount)]; }

// ---------------------------------------------------------------------------
// Parameter widgets.

namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.40f, 1.0f);

void errorText(const std::string& text)
{
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void message(const Message& m)
{
    if (m.text.empty())
        return;
    if (m.error)
        errorText(m.text);
    else
        ImGui::TextWrapped("%s", m.text.c_str());
}

// The panel section of a parameter: the first part of its table's key
// ("waves" for waves.wind.speed_mps and waves.list.*); "" for top-level keys.
std::string_view sectionOf(const Parameter& p)
{
    if (p.list != ParameterList::None) {
        const std::string_view key = listKey(p.list);
        return key.substr(0, key.find('.'));
    }
    const std::size_t dot = p.key.find('.');
    return dot == std::string_view::npos ? std::string_view() : p.key.substr(0, dot);
}

std::string sectionTitle(std::string_view section)
{
    if (section.empty())
        return "General";
    std::string title(section);
    title[0] = char(std::toupper(static_cast<unsigned char>(title[0])));
    return title;
}

// The wind's parameters sit under the switch that turns the wind on.
bool isWindParameter(const Parameter& p) { return p.key.starts_with("waves.wind."); }

// The key without its tables: "speed_mps" for waves.wind.speed_mps.
std::string shortName(std::string_view key)
{
    const std::size_t dot = key.rfind('.');
    return std::string(dot == std::string_view::npos ? key : key.substr(dot + 1));
}

// The name a message gives the value: "fog.start_m", "waves.list[2].amplitude_m".
std::string valueName(const Parameter& p, std::size_t item)
{
    if (p.list == ParameterList::None)
        return std::string(p.key);
    const std::string_view list = listKey(p.list);
    return fmt::format("{}[{}].{}", list, item, p.key.substr(list.size() + 1));
}

// Decimals that show a step of the slider: from its smallest end on a
// logarithmic slider, else from its span.
int decimalsFor(const Parameter& p)
{
    double digits;
    if (p.logarithmic)
        digits = 1.0 - std::floor(std::log10(std::max(std::abs(p.sliderMin), 1e-6)));
    else
        digits = 3.0 - std::floor(std::log10(std::max(p.sliderMax - p.sliderMin, 1e-6)));
    return int(std::clamp(digits, 0.0, 6.0));
}

// A printf format for ImGui: the number, then the unit.
std::string numberFormat(const Parameter& p)
{
    std::string format = p.kind == ParameterKind::Integer ? std::string("%lld") : fmt::format("%.{}f", decimalsFor(p));
    if (!p.unit.empty()) {
        format += ' ';
        for (char c : p.unit)
            format += c == '%' ? std::string("%%") : std::string(1, c);
    }
    return format;
}

// Parameters whose change rebuilds GPU resources are applied once, when the
// slider is let go, not at every step of a drag.
bool appliedOnRelease(const Parameter& p)
{
    return hasEffect(p.effect, ParameterEffect::Grid) || hasEffect(p.effect, ParameterEffect::Programs) ||
           hasEffect(p.effect, ParameterEffect::World);
}

void tooltip(const Parameter& p)
{
    if (!ImGui::IsItemHovered())
        return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
    ImGui::TextUnformatted(p.key.data(), p.key.data() + p.key.size());
    if (!p.description.empty())
        ImGui::TextUnformatted(p.description.data(), p.description.data() + p.description.size());
    ImGui::TextDisabled("allowed: %s", rangeText(p).c_str());
    if (hasEffect(p.effect, ParameterEffect::Waves))
        ImGui::TextDisabled("changes the wave set");
    if (appliedOnRelease(p))
        ImGui::TextDisabled("rebuilds GPU resources: applied when the slider is let go");
    ImGui::TextDisabled("Ctrl+click to type a value outside the slider");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

struct WidgetResult {
    bool changed = false;
    bool active = false;      // the widget is held (a drag in progress)
    bool deactivated = false; // it was let go this frame
};

void noteItemState(WidgetResult& r)
{
    r.active = ImGui::IsItemActive();
    r.deactivated = ImGui::IsItemDeactivated();
}

WidgetResult editValue(const Parameter& p, const char* label, ParameterValue& value)
{
    WidgetResult r;
    const std::string format = numberFormat(p);
    const ImGuiSliderFlags sliderFlags = p.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
    switch (p.kind) {
    case ParameterKind::Real: {
        double& v = std::get<double>(value);
        r.changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &p.sliderMin, &p.sliderMax, format.c_str(), sliderFlags);
        noteItemState(r);
        tooltip(p);
        if (std::isinf(p.max)) {
            // A slider cannot reach an unbounded maximum (deep water).
            bool infinite = std::isinf(v);
            ImGui::Indent();
            if (ImGui::Checkbox("infinite", &infinite)) {
                v = infinite ? std::numeric_limits<double>::infinity() : p.sliderMax;
                r.changed = true;
            }
            ImGui::Unindent();
        }
        return r;
    }
    case ParameterKind::Integer: {
        std::int64_t& v = std::get<std::int64_t>(value);
        const auto lo = std::int64_t(p.sliderMin), hi = std::int64_t(p.sliderMax);
        r.changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &v, &lo, &hi, format.c_str(), sliderFlags);
        break;
    }
    case ParameterKind::Flag:
        r.changed = ImGui::Checkbox(label, &std::get<bool>(value));
        break;
    case ParameterKind::Choice: {
        std::int64_t& index = std::get<std::int64_t>(value);
        const bool known = index >= 0 && std::size_t(index) < p.choices.size();
        const std::string preview = known ? std::string(p.choices[std::size_t(index)]) : std::string("?");
        const bool open = ImGui::BeginCombo(label, preview.c_str());
        noteItemState(r);
        tooltip(p);
        if (open) {
            for (std::size_t c = 0; c < p.choices.size(); ++c) {
                const std::string name(p.choices[c]);
                const bool selected = known && std::size_t(index) == c;
                if (ImGui::Selectable(name.c_str(), selected)) {
                    index = std::int64_t(c);
                    r.changed = true;
                }
                if (selected)
                    ImGui::SetItemDefaultFocus();
            }
            ImGui::EndCombo();
        }
        return r;
    }
    case ParameterKind::Colour: {
        glm::dvec3& v = std::get<glm::dvec3>(value);
        float c[3] = {float(v.x), float(v.y), float(v.z)};
        // Only a touched colour is written back, so float rounding never
        // counts as an edit.
        if (ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float)) {
            v = glm::dvec3(c[0], c[1], c[2]);
            r.changed = true;
        }
        break;
    }
    case ParameterKind::Direction3:
    case ParameterKind::Vector3: {
        glm::dvec3& v = std::get<glm::dvec3>(value);
        double c[3] = {v.x, v.y, v.z};
        if (ImGui::SliderScalarN(label, ImGuiDataType_Double, c, 3, &p.sliderMin, &p.sliderMax, format.c_str(), sliderFlags)) {
            v = glm::dvec3(c[0], c[1], c[2]);
            r.changed = true;
        }
        break;
    }
    case ParameterKind::Direction2: {
        glm::dvec2& v = std::get<glm::dvec2>(value);
        double c[2] = {v.x, v.y};
        if (ImGui::SliderScalarN(label, ImGuiDataType_Double, c, 2, &p.sliderMin, &p.sliderMax, format.c_str(), sliderFlags)) {
            v = glm::dvec2(c[0], c[1]);
            r.changed = true;
        }
        break;
    }
    }
    noteItemState(r);
    tooltip(p);
    return r;
}

std::string itemLabel(ParameterList list, const Scene& scene, std::size_t i)
{
    switch (list) {
    case ParameterList::Waves: {
        const Wave& w = scene.waves.listed.waves[i];
        return fmt::format("wave {}: {:.3g} m long, {:.3g} m high", i + 1, w.wavelength_m, w.amplitude_m);
    }
    case ParameterList::Objects: return fmt::format("object {}: {}", i + 1, scene.objects[i].path);
    case ParameterList::CameraPath: return fmt::format("key {}: at {:.2f} s", i + 1, scene.camera.path[i].time_s);
    case ParameterList::None: break;
    }
    return {};
}

// Applies the current view to the scene's camera pose.
void setCameraPose(CameraSettings& settings, const Camera& camera)
{
    settings.position_m = camera.position_m;
    settings.yaw_deg = std::remainder(camera.yaw_deg, 360.0);
    settings.pitch_deg = std::clamp(camera.pitch_deg, -89.0, 89.0);
}

} // namespace

// ---------------------------------------------------------------------------
// The panel.

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

bool Panel::editParameter(Session& session, const Parameter& p, std::size_t item, Scene& edited)
{
    ImGui::PushID(p.key.data(), p.key.data() + p.key.size());
    ImGui::PushID(int(item));
    ParameterValue value = p.get(edited, item);
    const bool staged = staged_ && staged_->key == p.key && staged_->item == item;
    if (staged)
        value = staged_->value;
    const std::string label = shortName(p.key);
    const WidgetResult r = editValue(p, label.c_str(), value);
    ImGui::PopID();
    ImGui::PopID();

    bool commit = r.changed;
    if (appliedOnRelease(p)) {
        if (r.changed && r.active) {
            staged_ = Staged{p.key, item, value};
            commit = false;
        } else if (r.deactivated && staged) {
            // Let go: `value` holds the staged value, or the last step's.
            staged_.reset();
            commit = true;
        }
    }
    if (!commit)
        return false;
    if (std::string problem = valueProblem(p, value, valueName(p, item)); !problem.empty()) {
        session.refuseEdit(std::move(problem));
        return false;
    }
    p.set(edited, item, value);
    return true;
}

void Panel::drawStats(const FrameStats& stats)
{
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", stats.context.c_str());
    ImGui::PopTextWrapPos();
    const float average = stats.times.average();
    ImGui::Text("%d x %d px   %.2f ms   %.0f fps", stats.size.x, stats.size.y, stats.times.latest(),
                average > 0.0f ? 1000.0f / average : 0.0f);
    ImGui::Text("water %lld triangles, world %lld, %d draw calls", stats.counters.waterTriangles,
                stats.counters.worldTriangles, stats.counters.drawCalls);
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
    ImGui::SliderScalar("time rate", ImGuiDataType_Double, &view.timeRate, &zero, &maxRate, "%.2fx");

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
    ImGui::TextDisabled("Right drag: look   WASD: move   Q/E: down/up");
    ImGui::TextDisabled("Shift: faster   wheel: speed   F1: panel");

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

void Panel::drawList(Session& session, ParameterList list, Scene& edited, bool& changed)
{
    const std::size_t count = listSize(edited, list);
    if (count == 0 && list != ParameterList::Waves)
        ImGui::TextDisabled("none in this scene");
    std::optional<std::size_t> remove;
    for (std::size_t i = 0; i < count; ++i) {
        ImGui::PushID(int(i));
        const std::string label = itemLabel(list, edited, i);
        const bool open = ImGui::TreeNode("##item", "%s", label.c_str());
        if (list == ParameterList::Waves) {
            ImGui::SameLine();
            if (ImGui::SmallButton("remove"))
                remove = i;
        }
        if (open) {
            for (const Parameter& p : parameters())
                if (p.list == list && isPresent(p, edited))
                    changed |= editParameter(session, p, i, edited);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (list != ParameterList::Waves)
        return;
    std::vector<Wave>& waves = edited.waves.listed.waves;
    if (remove) {
        waves.erase(waves.begin() + std::ptrdiff_t(*remove));
        staged_.reset();
        changed = true;
    }
    ImGui::BeginDisabled(waves.size() >= SWELL_MAX_WAVES);
    if (ImGui::Button("add wave")) {
        waves.push_back(Wave{});
        changed = true;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("%zu of %d", waves.size(), SWELL_MAX_WAVES);
}

void Panel::drawParameters(Session& session, Scene& edited, bool& changed)
{
    std::vector<std::string_view> sections;
    for (const Parameter& p : parameters())
        if (std::find(sections.begin(), sections.end(), sectionOf(p)) == sections.end())
            sections.push_back(sectionOf(p));

    for (std::string_view section : sections) {
        const std::string title = sectionTitle(section);
        if (!ImGui::CollapsingHeader(title.c_str()))
            continue;
        ImGui::PushID(title.c_str());
        for (const Parameter& p : parameters())
            if (sectionOf(p) == section && p.list == ParameterList::None && !isWindParameter(p) &&
                p.key != "debug_view" && isPresent(p, edited))
                changed |= editParameter(session, p, 0, edited);

        if (section == "waves") {
            bool wind = edited.waves.wind.has_value();
            if (ImGui::Checkbox("waves from the wind", &wind)) {
                if (wind) {
                    edited.waves.wind = lastWind_.value_or(WindSettings{});
                } else {
                    lastWind_ = edited.waves.wind;
                    edited.waves.wind.reset();
                    // Keep the sea as it looks: the generated waves become the list.
                    std::vector<Wave>& listed = edited.waves.listed.waves;
                    if (listed.empty()) {
                        listed = resolveWaves(edited.waves).waves;
                        if (listed.size() > SWELL_MAX_WAVES)
                            listed.resize(SWELL_MAX_WAVES);
                    }
                }
                staged_.reset();
                changed = true;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("On: waves generated from the wind settings.\n"
                                  "Off: the hand-listed waves (the generated ones are copied in when the list is empty).");
            for (const Parameter& p : parameters())
                if (isWindParameter(p) && isPresent(p, edited))
                    changed |= editParameter(session, p, 0, edited);
        }

        for (ParameterList list : {ParameterList::Waves, ParameterList::Objects, ParameterList::CameraPath}) {
            const std::string_view key = listKey(list);
            if (key.substr(0, key.find('.')) != section)
                continue;
            if (list == ParameterList::Waves && edited.waves.wind)
                continue;
            drawList(session, list, edited, changed);
        }
        ImGui::PopID();
    }
}

PanelRequests Panel::draw(Session& session, ViewState& view, const FrameStats& stats)
{
    PanelRequests requests;
    // A sidebar along the left edge, the height of the window whatever its
    // size; only its width is the user's to change.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    constexpr float kMargin = 8.0f;
    if (width_ <= 0.0f)
        width_ = std::clamp(viewport->WorkSize.x * 0.4f, 300.0f, 440.0f);
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + kMargin, viewport->WorkPos.y + kMargin), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width_, std::max(1.0f, viewport->WorkSize.y - 2.0f * kMargin)), ImGuiCond_Always);
    const bool visible = ImGui::Begin("Swell");
    width_ = std::max(200.0f, ImGui::GetWindowWidth());
    Scene edited = session.scene();
    bool changed = false;
    if (visible) {
        // Room on the right of each widget for the longest key name.
        ImGui::PushItemWidth(-ImGui::GetFontSize() * 11.5f);
        drawStats(stats);
        if (session.editMessage().error) {
            errorText("Not applied: " + session.editMessage().text);
            if (ImGui::SmallButton("dismiss"))
                session.clearEditMessage();
        }
        if (session.shaderMessage().error)
            errorText("Shader reload failed; the previous shaders stay in use.\n" + session.shaderMessage().text);
        drawView(session, view, stats, edited, changed, requests);
        drawFiles(session);
        drawShaders(session, requests);
        drawParameters(session, edited, changed);
        ImGui::PopItemWidth();
    }
    ImGui::End();

    if (changed)
        session.apply(edited);
    if (saveRequest_) {
        saveRequest_ = false;
        Scene toSave = session.scene();
        if (!view.followSceneCamera)
            setCameraPose(toSave.camera, view.fly.camera());
        session.save(toSave, savePath_);
    }
    if (loadRequest_) {
        const fs::path file = *loadRequest_;
        loadRequest_.reset();
        if (session.load(file)) {
            view.time_s = 0.0;
            view.followSceneCamera = true;
            staged_.reset();
            lastWind_.reset();
            sceneLoaded(file);
        }
    }
    return requests;
}

} // namespace swell::app::viewer
