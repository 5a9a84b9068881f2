// Reading the TOML tree into a Scene (reader.h).
#include "scene/reader.h"

#include "scene/suggestions.h"
#include "scene/text_values.h"
#include "swell/gpu/limits.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace swell::detail::scenefile {

namespace {

// ---------------------------------------------------------------------------
// Step 3: reading the TOML tree into a Scene.

// Keys that are not parameters: arrays of tables and strings. The plain
// tables ([waves], [wake], ...) are not listed here: the parameter table says
// which they are (parameterTables), so a table added there is read without a
// second list to keep in step.
enum class Shape { Table, TableList, Faces, ObjectPath, HullNode, ObjectClass, HeightmapPath, RigName };

struct StructuralKey {
    std::string_view key;
    Shape shape;
    ParameterList list; // the array of tables the key sits in (None: not in one)
};

constexpr StructuralKey kStructure[] = {
    {"waves.list", Shape::TableList, ParameterList::None},
    {"sky.faces", Shape::Faces, ParameterList::None},
    {"objects", Shape::TableList, ParameterList::None},
    {"objects.path", Shape::ObjectPath, ParameterList::Objects},
    {"objects.hull_node", Shape::HullNode, ParameterList::Objects},
    {"objects.class", Shape::ObjectClass, ParameterList::Objects},
    {"camera.path", Shape::TableList, ParameterList::None},
    {"camera.rig", Shape::TableList, ParameterList::None},
    {"camera.rig.name", Shape::RigName, ParameterList::CameraRig},
    {"seabed.beaches", Shape::TableList, ParameterList::None},
    {"seabed.shelves", Shape::TableList, ParameterList::None},
    {"seabed.breakwaters", Shape::TableList, ParameterList::None},
    {"seabed.heightmap.path", Shape::HeightmapPath, ParameterList::None},
};

constexpr ParameterList kLists[] = {ParameterList::Waves,         ParameterList::Objects,
                                    ParameterList::CameraPath,    ParameterList::CameraRig,
                                    ParameterList::SeabedBeaches,
                                    ParameterList::SeabedShelves, ParameterList::SeabedBreakwaters};

// The shape of a key that is not a parameter, or nothing when it is unknown.
std::optional<Shape> shapeOf(std::string_view key, ParameterList list)
{
    for (const StructuralKey& s : kStructure)
        if (s.key == key && s.list == list)
            return s.shape;
    const std::vector<std::string> tables = parameterTables(list);
    if (std::find(tables.begin(), tables.end(), key) != tables.end())
        return Shape::Table;
    return std::nullopt;
}

const Parameter* findParameterIn(std::string_view key, ParameterList list)
{
    const Parameter* p = findParameter(key);
    return (p != nullptr && p->list == list) ? p : nullptr;
}

ParameterList listOf(std::string_view tableListKey)
{
    for (ParameterList l : kLists)
        if (listKey(l) == tableListKey)
            return l;
    return ParameterList::None;
}

std::size_t listLimit(ParameterList list)
{
    switch (list) {
    case ParameterList::Waves: return SWELL_MAX_WAVES;
    case ParameterList::Objects: return kMaxSceneObjects;
    case ParameterList::CameraPath: return kMaxCameraKeys;
    case ParameterList::CameraRig: return kMaxRigCameras;
    case ParameterList::SeabedBeaches:
    case ParameterList::SeabedShelves:
    case ParameterList::SeabedBreakwaters: return kMaxSeabedShapes;
    case ParameterList::None: break;
    }
    return 0;
}


std::optional<double> number(const toml::node& node)
{
    if (const auto* i = node.as_integer())
        return static_cast<double>(i->get());
    if (const auto* f = node.as_floating_point())
        return f->get();
    return std::nullopt;
}

class SceneReader {
public:
    explicit SceneReader(Places& places) : places_(places) {}

