// The one table of every scalar and vector scene parameter: its TOML key,
// unit, range, default, a one-line description and an accessor into
// swell::Scene. Scene files (swell/scene/scene_file.h) check values against it,
// docs/SCENE.md is generated from it, and the viewer takes its slider ranges
// and units from it, so a range is written down exactly once.
//
// Strings (object paths, sky cubemap faces) and the shape of the scene (is
// the wind set, how many objects) are not parameters; scene_file.h handles
// them and docs/SCENE.md describes them by hand.
//
// A GUI walks the table like this:
//
//   for (const Parameter& p : parameters()) {
//       if (p.list != ParameterList::None || !isPresent(p, scene)) continue;
//       ParameterValue v = p.get(scene, 0);
//       ... edit v within p.sliderMin..p.sliderMax, labelled p.key and p.unit ...
//       p.set(scene, 0, v); // then redo what p.effect says
//   }
#pragma once

#include "swell/export.h"

#include "swell/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace swell {

// How a parameter is stored, written in TOML and edited.
enum class ParameterKind {
    Real,       // double; TOML integer or float
    Integer,    // whole number (int or uint32 in Scene), held as int64; TOML integer
    Flag,       // bool; TOML true/false
    Choice,     // an enum, held as the int64 index into Parameter::choices; TOML string
    Colour,     // glm::dvec3 linear RGB; TOML [r, g, b]
    Direction3, // glm::dvec3 of any non-zero length, normalised on use; TOML [x, y, z]
    Vector3,    // glm::dvec3, every component in range; TOML [x, y, z]
    Direction2, // glm::dvec2 in the xz plane, non-zero, normalised on use; TOML [x, z]
    Vector2,    // glm::dvec2, a point or size in the xz plane, every component in range; TOML [x, z]
    DateTime,   // an instant, double seconds since 1970-01-01T00:00:00Z; TOML offset date-time
                // (2003-10-17T12:30:30-07:00), written back in UTC (2003-10-17T19:30:30Z)
};

// The value of any parameter. Which alternative a kind uses:
//   Real, DateTime: double; Integer, Choice: int64; Flag: bool;
//   Colour, Direction3, Vector3: glm::dvec3; Direction2, Vector2: glm::dvec2.
using ParameterValue = std::variant<double, std::int64_t, bool, glm::dvec2, glm::dvec3>;

// The most scene objects a scene may hold (the [[objects]] list, and so the
// range of camera.mount_object): each object is a draw call per pass, and
// this many stay interactive.
inline constexpr std::size_t kMaxSceneObjects = 256;

// Where a parameter lives: a single value in the scene, or one per item of an
// array of tables (the accessor's `item` argument picks the item).
enum class ParameterList {
    None,       // one value per scene; `item` is ignored
    Waves,      // [[waves.list]]  -> Scene::waves.listed[item]
    Objects,    // [[objects]]     -> Scene::objects[item]
    CameraPath, // [[camera.path]] -> Scene::camera.path[item]
    CameraRig,  // [[camera.rig]]  -> Scene::camera.rig[item]
    SeabedBeaches,     // [[seabed.beaches]]     -> Scene::seabed.beaches[item]
    SeabedShelves,     // [[seabed.shelves]]     -> Scene::seabed.shelves[item]
    SeabedBreakwaters, // [[seabed.breakwaters]] -> Scene::seabed.breakwaters[item]
};

// What a change to the parameter asks of a renderer that is already running:
// a set of flags, since one parameter may ask for several things. The table
// is the only place that says it: Renderer::setScene and the viewer act on
// sceneChanges() (swell/scene/scene_changes.h), which reads these.
enum class ParameterEffect : unsigned {
    Frame = 0,          // picked up by the next frame (colours, camera, fog, poses)
    Waves = 1u << 0,    // the wave model is built again from the scene's waves
    Grid = 1u << 1,     // the water grid's index buffer is rebuilt
    Programs = 1u << 2, // the shader programs are rebuilt (a #define variant)
    World = 1u << 3,    // meshes and the sky are built again (asset files are read)
    Bodies = 1u << 4,   // the floating bodies and their wake start again (what moves them changed;
                        // objects that are bodies in neither scene move none)
    Seabed = 1u << 5,   // the sea floor (swell/scene/seabed.h) is built again, its heightmap read and
                        // its mesh uploaded, and so is what depends on the depth
};

constexpr ParameterEffect operator|(ParameterEffect a, ParameterEffect b)
{
    return ParameterEffect(unsigned(a) | unsigned(b));
}
constexpr ParameterEffect& operator|=(ParameterEffect& a, ParameterEffect b) { return a = a | b; }
// Whether `effects` includes every flag of `flag`, and it is not Frame.
constexpr bool hasEffect(ParameterEffect effects, ParameterEffect flag)
{
    return unsigned(flag) != 0 && (unsigned(effects) & unsigned(flag)) == unsigned(flag);
}

