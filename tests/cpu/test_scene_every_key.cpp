// Every key a scene file may hold, written from the parameter table (not from
// a hand list) in its documented place, in each form TOML allows: [table]
// sections, inline tables and dotted keys. A table the reader forgets (as it
// once forgot [wake]) fails here the day a parameter is added to it.
#include "core/fleet.h"
#include "swell/camera.h"
#include "swell/error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace swell;

namespace {

// A folder holding the files the generated scenes name (sky faces, a model).
// The loader checks that they exist and are regular files; it does not decode them.
fs::path everyKeyFolder()
{
    static const fs::path folder = [] {
        fs::path f = fs::path(SWELL_TEST_OUTPUT_DIR) / "scene_every_key";
        fs::create_directories(f / "sky");
        for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
            std::ofstream(f / "sky" / fmt::format("{}.png", face), std::ios::binary) << "png";
        std::ofstream(f / "hull.glb", std::ios::binary) << "glTF";
        std::ofstream(f / "floor.png", std::ios::binary) << "png";
        return f;
    }();
    return folder;
}

std::string everyKeyScenePath() { return (everyKeyFolder() / "every_key.toml").string(); }

// A TOML table as a tree: its own key = value lines, its sub-tables, and its
// arrays of tables (each item a table).
struct TomlTable {
    std::vector<std::pair<std::string, std::string>> values;
    std::map<std::string, TomlTable> tables;
    std::map<std::string, std::vector<TomlTable>> lists;

