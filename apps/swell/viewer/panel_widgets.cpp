// The panel's small parts: coloured messages, names and sections derived
// from the parameter table's keys, and one widget per parameter kind whose
// format, range and tooltip come from the table.
#include "viewer/panel_widgets.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h> // TempInputIsActive: a slider's typed value

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace swell::app::viewer {

namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.40f, 1.0f);

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

void noteItemState(WidgetResult& r)
{
    r.active = ImGui::IsItemActive();
    r.deactivated = ImGui::IsItemDeactivated();
}

// Whether the slider just drawn holds a value being typed (its text field
// after a Ctrl+click), which changes at each keystroke.
void noteTyping(WidgetResult& r) { r.typing = ImGui::TempInputIsActive(ImGui::GetItemID()); }

} // namespace

bool appliedOnRelease(const Parameter& p)
{
    return hasEffect(p.effect, ParameterEffect::Grid) || hasEffect(p.effect, ParameterEffect::Programs) ||
           hasEffect(p.effect, ParameterEffect::World);
}

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
        noteTyping(r);
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
        } else if (std::isinf(p.min)) {
            // Likewise an unbounded minimum (a history that always ran).
            bool infinite = std::isinf(v);
            ImGui::Indent();
            if (ImGui::Checkbox("-infinite", &infinite)) {
                v = infinite ? -std::numeric_limits<double>::infinity() : 0.0;
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
        noteTyping(r);
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
    case ParameterKind::DateTime: {
        // The hour of the day (UTC) on a slider, the date kept: what moves
        // the sun across the sky; the full instant is shown beside it.
        double& v = std::get<double>(value);
        const double dayStart_s = std::floor(v / 86400.0) * 86400.0;
        double hour_h = (v - dayStart_s) / 3600.0;
        const double lo = 0.0, hi = 24.0;
        if (ImGui::SliderScalar(label, ImGuiDataType_Double, &hour_h, &lo, &hi, "%.2f h UTC")) {
            v = dayStart_s + std::clamp(hour_h, 0.0, 24.0) * 3600.0;
            r.changed = true;
        }
        noteItemState(r);
        tooltip(p);
        ImGui::Indent();
        ImGui::TextDisabled("%s", formatDateTime(v).c_str());
        ImGui::Unindent();
        return r;
    }
    case ParameterKind::Direction2:
    case ParameterKind::Vector2: {
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

bool heldUntilRelease(const Parameter& p, const WidgetResult& r) { return appliedOnRelease(p) || r.typing; }

namespace {

bool holds(const std::optional<StagedValue>& staged, const Parameter& p, std::size_t item)
{
    return staged && staged->key == p.key && staged->item == item;
}

} // namespace

ParameterValue shownValue(const Parameter& p, std::size_t item, const Scene& scene,
                          const std::optional<StagedValue>& staged)
{
    return holds(staged, p, item) ? staged->value : p.get(scene, item);
}

bool takeEdit(const Parameter& p, std::size_t item, const WidgetResult& r, const ParameterValue& value,
              std::optional<StagedValue>& staged)
{
    if (heldUntilRelease(p, r) && r.changed && r.active) {
        staged = StagedValue{p.key, item, value};
        return false;
    }
    if (r.deactivated && holds(staged, p, item)) {
        // Let go (or Enter typed): `value` holds the staged value, or the last step's.
        staged.reset();
        return true;
    }
    return r.changed;
}

std::optional<std::string> clampToRange(const Parameter& p, ParameterValue& value, std::string_view name)
{
    double typed = 0.0;
    if (const auto* d = std::get_if<double>(&value))
        typed = *d;
    else if (const auto* i = std::get_if<std::int64_t>(&value))
        typed = double(*i);
    else
        return std::nullopt;
    const bool below = p.minExclusive ? typed <= p.min : typed < p.min;
    if (std::isnan(typed) || (!below && typed <= p.max) || (below && p.minExclusive))
        return std::nullopt; // in range; or NaN, or at an excluded end: the range check says why
    const double kept = below ? p.min : p.max;
    if (std::holds_alternative<double>(value))
        value = kept;
    else
        value = std::int64_t(kept);
    return fmt::format("{:g} is {} {}'s range {}: clamped to {:g}", typed, below ? "below" : "above", name,
                       rangeText(p), kept);
}

std::string itemLabel(ParameterList list, const Scene& scene, std::size_t i)
{
    switch (list) {
    case ParameterList::Waves: {
        const Wave& w = scene.waves.listed[i];
        return fmt::format("wave {}: {:.3g} m long, {:.3g} m high", i + 1, w.wavelength_m, w.amplitude_m);
    }
    case ParameterList::Objects: return fmt::format("object {}: {}", i + 1, scene.objects[i].path);
    case ParameterList::CameraPath: return fmt::format("key {}: at {:.2f} s", i + 1, scene.camera.path[i].time_s);
    case ParameterList::CameraRig: return fmt::format("rig camera {}: {}", i + 1, scene.camera.rig[i].name);
    case ParameterList::SeabedBeaches: return fmt::format("beach {}: slope {:.3g}", i + 1, scene.seabed.beaches[i].slope);
    case ParameterList::SeabedShelves: return fmt::format("shelf {}: {:.3g} m deep", i + 1, scene.seabed.shelves[i].depth_m);
    case ParameterList::SeabedBreakwaters:
        return fmt::format("breakwater {}: crest {:.3g} m", i + 1, scene.seabed.breakwaters[i].crest_m);
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

} // namespace swell::app::viewer