    Scene read(const toml::table& root)
    {
        readTable(root, "", "", ParameterList::None, 0);
        if (places_.has("waves.wind") && places_.has("waves.list"))
            fail(places_.at("waves.list"),
                 "waves.list and waves.wind exclude each other: list the waves, or let the wind generate them");
        if (places_.has("waves.swell") && !places_.has("waves.wind"))
            fail(places_.at("waves.swell"),
                 "waves.swell adds a swell to the waves generated from waves.wind; add a [waves.wind] table");
        if (scene_.sea.wind && scene_.sea.wind->swell) {
            const int total = scene_.sea.wind->waveCount + scene_.sea.wind->swell->waveCount;
            if (total > SWELL_MAX_WAVES)
                fail(places_.at("waves.swell"),
                     fmt::format("waves.wind.count + waves.swell.count = {}; at most {} waves in all (SWELL_MAX_WAVES)",
                                 total, SWELL_MAX_WAVES));
        }
        checkSunForm();
        // One depth for both wave sources (see WaveSource).
        if (scene_.sea.wind)
            scene_.sea.wind->depth_m = scene_.sea.depth_m;
        return std::move(scene_);
    }

private:
    // The sun is given by its direction, by its angles or by the date, time
    // and place: one form, whole (the angles need both, the place all three).
    void checkSunForm()
    {
        static constexpr std::array<const char*, 2> kAngles{"sun.elevation_deg", "sun.azimuth_deg"};
        static constexpr std::array<const char*, 3> kPlace{"sun.time", "sun.latitude_deg", "sun.longitude_deg"};
        if (scene_.sun.angles)
            checkSunKeys(kAngles, "sun.elevation_deg and sun.azimuth_deg (like a heading, from -z towards +x)");
        if (scene_.sun.place)
            checkSunKeys(kPlace, "sun.time, sun.latitude_deg and sun.longitude_deg");
    }

    // The keys of the sun's form all given (`with` names them), and no key
    // of another form; refused at the form's first key in the file.
    void checkSunKeys(std::span<const char* const> keys, std::string_view with)
    {
        const char* first = nullptr;
        for (const char* key : keys)
            if (places_.has(key) && (first == nullptr || places_.at(key).line < places_.at(first).line))
                first = key;
        for (const char* other : {"sun.direction", "sun.elevation_deg", "sun.azimuth_deg", "sun.time",
                                  "sun.latitude_deg", "sun.longitude_deg"})
            if (places_.has(other) && std::find(keys.begin(), keys.end(), std::string_view(other)) == keys.end())
                fail(places_.at(first),
                     fmt::format("{} and {} exclude each other: give the sun by its direction, by sun.elevation_deg "
                                 "and sun.azimuth_deg, or by sun.time, sun.latitude_deg and sun.longitude_deg",
                                 first, other));
        for (const char* key : keys)
            if (!places_.has(key))
                fail(places_.at(first),
                     fmt::format("{} places the sun with {}; {} is missing{}", first, with, key,
                                 std::string_view(key) == "sun.time"
                                     ? " (a date and time with its UTC offset: sun.time = 2003-10-17T12:30:30-07:00)"
                                     : ""));
    }

