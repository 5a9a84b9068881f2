// The panel's small parts, shared by its sections: coloured messages, the
// names and sections the panel derives from parameter keys, and editValue(),
// one widget for any parameter of the table (swell/scene/parameters.h).
#pragma once

#include "viewer/session.h"

#include "swell/camera.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace swell::app::viewer {

// Parameters whose change rebuilds GPU resources are applied once, when the
// slider is let go, not at every step of a drag.
bool appliedOnRelease(const Parameter& p);

// Wrapped text in the panel's error colour.
void errorText(const std::string& text);
// A message: in the error colour when it is one; nothing when empty.
void message(const Message& m);

// The panel section of a parameter: the first part of its table's key
// ("waves" for waves.wind.speed_mps and waves.list.*); "" for top-level keys.
std::string_view sectionOf(const Parameter& p);
// "Waves" for "waves", "General" for "".
std::string sectionTitle(std::string_view section);
// The wind's parameters sit under the switch that turns the wind on.
bool isWindParameter(const Parameter& p);
// The key without its tables: "speed_mps" for waves.wind.speed_mps.
std::string shortName(std::string_view key);
// The name a message gives the value: "fog.start_m", "waves.list[2].amplitude_m".
std::string valueName(const Parameter& p, std::size_t item);
// The heading of item i of a list: "wave 2: 12 m long, 0.3 m high".
std::string itemLabel(ParameterList list, const Scene& scene, std::size_t i);
// Sets the scene camera's position, heading and pitch from a camera.
void setCameraPose(CameraSettings& settings, const Camera& camera);

struct WidgetResult {
    bool changed = false;
    bool active = false;      // the widget is held (a drag in progress)
    bool deactivated = false; // it was let go this frame
    bool typing = false;      // a value is being typed into it (Ctrl+click): each keystroke changes it
};

// One parameter's widget labelled `label`, editing `value` in place.
WidgetResult editValue(const Parameter& p, const char* label, ParameterValue& value);

// Whether a change is held back until the widget is let go: a rebuild's
// slider (appliedOnRelease), and a value being typed, whose keystrokes are
// not values ("2" on the way to "25").
bool heldUntilRelease(const Parameter& p, const WidgetResult& r);

// A value held back while its widget is held: a rebuild's slider, a number
// being typed.
struct StagedValue {
    std::string_view key;
    std::size_t item = 0;
    ParameterValue value;
};

// The value p's widget shows for `item`: the one held back, else the scene's.
ParameterValue shownValue(const Parameter& p, std::size_t item, const Scene& scene,
                          const std::optional<StagedValue>& staged);

// After p's widget changed `value` (editValue's result r): whether the value
// goes to the scene now. One held back (heldUntilRelease) waits in `staged`
// and goes when the widget is let go or Enter ends the typing.
bool takeEdit(const Parameter& p, std::size_t item, const WidgetResult& r, const ParameterValue& value,
              std::optional<StagedValue>& staged);

// A number typed outside the parameter's documented range, brought inside
// it: the value clamped in place and the words that say so ("25 is above
// sun.intensity's range 0..20: clamped to 20"); nothing for a value in range,
// a vector, a choice or NaN (which the range check refuses).
std::optional<std::string> clampToRange(const Parameter& p, ParameterValue& value, std::string_view name);

} // namespace swell::app::viewer
