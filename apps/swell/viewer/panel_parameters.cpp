// The panel's parameter sections: every parameter of the table, grouped by
// the first part of its key, one widget each; the lists (waves, objects,
// camera keys) as trees; the switch between wind and listed waves. Rebuild
// parameters are staged while their slider is held and applied on release.
#include "viewer/panel.h"

#include "viewer/panel_widgets.h"

#include "swell/gpu/limits.h"

#include <imgui.h>

#include <algorithm>

namespace swell::app::viewer {

bool Panel::editParameter(Session& session, const Parameter& p, std::size_t item, Scene& edited)
{
    ImGui::PushID(p.key.data(), p.key.data() + p.key.size());
    ImGui::PushID(int(item));
    ParameterValue value = shownValue(p, item, edited, staged_);
    const std::string label = shortName(p.key);
    const WidgetResult r = editValue(p, label.c_str(), value);
    ImGui::PopID();
    ImGui::PopID();

    const Field field{p.key, item};
    bool accepted = false;
    if (takeEdit(p, item, r, value, staged_)) {
        // A number typed past the documented range is taken at its end, and says so.
        std::optional<std::string> clamped = clampToRange(p, value, valueName(p, item));
        if (std::string problem = valueProblem(p, value, valueName(p, item)); !problem.empty()) {
            session.refuseEdit(std::move(problem));
            refused_ = field;
        } else {
            p.set(edited, item, value);
            lastEdited_ = field;
            accepted = true;
            clamped_ = clamped ? std::optional<Note>(Note{field, std::move(*clamped)}) : std::nullopt;
        }
    }
    // Beside the field, where the eye is, not at the top of a scrolled panel.
    const float top = ImGui::GetCursorPosY();
    if (refused_ == field && session.editMessage().error) {
        refusedEditText(session);
        refusedShown_ = true;
    } else if (clamped_ && clamped_->field == field) {
        ImGui::TextWrapped("%s", clamped_->text.c_str());
    }
    keepMessageRow(field, ImGui::GetCursorPosY() - top);
    return accepted;
}

void Panel::keepMessageRow(const Field& field, float messageHeight)
{
    // The space a message took under its field stays when the message goes
    // (dismissed, or the value put right), so the rows below do not jump
    // under the pointer; it is given back once the pointer leaves the panel.
    if (messageHeight > 0.0f) {
        messageRow_ = MessageRow{field, std::max(messageHeight, messageRow_ && messageRow_->field == field
                                                                    ? messageRow_->height
                                                                    : 0.0f)};
        if (messageHeight < messageRow_->height)
            ImGui::Dummy(ImVec2(0.0f, messageRow_->height - messageHeight - ImGui::GetStyle().ItemSpacing.y));
    } else if (messageRow_ && messageRow_->field == field) {
        ImGui::Dummy(ImVec2(0.0f, messageRow_->height - ImGui::GetStyle().ItemSpacing.y));
    }
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
    std::vector<Wave>& waves = edited.waves.listed;
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
            bool wind = edited.sea.wind.has_value();
            if (ImGui::Checkbox("waves from the wind", &wind)) {
                if (wind) {
                    edited.sea.wind = lastWind_.value_or(WindSettings{});
                } else {
                    lastWind_ = edited.sea.wind;
                    edited.sea.wind.reset();
                    // Keep the sea as it looks: the generated waves become the list.
                    std::vector<Wave>& listed = edited.waves.listed;
                    if (listed.empty()) {
                        listed = resolveWaves(edited).waves;
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

        for (ParameterList list : {ParameterList::Waves, ParameterList::Objects, ParameterList::CameraPath,
                                   ParameterList::CameraRig, ParameterList::SeabedBeaches, ParameterList::SeabedShelves,
                                   ParameterList::SeabedBreakwaters}) {
            const std::string_view key = listKey(list);
            if (key.substr(0, key.find('.')) != section)
                continue;
            if (list == ParameterList::Waves && edited.sea.wind)
                continue;
            drawList(session, list, edited, changed);
        }
        ImGui::PopID();
    }
}

} // namespace swell::app::viewer