    // Entries of a table in the order they appear in the file (toml++ keeps
    // them sorted by name), so the first problem reported is the first one written.
    static std::vector<std::pair<const toml::key*, const toml::node*>> inFileOrder(const toml::table& table)
    {
        std::vector<std::pair<const toml::key*, const toml::node*>> entries;
        for (auto&& [k, v] : table)
            entries.emplace_back(&k, &v);
        std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
            const auto& pa = a.first->source().begin;
            const auto& pb = b.first->source().begin;
            return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
        });
        return entries;
    }

    // schema: the key without item numbers ("objects"); shown: as the user
    // sees it ("objects[2]"); list/item: the array of tables we are inside.
    void readTable(const toml::table& table, const std::string& schema, const std::string& shown, ParameterList list,
                   std::size_t item)
    {
        for (auto [k, node] : inFileOrder(table)) {
            // A quoted key is one name, dots and all: "fog.start_m" = 1 at
            // the top level is not fog.start_m, and must not pass for it.
            if (k->str().find('.') != std::string_view::npos)
                quotedDottedKey(*k, shown);
            std::string childSchema = join(schema, k->str());
            std::string childShown = join(shown, k->str());
            if (const Parameter* p = findParameterIn(childSchema, list)) {
                readParameter(*p, *node, childShown, item);
                continue;
            }
            const std::optional<Shape> shape = shapeOf(childSchema, list);
            if (!shape)
                unknownKey(*k, childSchema, shown, list);
            switch (*shape) {
            case Shape::Table:
                if (!node->is_table())
                    fail(places_.of(node->source()), fmt::format("{} must be a table, not {}", childShown, typeName(*node)));
                places_.add(childShown, node->source());
                // Present, even when empty, means "generate from the wind" (or
                // "add a swell"); a swell read first has already set the wind up.
                if (childSchema == "waves.wind" && !scene_.sea.wind)
                    scene_.sea.wind.emplace();
                if (childSchema == "waves.swell") {
                    if (!scene_.sea.wind)
                        scene_.sea.wind.emplace();
                    if (!scene_.sea.wind->swell)
                        scene_.sea.wind->swell.emplace();
                }
                readTable(*node->as_table(), childSchema, childShown, list, item);
                break;
            case Shape::TableList: readTableList(*node, childSchema, childShown); break;
            case Shape::Faces: readFaces(*node, childShown); break;
            case Shape::ObjectPath:
                scene_.objects[item].path = readPath(*node, childShown, places_);
                places_.add(childShown, node->source());
                break;
            case Shape::HullNode:
                scene_.objects[item].hullNode = readNodeName(*node, childShown, places_);
                places_.add(childShown, node->source());
                break;
            case Shape::ObjectClass:
                scene_.objects[item].className = readClass(*node, childShown, places_);
                places_.add(childShown, node->source());
                break;
            case Shape::RigName:
                scene_.camera.rig[item].name = readRigName(*node, childShown, places_);
                places_.add(childShown, node->source());
                break;
            case Shape::HeightmapPath:
                scene_.seabed.heightmap.path = readPath(*node, childShown, places_);
                places_.add(childShown, node->source());
                break;
            }
        }
    }

    [[noreturn]] void quotedDottedKey(const toml::key& key, const std::string& shownPrefix)
    {
        const std::string name = shortText(key.str());
        const std::string shown = shownPrefix.empty() ? fmt::format("\"{}\"", name) : fmt::format("{}.\"{}\"", shownPrefix, name);
        std::string hint;
        if (const std::string dotted = join(shownPrefix, key.str()); findParameter(dotted) != nullptr)
            hint = fmt::format("; to set {}, write the key without quotes", dotted);
        fail(places_.of(key.source()),
             fmt::format("unknown key '{}': a quoted key is one name, dots included, and no scene key has a dot in "
                         "its name{}",
                         shown, hint));
    }

    static bool isTopLevelKey(std::string_view name)
    {
        for (const Parameter& p : parameters())
            if (p.list == ParameterList::None && p.key == name)
                return true;
        return false;
    }

    [[noreturn]] void unknownKey(const toml::key& key, const std::string& schema, const std::string& shownPrefix,
                                 ParameterList list)
    {
        // Candidates in the same array of tables, written as the user would.
        std::string_view itemKey = listKey(list);
        std::vector<std::string> schemaNames;
        std::vector<std::string> shownNames;
        auto consider = [&](std::string_view name) {
            schemaNames.emplace_back(name);
            shownNames.push_back(list == ParameterList::None ? std::string(name)
                                                             : std::string(shownPrefix) + std::string(name.substr(itemKey.size())));
        };
        for (const Parameter& p : parameters())
            if (p.list == list)
                consider(p.key);
        for (const StructuralKey& s : kStructure)
            if (s.list == list)
                consider(s.key);
        for (const std::string& table : parameterTables(list))
            consider(table);

        std::string shown = join(shownPrefix, key.str());
        std::string message = fmt::format("unknown key '{}'", shortText(shown));
        std::optional<std::string> guess = closest(schema, schemaNames);
        std::string unitHint;
        if (!guess) {
            // The right name in another unit ("direction_rad" for
            // "direction_deg"): the one key of the table whose name is the
            // same up to its unit suffix.
            const std::string_view last = key.str();
            if (const std::size_t underscore = last.rfind('_'); underscore != std::string_view::npos && underscore > 0) {
                const std::string stem =
                    schema.substr(0, schema.size() - last.size()) + std::string(last.substr(0, underscore + 1));
                std::vector<std::string> sameStem;
                for (const std::string& n : schemaNames)
                    if (n.starts_with(stem) && n.find('.', stem.size()) == std::string::npos)
                        sameStem.push_back(n);
                if (sameStem.size() == 1) {
                    guess = sameStem.front();
                    if (const Parameter* p = findParameterIn(*guess, list); p != nullptr && !p->unit.empty())
                        unitHint = fmt::format(", in {}", p->unit);
                }
            }
        }
        if (!guess) {
            // A key of the same table that the word begins, or that begins
            // it ("coverage" for "cover"): the one such key, 4 letters shared at least.
            const std::string_view last = key.str();
            const std::string table = schema.substr(0, schema.size() - last.size());
            std::vector<std::string> sharing;
            for (const std::string& n : schemaNames) {
                if (!n.starts_with(table) || n.find('.', table.size()) != std::string::npos)
                    continue;
                const std::string_view name = std::string_view(n).substr(table.size());
                if (std::min(name.size(), last.size()) >= 4 && (name.starts_with(last) || last.starts_with(name)))
                    sharing.push_back(n);
            }
            if (sharing.size() == 1)
                guess = sharing.front();
        }
        if (!guess) {
            // A known key in the wrong table: the same last part, exactly one owner.
            std::string_view last = key.str();
            std::vector<std::string> owners;
            for (const std::string& n : schemaNames)
                if (n.size() > last.size() && n.ends_with(last) && n[n.size() - last.size() - 1] == '.')
                    owners.push_back(n);
            if (owners.size() == 1)
                guess = owners.front();
        }
        if (guess) {
            auto at = std::find(schemaNames.begin(), schemaNames.end(), *guess) - schemaNames.begin();
            message += fmt::format("; did you mean '{}'{}?", shownNames[static_cast<std::size_t>(at)], unitHint);
        } else if (const std::size_t dot = shown.rfind('.'); dot != std::string::npos && isTopLevelKey(key.str())) {
            // In TOML a key belongs to the last [table] above it, so a
            // top-level key written after one lands in that table.
            message += fmt::format("; '{}' is a top-level key: write it above the first [table] header, "
                                   "since every key after [{}] belongs to that table",
                                   key.str(), shown.substr(0, dot));
        }
        fail(places_.of(key.source()), message);
    }

    void readTableList(const toml::node& node, const std::string& schema, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr)
            fail(places_.of(node.source()),
                 fmt::format("{} must be an array of tables, written [[{}]], not {}", shown, schema, typeName(node)));
        places_.add(shown, node.source());
        ParameterList list = listOf(schema);
        std::size_t limit = listLimit(list);
        if (array->size() > limit)
            fail(places_.of((*array)[limit].source()),
                 fmt::format("{} has {} entries; at most {} are allowed", shown, array->size(), limit));
        for (std::size_t i = 0; i < array->size(); ++i) {
            const toml::node& element = (*array)[i];
            std::string itemShown = fmt::format("{}[{}]", shown, i);
            if (!element.is_table())
                fail(places_.of(element.source()), fmt::format("{} must be a table, not {}", itemShown, typeName(element)));
            places_.add(itemShown, element.source());
            switch (list) {
            case ParameterList::Waves: scene_.waves.listed.emplace_back(); break;
            case ParameterList::Objects: scene_.objects.emplace_back(); break;
            case ParameterList::CameraPath: scene_.camera.path.emplace_back(); break;
            case ParameterList::CameraRig: scene_.camera.rig.emplace_back(); break;
            case ParameterList::SeabedBeaches: scene_.seabed.beaches.emplace_back(); break;
            case ParameterList::SeabedShelves: scene_.seabed.shelves.emplace_back(); break;
            case ParameterList::SeabedBreakwaters: scene_.seabed.breakwaters.emplace_back(); break;
            case ParameterList::None: break;
            }
            readTable(*element.as_table(), schema, itemShown, list, i);
            if (list == ParameterList::Objects && !places_.has(itemShown + ".path"))
                fail(places_.of(element.source()),
                     fmt::format("{} needs a path: a .gltf or .glb file, or \"builtin:NAME\"", itemShown));
            if (list == ParameterList::CameraRig && !places_.has(itemShown + ".name"))
                fail(places_.of(element.source()),
                     fmt::format("{} needs a name (its files are NAME.<name>.png, ...): name = \"left\"", itemShown));
        }
    }

    void readFaces(const toml::node& node, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr)
            fail(places_.of(node.source()),
                 fmt::format("{} must be an array of 6 image paths (+x, -x, +y, -y, +z, -z), not {}", shown, typeName(node)));
        places_.add(shown, node.source());
        if (array->size() != 0 && array->size() != 6)
            fail(places_.of(node.source()),
                 fmt::format("{} must list 6 image paths (+x, -x, +y, -y, +z, -z), or none for the procedural sky; "
                             "it lists {}",
                             shown, array->size()));
        scene_.sky.cubemapFaces.clear();
        for (std::size_t i = 0; i < array->size(); ++i) {
            std::string faceShown = fmt::format("{}[{}]", shown, i);
            scene_.sky.cubemapFaces.push_back(readPath((*array)[i], faceShown, places_));
            places_.add(faceShown, (*array)[i].source());
        }
    }

    [[noreturn]] void wrongType(const Parameter& p, const toml::node& node, const std::string& shown)
    {
        std::string expected;
        std::string unit = p.unit.empty() ? std::string() : fmt::format(" ({})", p.unit);
        switch (p.kind) {
        case ParameterKind::Real: expected = "a number" + unit; break;
        case ParameterKind::Integer: expected = "a whole number"; break;
        case ParameterKind::Flag: expected = "true or false"; break;
        case ParameterKind::Choice: expected = "one of " + rangeText(p); break;
        case ParameterKind::Colour: expected = "an array of 3 numbers [r, g, b]"; break;
        case ParameterKind::Direction3:
        case ParameterKind::Vector3: expected = "an array of 3 numbers [x, y, z]" + unit; break;
        case ParameterKind::Direction2:
        case ParameterKind::Vector2: expected = "an array of 2 numbers [x, z]" + unit; break;
        case ParameterKind::DateTime:
            expected = "a date and time with its UTC offset (2003-10-17T12:30:30-07:00, or Z for UTC)";
            break;
        }
        fail(places_.of(node.source()), fmt::format("{} must be {}, not {}", shown, expected, typeName(node)));
    }

    // A scalar, or one component of a vector (then `shown` is "sun.color[1]").
    double readNumber(const Parameter& p, const toml::node& node, const std::string& shown, bool component)
    {
        std::optional<double> x = number(node);
        if (!x && component)
            fail(places_.of(node.source()), fmt::format("{} must be a number, not {}", shown, typeName(node)));
        if (!x)
            wrongType(p, node, shown);
        if (!inRange(p, *x))
            fail(places_.of(node.source()), rangeMessage(p, shown, *x));
        return *x;
    }

    template <int N>
    glm::vec<N, double> readVector(const Parameter& p, const toml::node& node, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr || array->size() != N) {
            if (array != nullptr)
                fail(places_.of(node.source()),
                     fmt::format("{} must have {} components, not {}", shown, N, array->size()));
            wrongType(p, node, shown);
        }
        glm::vec<N, double> v(0.0);
        for (int c = 0; c < N; ++c)
            v[c] = readNumber(p, (*array)[static_cast<std::size_t>(c)], fmt::format("{}[{}]", shown, c), true);
        return v;
    }

    // A TOML offset date-time as seconds since 1970-01-01T00:00:00Z. A local
    // date-time (no offset) names no instant, so it is refused, as are a
    // date or a time alone.
    double readDateTime(const Parameter& p, const toml::node& node, const std::string& shown)
    {
        const auto* v = node.as_date_time();
        if (v == nullptr)
            wrongType(p, node, shown);
        const toml::date_time& dt = v->get();
        if (!dt.offset)
            fail(places_.of(node.source()),
                 fmt::format("{} has no UTC offset, so it names no instant; add one (2003-10-17T12:30:30-07:00), or "
                             "Z for UTC",
                             shown));
        using namespace std::chrono;
        const year_month_day date{year{int(dt.date.year)}, month{unsigned(dt.date.month)}, day{unsigned(dt.date.day)}};
        const double day_s = double(sys_days{date}.time_since_epoch().count()) * 86400.0;
        const double x = day_s + dt.time.hour * 3600.0 + dt.time.minute * 60.0 + dt.time.second
            + dt.time.nanosecond * 1.0e-9 - dt.offset->minutes * 60.0;
        if (!inRange(p, x))
            fail(places_.of(node.source()), rangeMessage(p, shown, x));
        return x;
    }

    void readParameter(const Parameter& p, const toml::node& node, const std::string& shown, std::size_t item)
    {
        ParameterValue value;
        switch (p.kind) {
        case ParameterKind::Real: value = readNumber(p, node, shown, false); break;
        case ParameterKind::Integer: {
            const auto* i = node.as_integer();
            if (i == nullptr)
                wrongType(p, node, shown);
            if (!inRange(p, static_cast<double>(i->get())))
                fail(places_.of(node.source()), rangeMessage(p, shown, static_cast<double>(i->get())));
            value = i->get();
            break;
        }
        case ParameterKind::Flag: {
            const auto* b = node.as_boolean();
            if (b == nullptr)
                wrongType(p, node, shown);
            value = b->get();
            break;
        }
        case ParameterKind::Choice: {
            const auto* s = node.as_string();
            if (s == nullptr)
                wrongType(p, node, shown);
            auto it = std::find(p.choices.begin(), p.choices.end(), s->get());
            if (it == p.choices.end()) {
                std::vector<std::string> names(p.choices.begin(), p.choices.end());
                std::optional<std::string> guess = closest(s->get(), names);
                fail(places_.of(node.source()),
                     fmt::format("{} = \"{}\" is not a choice; allowed {}{}", shown, shortText(s->get()), rangeText(p),
                                 guess ? fmt::format("; did you mean \"{}\"?", *guess) : std::string()));
            }
            value = static_cast<std::int64_t>(it - p.choices.begin());
            break;
        }
        case ParameterKind::Colour:
        case ParameterKind::Direction3:
        case ParameterKind::Vector3: value = readVector<3>(p, node, shown); break;
        case ParameterKind::Direction2:
        case ParameterKind::Vector2: value = readVector<2>(p, node, shown); break;
        case ParameterKind::DateTime: value = readDateTime(p, node, shown); break;
        }
        places_.add(shown, node.source());
        // What is left: zero-length directions.
        if (std::string problem = valueProblem(p, value, shown); !problem.empty())
            fail(places_.of(node.source()), problem);
        p.set(scene_, item, value);
    }

    Places& places_;
    Scene scene_;
};

} // namespace

Scene readScene(const toml::table& root, Places& places)
{
    return SceneReader(places).read(root);
}

std::string typeName(const toml::node& node)
{
    switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
    }
}

} // namespace swell::detail::scenefile