    TomlTable& table(std::string_view dotted)
    {
        TomlTable* t = this;
        std::size_t start = 0;
        while (start < dotted.size()) {
            std::size_t dot = dotted.find('.', start);
            std::string part(dotted.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
            t = &t->tables[part];
            start = dot == std::string_view::npos ? dotted.size() : dot + 1;
        }
        return *t;
    }
};

enum class Form { Sections, InlineTables, DottedKeys };

const char* formName(Form f)
{
    switch (f) {
    case Form::Sections: return "sections";
    case Form::InlineTables: return "inline tables";
    case Form::DottedKeys: return "dotted keys";
    }
    return "";
}

std::string inlineTable(const TomlTable& t);

// The entries of `t` inside braces: key = value, sub-tables inline, lists as
// arrays of inline tables.
std::string inlineEntries(const TomlTable& t)
{
    std::vector<std::string> entries;
    for (const auto& [k, v] : t.values)
        entries.push_back(fmt::format("{} = {}", k, v));
    for (const auto& [k, sub] : t.tables)
        entries.push_back(fmt::format("{} = {}", k, inlineTable(sub)));
    for (const auto& [k, items] : t.lists) {
        std::vector<std::string> written;
        for (const TomlTable& item : items)
            written.push_back(inlineTable(item));
        entries.push_back(fmt::format("{} = [{}]", k, fmt::join(written, ", ")));
    }
    return fmt::format("{}", fmt::join(entries, ", "));
}

std::string inlineTable(const TomlTable& t) { return "{ " + inlineEntries(t) + " }"; }

// key.sub.leaf = value lines for every value under `t`, prefixed; lists as
// inline arrays (an array of tables has no dotted form).
void dottedLines(const TomlTable& t, const std::string& prefix, std::string& out)
{
    for (const auto& [k, v] : t.values)
        out += fmt::format("{}{} = {}\n", prefix, k, v);
    for (const auto& [k, sub] : t.tables)
        dottedLines(sub, prefix + k + ".", out);
    for (const auto& [k, items] : t.lists) {
        std::vector<std::string> written;
        for (const TomlTable& item : items)
            written.push_back(inlineTable(item));
        out += fmt::format("{}{} = [{}]\n", prefix, k, fmt::join(written, ", "));
    }
}

// [a.b] headers, then [[list]] items, as the docs' examples write them.
void sectionLines(const TomlTable& t, const std::string& name, std::string& out)
{
    // A header for a table with values, and for an empty leaf ([waves.wind]
    // alone means the default wind).
    if (!name.empty() && (!t.values.empty() || (t.tables.empty() && t.lists.empty())))
        out += fmt::format("\n[{}]\n", name);
    for (const auto& [k, v] : t.values)
        out += fmt::format("{} = {}\n", k, v);
    for (const auto& [k, sub] : t.tables)
        sectionLines(sub, name.empty() ? k : name + "." + k, out);
    for (const auto& [k, items] : t.lists)
        for (const TomlTable& item : items) {
            out += fmt::format("\n[[{}]]\n", name.empty() ? k : name + "." + k);
            for (const auto& [ik, iv] : item.values)
                out += fmt::format("{} = {}\n", ik, iv);
        }
}

std::string write(const TomlTable& root, Form form)
{
    std::string out;
    switch (form) {
    case Form::Sections: sectionLines(root, "", out); break;
    case Form::InlineTables:
        // Top-level values first, then each top-level table as one inline table.
        for (const auto& [k, v] : root.values)
            out += fmt::format("{} = {}\n", k, v);
        for (const auto& [k, sub] : root.tables)
            out += fmt::format("{} = {}\n", k, inlineTable(sub));
        for (const auto& [k, items] : root.lists) {
            std::vector<std::string> written;
            for (const TomlTable& item : items)
                written.push_back(inlineTable(item));
            out += fmt::format("{} = [{}]\n", k, fmt::join(written, ", "));
        }
        break;
    case Form::DottedKeys: dottedLines(root, "", out); break;
    }
    return out;
}

// The key's last part inside its table or list item.
std::string_view leafOf(const Parameter& p)
{
    std::string_view owner = p.list == ParameterList::None ? std::string_view() : listKey(p.list);
    if (p.list == ParameterList::None) {
        auto dot = p.key.rfind('.');
        return dot == std::string_view::npos ? p.key : p.key.substr(dot + 1);
    }
    return p.key.substr(owner.size() + 1);
}

std::string_view tableOf(const Parameter& p)
{
    auto dot = p.key.rfind('.');
    return dot == std::string_view::npos ? std::string_view() : p.key.substr(0, dot);
}

// Which wave source and which sun a scene takes: waves.wind (with a swell)
// and waves.list exclude each other, as do sun.direction and the sun's date
// and place, so every key needs two scenes: the wind's, with the sun's
// direction, and the listed waves', with the sun placed.
enum class Waves { Wind, Listed };

bool placesTheSun(const Parameter& p)
{
    return p.key == "sun.time" || p.key == "sun.latitude_deg" || p.key == "sun.longitude_deg";
}

// The sun's third form, by its angles: written only when one of them is the
// key changed (the wind's scene then gives its sun so, not by its direction).
bool anglesOfTheSun(const Parameter& p) { return p.key == "sun.elevation_deg" || p.key == "sun.azimuth_deg"; }

// A fisheye's coefficients are taken only with the fisheye's model
// (docs/SCENE.md, "The lens"): the scene that changes one sets camera.lens.
bool fisheyeCoefficient(const Parameter& p) { return p.key.starts_with("camera.fisheye_"); }

bool belongsToOtherSource(const Parameter& p, Waves waves)
{
    if (anglesOfTheSun(p))
        return true;
    if (waves == Waves::Wind)
        return p.list == ParameterList::Waves || placesTheSun(p);
    return p.key.starts_with("waves.wind.") || p.key.starts_with("waves.swell.") || p.key == "sun.direction";
}

// The keys that mean something only on one of the fleet's built-ins (docs/SCENE.md,
// "The fleet"): set, the object is the tug.
bool fleetKey(const Parameter& p)
{
    return p.key == "objects.length_m" || p.key == "objects.beam_m" || p.key == "objects.hull_color" ||
           p.key == "objects.superstructure_color" || p.key == "objects.superstructure";
}

// Every parameter of the table at its default, plus the keys that are not
// parameters (sky faces, an object's path, hull node and class), in one
// tree; with `changed` written as `changedValue` instead of its default.
TomlTable everyKey(Waves waves, const Parameter* changed = nullptr, const std::string& changedValue = {})
{
    TomlTable root;
    TomlTable object, wave, cameraKey, rigCamera, beach, shelf, breakwater;
    if (changed != nullptr && fleetKey(*changed)) {
        object.values.emplace_back("path", "\"builtin:tug\""); // a built-in brings its own hull
    } else {
        object.values.emplace_back("path", "\"hull.glb\"");
        object.values.emplace_back("hull_node", "\"Hull\"");
    }
    object.values.emplace_back("class", "\"tug\"");
    rigCamera.values.emplace_back("name", "\"left\"");
    for (const Parameter& p : parameters()) {
        const bool sunByAngles = changed != nullptr && anglesOfTheSun(*changed);
        if (sunByAngles && p.key == "sun.direction")
            continue;
        if (belongsToOtherSource(p, waves) && !(sunByAngles && anglesOfTheSun(p)))
            continue;
        std::string value = &p == changed ? changedValue : formatValue(p, p.defaultValue);
        if (changed != nullptr && fisheyeCoefficient(*changed) && p.key == "camera.lens")
            value = formatValue(p, std::int64_t(LensModel::KannalaBrandt));
        switch (p.list) {
        case ParameterList::None: root.table(tableOf(p)).values.emplace_back(leafOf(p), value); break;
        case ParameterList::Objects: object.values.emplace_back(leafOf(p), value); break;
        case ParameterList::Waves: wave.values.emplace_back(leafOf(p), value); break;
        case ParameterList::CameraPath: cameraKey.values.emplace_back(leafOf(p), value); break;
        case ParameterList::CameraRig: rigCamera.values.emplace_back(leafOf(p), value); break;
        case ParameterList::SeabedBeaches: beach.values.emplace_back(leafOf(p), value); break;
        case ParameterList::SeabedShelves: shelf.values.emplace_back(leafOf(p), value); break;
        case ParameterList::SeabedBreakwaters: breakwater.values.emplace_back(leafOf(p), value); break;
        }
    }
    root.table("sky").values.emplace_back(
        "faces", R"(["sky/px.png", "sky/nx.png", "sky/py.png", "sky/ny.png", "sky/pz.png", "sky/nz.png"])");
    root.lists["objects"].push_back(object);
    root.table("camera").lists["path"].push_back(cameraKey);
    root.table("camera").lists["rig"].push_back(rigCamera);
    root.table("seabed").lists["beaches"].push_back(beach);
    root.table("seabed").lists["shelves"].push_back(shelf);
    root.table("seabed").lists["breakwaters"].push_back(breakwater);
    root.table("seabed.heightmap").values.emplace_back("path", "\"floor.png\"");
    if (waves == Waves::Listed)
        root.table("waves").lists["list"].push_back(wave);
    return root;
}

} // namespace

// The tables the reader accepts are the parameter table's, every one of them.
TEST(SceneEveryKey, EveryTableOfTheParameterTableIsATable)
{
    const std::vector<std::string> tables = parameterTables(ParameterList::None);
    for (const char* t : {"waves", "waves.wind", "waves.swell", "grid", "sun", "sky", "fog", "water", "reflection",
                          "wake", "camera"})
        EXPECT_NE(std::find(tables.begin(), tables.end(), t), tables.end()) << t;
    for (const std::string& t : tables) {
        // An empty table of each: accepted (its keys take their defaults).
        std::string text = fmt::format("[{}]\n", t);
        if (t == "waves.swell")
            text = "[waves.wind]\n" + text;
        EXPECT_NO_THROW(parseScene(text, everyKeyScenePath())) << text;
    }
}

TEST(SceneEveryKey, EveryDocumentedKeyLoadsInEachForm)
{
    for (Waves waves : {Waves::Wind, Waves::Listed})
        for (Form form : {Form::Sections, Form::InlineTables, Form::DottedKeys}) {
            const std::string text = write(everyKey(waves), form);
            SCOPED_TRACE(fmt::format("{}, {}:\n{}", waves == Waves::Wind ? "wind" : "listed waves", formName(form), text));
            Scene scene;
            try {
                scene = parseScene(text, everyKeyScenePath());
            } catch (const InputError& e) {
                ADD_FAILURE() << e.what();
                continue;
            }
            // Every value written is the one read (all defaults, item 0 of each list).
            ASSERT_EQ(scene.objects.size(), 1u);
            EXPECT_EQ(scene.objects[0].hullNode, "Hull");
            EXPECT_EQ(scene.objects[0].className, "tug");
            EXPECT_EQ(scene.sky.cubemapFaces.size(), 6u);
            ASSERT_EQ(scene.camera.path.size(), 1u);
            ASSERT_EQ(scene.camera.rig.size(), 1u);
            EXPECT_EQ(scene.camera.rig[0].name, "left");
            EXPECT_EQ(scene.sea.wind.has_value(), waves == Waves::Wind);
            EXPECT_EQ(scene.sun.place.has_value(), waves == Waves::Listed);
            for (const Parameter& p : parameters()) {
                if (!belongsToOtherSource(p, waves) && isPresent(p, scene)) {
                    EXPECT_EQ(formatValue(p, p.get(scene, 0)), formatValue(p, p.defaultValue)) << p.key;
                }
            }
        }
}

namespace {

// A value of p other than its default, inside its slider span: a step of a
// thousandth of the span (or 1) down, or up from the span's bottom, small
// enough to keep the cross-field rules (a fade's end within the grid); the
// other flag; the next choice.
ParameterValue otherValue(const Parameter& p)
{
    auto nudge = [&](double x) {
        if (!std::isfinite(x)) // deep water's infinite depth: a finite one
            return p.sliderMax;
        const double step = p.kind == ParameterKind::Integer ? 1.0 : 0.001 * (p.sliderMax - p.sliderMin);
        return x - step >= p.sliderMin ? x - step : x + step;
    };
    switch (p.kind) {
    case ParameterKind::Real: return nudge(std::get<double>(p.defaultValue));
    case ParameterKind::DateTime: return std::get<double>(p.defaultValue) + 3600.0; // an hour later, whole seconds
    case ParameterKind::Integer: return static_cast<std::int64_t>(nudge(double(std::get<std::int64_t>(p.defaultValue))));
    case ParameterKind::Flag: return !std::get<bool>(p.defaultValue);
    case ParameterKind::Choice:
        return (std::get<std::int64_t>(p.defaultValue) + 1) % static_cast<std::int64_t>(p.choices.size());
    case ParameterKind::Direction2: {
        glm::dvec2 v = std::get<glm::dvec2>(p.defaultValue);
        return glm::dvec2(v.y, -v.x); // turned a quarter
    }
    case ParameterKind::Vector2: {
        glm::dvec2 v = std::get<glm::dvec2>(p.defaultValue);
        return glm::dvec2(nudge(v.x), nudge(v.y));
    }
    case ParameterKind::Colour:
    case ParameterKind::Direction3:
    case ParameterKind::Vector3: {
        glm::dvec3 v = std::get<glm::dvec3>(p.defaultValue);
        if (p.kind == ParameterKind::Direction3)
            return glm::dvec3(v.z, v.x, v.y) + glm::dvec3(0.0, 0.5, 0.0);
        return glm::dvec3(nudge(v.x), nudge(v.y), nudge(v.z));
    }
    }
    return p.defaultValue;
}

} // namespace

// Each key at a value other than its default, every other key at its
// default: read into the field its accessor names, and written back by
// saveScene() (a key read into the wrong field, or not at all, or not
// written, fails). The spectral model's keys mean something
// only in a spectral sea, so the wind's scene draws one.
TEST(SceneEveryKey, EachKeySetsItsOwnField)
{
    const Parameter* model = findParameter("waves.model");
    ASSERT_NE(model, nullptr);
    const ParameterValue spectral = std::int64_t(WaveModelKind::Spectral);
    for (const Parameter& p : parameters()) {
        ParameterValue value = &p == model ? spectral : otherValue(p);
        // A stretch of the tug's design, within the fleet's bounds.
        if (p.key == "objects.length_m")
            value = 1.25 * detail::fleetDesign("tug").length_m;
        if (p.key == "objects.beam_m")
            value = 1.25 * detail::fleetDesign("tug").beam_m;
        // A paint: a colour (its default, [-1, -1, -1], is the model's own).
        if (p.key == "objects.hull_color" || p.key == "objects.superstructure_color")
            value = glm::dvec3(0.25, 0.5, 0.75);
        EXPECT_EQ(valueProblem(p, value), "") << p.key;
        EXPECT_NE(formatValue(p, value), formatValue(p, p.defaultValue)) << p.key;
        const Waves waves = p.list == ParameterList::Waves || placesTheSun(p) ? Waves::Listed : Waves::Wind;
        TomlTable root = everyKey(waves, &p, formatValue(p, value));
        if (waves == Waves::Wind && &p != model)
            for (auto& [k, v] : root.table("waves").values)
                if (k == "model")
                    v = formatValue(*model, spectral);
        const std::string text = write(root, Form::Sections);
        try {
            const Scene scene = parseScene(text, everyKeyScenePath());
            EXPECT_TRUE(isPresent(p, scene)) << p.key;
            if (isPresent(p, scene)) {
                EXPECT_EQ(formatValue(p, p.get(scene, 0)), formatValue(p, value)) << p.key;
                // And saveScene() writes it where the reader finds it again.
                const Scene again = parseScene(saveScene(scene), everyKeyScenePath());
                EXPECT_EQ(formatValue(p, p.get(again, 0)), formatValue(p, value)) << p.key << " after saveScene";
            }
        } catch (const InputError& e) {
            ADD_FAILURE() << p.key << " = " << formatValue(p, value) << ": " << e.what();
        }
    }
}

// docs/SCENE.md's sun from an elevation e and an azimuth a:
// [sin(a) cos(e), sin(e), -cos(a) cos(e)], the direction a camera with that
// heading and pitch looks along (so the conventions of the two agree).
TEST(SceneEveryKey, TheDocsSunFormulaIsWhereACameraWithThatHeadingLooks)
{
    for (double a : {-170.0, -5.7, 0.0, 30.0, 90.0, 200.0})
        for (double e : {0.0, 4.0, 45.0, 80.0}) {
            Camera camera;
            camera.yaw_deg = a;
            camera.pitch_deg = e;
            const double ar = glm::radians(a), er = glm::radians(e);
            const glm::dvec3 documented(std::sin(ar) * std::cos(er), std::sin(er), -std::cos(ar) * std::cos(er));
            EXPECT_LT(glm::length(camera.forward() - documented), 1e-12) << a << " " << e;
        }
}

// The presets the intro of docs/SCENE.md names are those in scenes/, and its
// list of debug views is the parameter table's.
TEST(SceneEveryKey, TheDocsNameEveryPresetAndEveryDebugView)
{
    std::ifstream in(fs::path(SWELL_SOURCE_DIR) / "docs" / "SCENE.md");
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string intro = doc.substr(0, doc.find("```"));
    for (const auto& entry : fs::directory_iterator(fs::path(SWELL_SOURCE_DIR) / "scenes"))
        if (entry.path().extension() == ".toml") {
            EXPECT_NE(intro.find("`" + entry.path().stem().string() + "`"), std::string::npos)
                << "docs/SCENE.md's intro does not name the preset " << entry.path().stem();
        }
    const Parameter* debugView = findParameter("debug_view");
    ASSERT_NE(debugView, nullptr);
    const std::string topLevel = doc.substr(doc.find("### Top level"));
    const std::string prose = topLevel.substr(0, topLevel.find("\n## "));
    for (std::string_view choice : debugView->choices)
        EXPECT_NE(prose.find(fmt::format("`\"{}\"`", choice)), std::string::npos)
            << "docs/SCENE.md's Top level section does not list debug_view = \"" << choice << "\"";
}