struct SWELL_API Parameter {
    // Full dotted TOML key. Inside an array of tables it starts with the
    // array's key: "objects.scale" is `scale` inside an [[objects]] item.
    std::string_view key{};
    ParameterKind kind = ParameterKind::Real;
    ParameterList list = ParameterList::None;
    ParameterEffect effect = ParameterEffect::Frame;
    // SI-style unit symbol ("m", "deg", "m/s", "1/m"), or "" when dimensionless.
    std::string_view unit{};
    // Hard bounds, checked when a scene is loaded, for the value or for every
    // component of a vector. Inclusive, except that `min` itself is refused
    // when minExclusive (a wavelength must be > 0). max may be +infinity.
    double min = 0.0;
    double max = 0.0;
    bool minExclusive = false;
    // A GUI's slider span: finite, inside min..max. Values outside it are
    // valid, just unusual. Logarithmic when the span covers decades.
    double sliderMin = 0.0;
    double sliderMax = 0.0;
    bool logarithmic = false;
    std::string_view description{}; // one line, no unit (that is `unit`)
    // Choice only: the TOML names, indexed by the enum's value.
    std::span<const std::string_view> choices{};

    // Read and write the parameter in a scene. `item` indexes the list named
    // by `list` and must be in range. set() does not check ranges (load and
    // validateScene() do); it throws std::bad_variant_access when `value`
    // holds the wrong alternative for `kind`.
    ParameterValue (*get)(const Scene& scene, std::size_t item) = nullptr;
    void (*set)(Scene& scene, std::size_t item, const ParameterValue& value) = nullptr;
    // Whether the parameter means anything in this scene (the wind settings
    // only when the waves come from the wind); nullptr: always.
    bool (*present)(const Scene& scene) = nullptr;

    // The value a scene file gets when it leaves the key out: the default
    // member initialisers of Scene, WindSettings, Wave, SceneObject, CameraKey.
    ParameterValue defaultValue{};
};

// Every parameter, in the order scene files and docs list them.
SWELL_API std::span<const Parameter> parameters();

// The parameter with this full key ("fog.start_m", "objects.scale"), or nullptr.
SWELL_API const Parameter* findParameter(std::string_view key);

// The TOML key of an array of tables: "waves.list", "objects", "camera.path",
// "seabed.beaches", ...; "" for ParameterList::None.
SWELL_API std::string_view listKey(ParameterList list);

// Every table that holds parameters of `list`, each once, in the table's
// order: for None "waves", "waves.wind", "waves.swell", "grid", ... "wake",
// "camera" (a table holding only other tables counts too); for an array of
// tables, the tables inside its items (none today). Scene files read exactly
// these as tables, and saveScene() writes them, so a parameter added to the
// table is read and written with no second list to update.
SWELL_API std::vector<std::string> parameterTables(ParameterList list);

// How many items the scene has in that list (1 for ParameterList::None).
SWELL_API std::size_t listSize(const Scene& scene, ParameterList list);

// p.present is null or says yes.
SWELL_API bool isPresent(const Parameter& p, const Scene& scene);

// How many numbers the kind holds: 3 for Colour/Direction3/Vector3, 2 for
// Direction2/Vector2, 1 otherwise.
SWELL_API int componentCount(ParameterKind kind);

// Whether one number (a scalar, or one component of a vector) is allowed:
// NaN never is, infinity only when max is +infinity.
SWELL_API bool inRange(const Parameter& p, double x);

// The allowed values in words, with the unit: "0..1000000 m",
// "> 0 and <= 10000 m", "\"raymarch\" or \"fixed\"", "true or false".
SWELL_API std::string rangeText(const Parameter& p);

// The message for a number outside p's range, naming it as `name` (the key
// as the user wrote it: "fog.start_m", "objects[2].scale", "sun.color[1]"):
// "fog.start_m = -5 is out of range; allowed 0..1000000 m".
SWELL_API std::string rangeMessage(const Parameter& p, std::string_view name, double x);

// Why the value is not allowed for p, or "" when it is: the wrong variant
// alternative, a number or component out of range, a zero-length direction,
// a choice index past the end. The message names the value as `name`, or as
// p.key when `name` is empty.
SWELL_API std::string valueProblem(const Parameter& p, const ParameterValue& value, std::string_view name = {});

// The value as a TOML literal: 1200.0, 256, true, "raymarch", [0.7, 0.8, 0.9], inf,
// 2003-10-17T19:30:30Z.
SWELL_API std::string formatValue(const Parameter& p, const ParameterValue& value);

// An instant (seconds since 1970-01-01T00:00:00Z) as a TOML date-time in
// UTC, to the second: 2003-10-17T19:30:30Z.
SWELL_API std::string formatDateTime(double time_s);

} // namespace swell
