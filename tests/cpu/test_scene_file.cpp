// Scene files: the parameter table, round trips, the presets in scenes/, the
// generated table in docs/SCENE.md, and malformed inputs, each of which must
// throw InputError at the right file, line and column with a message that
// names the key, and none of which may crash.
#include "swell/error.h"
#include "swell/parameters.h"
#include "swell/scene.h"
#include "swell/scene_file.h"
#include "swell/shader_constants.h"

#include <fmt/format.h>
#include "support/expect_input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <csignal>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace swell;

namespace {

// A folder of this test's own, with the files the inline scenes refer to.
fs::path workFolder()
{
    static const fs::path folder = [] {
        fs::path f = fs::path(SWELL_TEST_OUTPUT_DIR) / "scene_file";
        fs::create_directories(f / "models");
        fs::create_directories(f / "sky");
        fs::create_directories(f / "folder.glb");
        std::ofstream(f / "models" / "boat.glb", std::ios::binary) << "glTF";
        for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
            std::ofstream(f / "sky" / fmt::format("{}.png", face), std::ios::binary) << "png";
        return f;
    }();
    return folder;
}

// Inline scenes pretend to live here, so relative paths resolve to workFolder().
std::string inlinePath() { return (workFolder() / "inline.toml").string(); }

void writeFile(const fs::path& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
    ASSERT_TRUE(out.good()) << path;
}

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every parameter of every item, the lists' lengths and the strings.
void expectSameScene(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.waves.wind.has_value(), b.waves.wind.has_value());
    if (a.waves.wind) {
        EXPECT_EQ(a.waves.wind->depth_m, b.waves.wind->depth_m);
    }
    ASSERT_EQ(a.waves.listed.waves.size(), b.waves.listed.waves.size());
    ASSERT_EQ(a.objects.size(), b.objects.size());
    ASSERT_EQ(a.camera.path.size(), b.camera.path.size());
    EXPECT_EQ(a.sky.cubemapFaces, b.sky.cubemapFaces);
    for (std::size_t i = 0; i < a.objects.size(); ++i)
        EXPECT_EQ(a.objects[i].path, b.objects[i].path);
    for (const Parameter& p : parameters()) {
        if (!isPresent(p, a))
            continue;
        for (std::size_t i = 0; i < listSize(a, p.list); ++i)
            EXPECT_EQ(formatValue(p, p.get(a, i)), formatValue(p, p.get(b, i))) << p.key << " item " << i;
    }
}

} // namespace

// ---------------------------------------------------------------------------
// The parameter table

TEST(Parameters, TableIsConsistent)
{
    std::set<std::string_view> keys;
    for (const Parameter& p : parameters()) {
        SCOPED_TRACE(std::string(p.key));
        EXPECT_TRUE(keys.insert(p.key).second) << "duplicate key";
        EXPECT_EQ(findParameter(p.key), &p);
        EXPECT_FALSE(p.description.empty());
        EXPECT_EQ(p.unit.find(' '), std::string_view::npos);
        EXPECT_TRUE(p.get != nullptr && p.set != nullptr);
        EXPECT_LE(p.min, p.max);
        EXPECT_TRUE(std::isfinite(p.sliderMin) && std::isfinite(p.sliderMax));
        EXPECT_LT(p.sliderMin, p.sliderMax);
        EXPECT_TRUE(inRange(p, p.sliderMin) || (p.minExclusive && p.sliderMin == p.min && p.kind != ParameterKind::Real));
        EXPECT_TRUE(inRange(p, p.sliderMax));
        if (p.logarithmic) {
            EXPECT_GT(p.sliderMin, 0.0);
        }
        EXPECT_EQ(valueProblem(p, p.defaultValue), "") << "the default is out of range";
        EXPECT_EQ(p.kind == ParameterKind::Choice, !p.choices.empty());
        if (p.list != ParameterList::None) {
            EXPECT_TRUE(p.key.starts_with(std::string(listKey(p.list)) + "."));
        }
    }
    EXPECT_EQ(findParameter("fog.strat_m"), nullptr);
}

TEST(Parameters, SetThenGetRoundTrips)
{
    Scene scene;
    scene.objects.emplace_back();
    const Parameter* scale = findParameter("objects.scale");
    ASSERT_NE(scale, nullptr);
    scale->set(scene, 0, 2.5);
    EXPECT_EQ(scene.objects[0].scale, 2.5);
    EXPECT_EQ(std::get<double>(scale->get(scene, 0)), 2.5);

    const Parameter* view = findParameter("debug_view");
    ASSERT_NE(view, nullptr);
    view->set(scene, 0, std::int64_t{4});
    EXPECT_EQ(scene.debugView, DebugView::Lod);
    EXPECT_EQ(formatValue(*view, view->get(scene, 0)), "\"lod\"");

    // Setting a wind parameter switches the wind on; reading it off does not.
    const Parameter* speed = findParameter("waves.wind.speed_mps");
    ASSERT_NE(speed, nullptr);
    Scene calm;
    EXPECT_FALSE(isPresent(*speed, calm));
    EXPECT_EQ(std::get<double>(speed->get(calm, 0)), WindSettings{}.windSpeed_mps);
    EXPECT_FALSE(calm.waves.wind.has_value());
    speed->set(calm, 0, 12.0);
    ASSERT_TRUE(calm.waves.wind.has_value());
    EXPECT_EQ(calm.waves.wind->windSpeed_mps, 12.0);
    EXPECT_TRUE(isPresent(*speed, calm));

    const Parameter* seed = findParameter("waves.wind.seed");
    ASSERT_NE(seed, nullptr);
    seed->set(calm, 0, std::int64_t{4294967295});
    EXPECT_EQ(calm.waves.wind->seed, 4294967295u);
    EXPECT_THROW(seed->set(calm, 0, 1.0), std::bad_variant_access);
}

TEST(Parameters, RangeTextAndProblems)
{
    const Parameter& start = *findParameter("fog.start_m");
    EXPECT_EQ(rangeText(start), "0..1000000 m");
    EXPECT_EQ(valueProblem(start, -1.0), "fog.start_m = -1 is out of range; allowed 0..1000000 m");
    EXPECT_NE(valueProblem(start, std::nan("")).find("not a finite number"), std::string::npos);
    EXPECT_EQ(valueProblem(start, true), "fog.start_m holds the wrong type of value");

    const Parameter& depth = *findParameter("waves.depth_m");
    EXPECT_EQ(rangeText(depth), "> 0 m, inf allowed");
    EXPECT_EQ(valueProblem(depth, HUGE_VAL), "");
    EXPECT_NE(valueProblem(depth, 0.0), "");

    const Parameter& sun = *findParameter("sun.direction");
    EXPECT_NE(valueProblem(sun, glm::dvec3(0.0)).find("must not be zero"), std::string::npos);
    EXPECT_EQ(rangeText(*findParameter("reflection.mode")), "\"fixed\" or \"raymarch\"");
    EXPECT_EQ(formatValue(depth, HUGE_VAL), "inf");
    EXPECT_EQ(formatValue(start, 1200.0), "1200.0");
}

// ---------------------------------------------------------------------------
// Defaults, round trips, presets

TEST(SceneFile, DefaultsAreValid)
{
    EXPECT_NO_THROW(validateScene(Scene{}, inlinePath()));
    EXPECT_NO_THROW(validateScene(defaultScene(), inlinePath()));
    Scene scene = defaultScene();
    ASSERT_TRUE(scene.waves.wind.has_value());
    EXPECT_NEAR(scene.waves.wind->windSpeed_mps, 8.0, 2.0);
    EXPECT_TRUE(scene.showTerrain);
    EXPECT_GT(scene.camera.position_m.y, 3.0);
    EXPECT_LT(scene.camera.position_m.y, 10.0);
    // The sun is ahead (-z) and to the left (-x) of the default camera, above the horizon.
    EXPECT_LT(scene.sun.direction.z, 0.0);
    EXPECT_LT(scene.sun.direction.x, 0.0);
    EXPECT_GT(scene.sun.direction.y, 0.0);
}

TEST(SceneFile, EmptyFileIsTheDefaultStruct)
{
    Scene parsed = parseScene("", inlinePath());
    expectSameScene(parsed, Scene{});
    EXPECT_FALSE(parsed.waves.wind.has_value());
    EXPECT_TRUE(parsed.objects.empty());
}

TEST(SceneFile, ResolveWaves)
{
    Scene scene = defaultScene();
    WaveSet generated = resolveWaves(scene.waves);
    EXPECT_EQ(static_cast<int>(generated.waves.size()), scene.waves.wind->waveCount);
    EXPECT_EQ(validate(generated), "");

    scene.waves.listed.depth_m = 20.0;
    EXPECT_EQ(resolveWaves(scene.waves).depth_m, 20.0); // the scene's depth wins over the wind's own

    WaveSource listed;
    listed.listed.waves.push_back(Wave{{1.0, 0.0}, 12.0, 0.2, 0.5, 0.0});
    listed.listed.depth_m = 30.0;
    WaveSet resolved = resolveWaves(listed);
    ASSERT_EQ(resolved.waves.size(), 1u);
    EXPECT_EQ(resolved.waves[0].wavelength_m, 12.0);
    EXPECT_EQ(resolved.depth_m, 30.0);
}

TEST(SceneFile, DefaultSceneRoundTrips)
{
    Scene original = defaultScene();
    std::string text = saveScene(original);
    Scene back = parseScene(text, inlinePath());
    expectSameScene(back, original);
    EXPECT_EQ(saveScene(back), text);
}

TEST(SceneFile, EverythingRoundTrips)
{
    // Awkward numbers (0.1 + 0.2, tiny, negative zero, large) and every list.
    Scene s;
    s.waves.listed.depth_m = 17.25;
    s.waves.listed.waves.push_back(Wave{{0.1 + 0.2, -1.0}, 33.3, 0.123456789012345, 0.7, -3.0});
    s.waves.listed.waves.push_back(Wave{{-0.0, 1e-7}, 1e-3, 0.0, 0.0, 999.0});
    s.grid = {GridLayout::Paper, 512, 3000.5, 1000.0, 2999.0};
    s.sun = {{0.25, 0.5, -1.0}, {1.0, 0.5, 1.0 / 3.0}, 7.5};
    s.sky.cubemapFaces = {"sky/px.png", "sky/nx.png", "sky/py.png", "sky/ny.png", "sky/pz.png", "sky/nz.png"};
    s.sky.zenithColor = {0.0, 0.0, 0.0};
    s.fog = {0.0, 123456.0, {0.5, 0.25, 0.125}, FogModel::Atmosphere};
    s.water = {{0.1, 0.2, 0.3}, {99.0, 0.0, 1.5}, 0.05, 1.0, 10.0, 0.0};
    s.reflection = {ReflectionMode::FixedDistance, 1e-3, 0.1, 0.0};
    s.objects.push_back({"models/boat.glb", {1.5, -2.0, 1e5}, -3600.0, 1e4, true});
    s.objects.push_back({"builtin:rock", {0.0, 0.0, 0.0}, 45.0, 0.001, false});
    s.camera = {{1.0, 2.0, 3.0}, 90.0, 89.0, 150.0, 1e-4, 1e7, {}};
    s.camera.path.push_back({0.0, {0.0, 5.0, 0.0}, 0.0, 0.0});
    s.camera.path.push_back({0.5, {1.0, 5.0, -1.0}, 720.0, -89.0});
    s.debugView = DebugView::Wireframe;
    s.showTerrain = false;

    std::string text = saveScene(s);
    Scene back = parseScene(text, inlinePath());
    expectSameScene(back, s);
    EXPECT_EQ(saveScene(back), text);

    // And with the wind, which replaces the listed waves.
    s.waves.wind = WindSettings{};
    s.waves.wind->windSpeed_mps = 31.5;
    s.waves.wind->seed = 4294967295u;
    s.waves.wind->depth_m = s.waves.listed.depth_m;
    s.waves.listed.waves.clear();
    text = saveScene(s);
    back = parseScene(text, inlinePath());
    expectSameScene(back, s);
}

TEST(SceneFile, SavedFilesAreCommented)
{
    std::string text = saveScene(defaultScene());
    EXPECT_NE(text.find("start_m = 1200.0"), std::string::npos) << text;
    EXPECT_NE(text.find("# 0..1000000 m"), std::string::npos) << text;
    EXPECT_NE(text.find("[waves.wind]"), std::string::npos);
    EXPECT_NE(text.find("path = \"builtin:buoy\""), std::string::npos);
}

TEST(SceneFile, PresetsLoad)
{
    const fs::path folder = fs::path(SWELL_SOURCE_DIR) / "scenes";
    const std::vector<std::string> presets{"calm.toml", "trade-wind.toml", "storm.toml", "sunset.toml", "fog.toml",
                                           "underwater.toml", "paper.toml", "under-way.toml", "cloud-shadows.toml",
                                           "gale-under-way.toml"};
    for (const std::string& name : presets) {
        SCOPED_TRACE(name);
        Scene scene;
        try {
            scene = loadScene(folder / name);
        } catch (const InputError& e) {
            ADD_FAILURE() << e.what();
            continue;
        }
        EXPECT_EQ(validate(resolveWaves(scene.waves)), "");
        EXPECT_NE(readFile(folder / name).find("# "), std::string::npos) << "presets are commented";
        // Saving and reading back keeps a preset as it was.
        expectSameScene(parseScene(saveScene(scene), folder / name), scene);
    }
    // Every scene in the folder is a preset that is tested here.
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".toml") {
            EXPECT_NE(std::find(presets.begin(), presets.end(), entry.path().filename().string()), presets.end())
                << entry.path() << " is not tested";
        }
}

TEST(SceneFile, RelativePathsStartAtTheSceneFolder)
{
    const std::string scene = "[sky]\n"
                              "faces = [\"sky/px.png\", \"sky/nx.png\", \"sky/py.png\", \"sky/ny.png\", \"sky/pz.png\", "
                              "\"sky/nz.png\"]\n"
                              "[[objects]]\npath = \"models/boat.glb\"\n"
                              "[[objects]]\npath = \"" + (workFolder() / "models" / "boat.glb").string() + "\"\n";
    writeFile(workFolder() / "relative.toml", scene);
    Scene loaded = loadScene(workFolder() / "relative.toml");
    EXPECT_EQ(loaded.objects.size(), 2u);
    EXPECT_EQ(loaded.objects[0].path, "models/boat.glb"); // kept as written
    EXPECT_EQ(loaded.sky.cubemapFaces.size(), 6u);
    // The same text elsewhere does not find the files.
    EXPECT_THROW(parseScene(scene, "/nonexistent-folder/scene.toml"), InputError);
}

TEST(SceneFile, AnEditIsCheckedOnlyWhereItCanMatter)
{
    // A scene whose model file then disappears: an edit of the fog, as a
    // viewer's slider makes, must not look at the disk again; an edit of the
    // objects must.
    fs::create_directories(workFolder() / "edit" / "models");
    writeFile(workFolder() / "edit" / "models" / "box.glb", "not read before it is loaded");
    writeFile(workFolder() / "edit" / "scene.toml", "[[objects]]\npath = \"models/box.glb\"\n");
    const fs::path file = workFolder() / "edit" / "scene.toml";
    const Scene before = loadScene(file);
    fs::remove(workFolder() / "edit" / "models" / "box.glb");
    Scene fogged = before;
    fogged.fog.start_m += 100.0;
    EXPECT_NO_THROW(validateSceneChange(before, fogged, file)) << "a fog edit read the scene's files again";
    EXPECT_THROW(validateScene(fogged, file), InputError) << "the whole check still finds the missing file";
    Scene moved = before;
    moved.objects[0].path = "models/other.glb";
    EXPECT_THROW(validateSceneChange(before, moved, file), InputError);
    // Values are always checked.
    Scene broken = before;
    broken.fog.end_m = broken.fog.start_m - 1.0;
    EXPECT_THROW(validateSceneChange(before, broken, file), InputError);
}

TEST(SceneFile, TheSpectralModelNeedsTheWind)
{
    const InputError e = test::expectInputError([] {
        parseScene("[waves]\nmodel = \"spectral\"\n[[waves.list]]\nwavelength_m = 8.0\n", inlinePath());
    });
    EXPECT_EQ(e.place().line, 2);
    EXPECT_NE(std::string(e.what()).find("[waves.wind]"), std::string::npos) << e.what();
    EXPECT_NO_THROW(parseScene("[waves]\nmodel = \"spectral\"\n[waves.wind]\nspeed_mps = 12.0\n", inlinePath()));
}

TEST(SceneFile, InlineTablesAndArraysWork)
{
    Scene s = parseScene("waves = { depth_m = 50.0, list = [ { wavelength_m = 8, direction = [0, 1] } ] }\n"
                         "fog = { start_m = 10, end_m = 20.5 }\n",
                         inlinePath());
    ASSERT_EQ(s.waves.listed.waves.size(), 1u);
    EXPECT_EQ(s.waves.listed.waves[0].wavelength_m, 8.0); // integers are accepted for numbers
    EXPECT_EQ(s.waves.listed.depth_m, 50.0);
    EXPECT_EQ(s.fog.end_m, 20.5);

    Scene w = parseScene("[waves]\nwind = {}\ndepth_m = 40.0\n", inlinePath());
    ASSERT_TRUE(w.waves.wind.has_value()); // an empty wind table means the default wind
    EXPECT_EQ(w.waves.wind->depth_m, 40.0);
}

// ---------------------------------------------------------------------------
// docs/SCENE.md

namespace {

std::string tableHeading(const Parameter& p)
{
    if (p.list != ParameterList::None)
        return fmt::format("`[[{}]]`", listKey(p.list));
    auto dot = p.key.rfind('.');
    return dot == std::string_view::npos ? std::string("top level") : fmt::format("`[{}]`", p.key.substr(0, dot));
}

std::string_view lastPart(std::string_view key)
{
    auto dot = key.rfind('.');
    return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

// The keys that are strings, not parameters, as the reference lists them
// after the parameters (the reader's own list is src/scene/reader.cpp's).
struct StringKey {
    const char* table;
    const char* key;
    const char* range;
    const char* defaultValue;
    const char* description;
};
constexpr StringKey kStringKeys[] = {
    {"`[sky]`", "faces", "6 image paths (+x, -x, +y, -y, +z, -z), or none", "`[]`",
     "a cubemap sky instead of the procedural one"},
    {"`[[objects]]`", "path", "a .gltf or .glb file, or \"builtin:buoy\", \"builtin:boat\" or \"builtin:rock\"",
     "required", "the object's model, relative to the scene file's folder"},
    {"`[[objects]]`", "hull_node", "a node name of the glTF file", "`\"\"`",
     "the node whose mesh is the closed hull volume: kept dry, and the body's shape"},
};

// The parameter reference of docs/SCENE.md, written from the table.
std::string parameterReference()
{
    std::string out = "| Table | Key | Range | Default | Description |\n|---|---|---|---|---|\n";
    for (const Parameter& p : parameters())
        out += fmt::format("| {} | `{}` | {} | `{}` | {} |\n", tableHeading(p), lastPart(p.key), rangeText(p),
                           formatValue(p, p.defaultValue), p.description);
    for (const StringKey& k : kStringKeys)
        out += fmt::format("| {} | `{}` | {} | {} | {} |\n", k.table, k.key, k.range, k.defaultValue, k.description);
    return out;
}

} // namespace

TEST(SceneFile, DocsListEveryParameter)
{
    const std::string begin = "<!-- BEGIN PARAMETERS: written from the parameter table; "
                              "tests/cpu/test_scene_file.cpp checks it -->\n";
    const std::string end = "<!-- END PARAMETERS -->";
    const std::string doc = readFile(fs::path(SWELL_SOURCE_DIR) / "docs" / "SCENE.md");
    const std::string expected = parameterReference();
    auto b = doc.find(begin);
    auto e = doc.find(end);
    std::string actual = (b == std::string::npos || e == std::string::npos || e < b)
        ? std::string()
        : doc.substr(b + begin.size(), e - b - begin.size());
    if (actual != expected) {
        fs::path out = fs::path(SWELL_TEST_OUTPUT_DIR) / "SCENE-parameters.md";
        writeFile(out, begin + expected + end + "\n");
        ADD_FAILURE() << "docs/SCENE.md's parameter table is out of date; the current one is in " << out;
    }
    // The keys that are not parameters are described by hand.
    for (const char* key : {"faces", "path", "[[waves.list]]", "[[objects]]", "[[camera.path]]", "builtin:buoy",
                            "builtin:boat", "builtin:rock"})
        EXPECT_NE(doc.find(key), std::string::npos) << key;
}

// ---------------------------------------------------------------------------
// Malformed inputs: each throws InputError at its path, line and column.

namespace {

struct Malformed {
    const char* name;
    std::string toml;
    int line;
    int column;
    std::string message; // a part of the message, naming the key
};

// gtest names a failing case by this, not by its bytes.
void PrintTo(const Malformed& m, std::ostream* os) { *os << m.name; }

std::string repeat(const std::string& s, int n)
{
    std::string out;
    for (int i = 0; i < n; ++i)
        out += s;
    return out;
}

const std::string kSixFaces = "faces = [\"sky/px.png\", \"sky/nx.png\", \"sky/py.png\", \"sky/nope.png\", \"sky/pz.png\", "
                              "\"sky/nz.png\"]\n";

std::vector<Malformed> malformedCases()
{
    return {
        // TOML syntax, reported where the parser stopped
        {"SyntaxMissingValue", "[fog]\nstart_m = \n", 2, 11, "TOML syntax"},
        {"SyntaxUnterminatedString", "[[objects]]\npath = \"builtin:buoy\n", 2, 8, "TOML syntax: this string has no closing \""},
        {"SyntaxDuplicateKey", "[fog]\nstart_m = 1.0\nstart_m = 2.0\n", 3, 11, "start_m"},
        {"SyntaxDuplicateTable", "[fog]\nstart_m = 1.0\n[fog]\n", 3, 1, "fog"},
        {"InvalidUtf8", "[fog]\nstart_m = 1.0 # caf\xe9\n", 2, 20, "byte 0xE9 is not UTF-8"},
        {"OverlongUtf8", "terrain = true # \xc0\xaf\n", 1, 18, "byte 0xC0 is not UTF-8"},
        {"Utf16SurrogateInUtf8", "# \xed\xa0\x80\n", 1, 3, "byte 0xED is not UTF-8"},
        {"ColumnsCountCharacters", "[sky]\nfaces = [\"\u00e9\u00e9.png\", 2, 3, 4, 5, 6]\n", 2, 20,
         "sky.faces[1] must be a string (a file path), not an integer"},
        {"NulByte", std::string("terrain = true\n\0\0\0", 18), 2, 1, "NUL byte"},
        // Unknown keys, with suggestions
        {"UnknownKeyTypo", "[fog]\nstrat_m = 10.0\n", 2, 1, "unknown key 'fog.strat_m'; did you mean 'fog.start_m'?"},
        {"UnknownDottedKey", "fog.strat_m = 10.0\n", 1, 5, "unknown key 'fog.strat_m'; did you mean 'fog.start_m'?"},
        {"UnknownTable", "[wter]\nshininess = 3.0\n", 1, 2, "unknown key 'wter'; did you mean 'water'?"},
        {"UnknownKeyBeginningAnother", "[sky.clouds]\ncoverage = 0.5\n", 2, 1,
         "unknown key 'sky.clouds.coverage'; did you mean 'sky.clouds.cover'?"},
        {"UnknownTopLevel", "colour = [1, 1, 1]\n", 1, 1, "unknown key 'colour'"},
        {"KeyInTheWrongTable", "start_m = 100.0\n", 1, 1, "unknown key 'start_m'; did you mean 'fog.start_m'?"},
        {"UnknownInObject", "[[objects]]\npath = \"builtin:buoy\"\npostion_m = [0, 0, 0]\n", 3, 1,
         "unknown key 'objects[0].postion_m'; did you mean 'objects[0].position_m'?"},
        {"UnknownInSecondObject", "[[objects]]\npath = \"builtin:buoy\"\n[[objects]]\npath = \"builtin:rock\"\nsclae = 2.0\n",
         5, 1, "unknown key 'objects[1].sclae'; did you mean 'objects[1].scale'?"},
        {"UnknownInCameraPath", "[[camera.path]]\ntime_s = 0.0\nyaw_dg = 3.0\n", 3, 1,
         "unknown key 'camera.path[0].yaw_dg'; did you mean 'camera.path[0].yaw_deg'?"},
        {"UnknownInInlineWind", "[waves]\nwind = { sped_mps = 3.0 }\n", 2, 10,
         "unknown key 'waves.wind.sped_mps'; did you mean 'waves.wind.speed_mps'?"},
        {"UnknownInInlineWaveList", "[waves]\nlist = [{ wavelength_m = 10.0, amplitud_m = 1.0 }]\n", 2, 32,
         "unknown key 'waves.list[0].amplitud_m'; did you mean 'waves.list[0].amplitude_m'?"},
        {"CameraKeyOutsideThePath", "[camera]\ntime_s = 3.0\n", 2, 1, "unknown key 'camera.time_s'"},
        // Wrong types
        {"StringForNumber", "[fog]\nstart_m = \"far\"\n", 2, 11, "fog.start_m must be a number (m), not a string"},
        {"FloatForInteger", "[grid]\nresolution = 256.5\n", 2, 14, "grid.resolution must be a whole number, not a float"},
        {"IntegerForFlag", "terrain = 1\n", 1, 11, "terrain must be true or false, not an integer"},
        {"DateForNumber", "[fog]\nend_m = 1979-05-27\n", 2, 9, "fog.end_m must be a number (m), not a date"},
        {"NumberForTable", "fog = 3\n", 1, 7, "fog must be a table, not an integer"},
        {"TableForArrayOfTables", "[objects]\npath = \"builtin:buoy\"\n", 1, 1, "objects must be an array of tables"},
        {"NumberInArrayOfTables", "[waves]\nlist = [1, 2]\n", 2, 9, "waves.list[0] must be a table, not an integer"},
        {"ShortVector", "[sun]\ncolor = [1.0, 0.5]\n", 2, 9, "sun.color must have 3 components, not 2"},
        {"StringInVector", "[sun]\ncolor = [1.0, \"red\", 0.5]\n", 2, 15, "sun.color[1] must be a number, not a string"},
        {"NumberForVector", "[camera]\nposition_m = 6.0\n", 2, 14, "camera.position_m must be an array of 3 numbers"},
        {"NumberForChoice", "debug_view = 2\n", 1, 14, "debug_view must be one of \"shaded\""},
        {"NumberForPath", "[[objects]]\npath = 3\n", 2, 8, "objects[0].path must be a string"},
        // Ranges and finiteness
        {"NegativeDistance", "[fog]\nstart_m = -5.0\n", 2, 11, "fog.start_m = -5 is out of range; allowed 0..1000000 m"},
        {"NotANumber", "[fog]\nend_m = nan\n", 2, 9, "fog.end_m = nan is not a finite number"},
        {"Infinity", "[water]\nshininess = inf\n", 2, 13, "water.shininess = inf is not a finite number; allowed 1..10000"},
        {"ColourChannel", "[sun]\ncolor = [1.0, 2.0, 1.0]\n", 2, 15, "sun.color[1] = 2 is out of range; allowed each channel 0..1"},
        {"IntegerRange", "[grid]\nresolution = 100000\n", 2, 14, "grid.resolution = 100000 is out of range; allowed 16..2048"},
        {"HugeInteger", "[waves.wind]\ncount = 9223372036854775807\n", 2, 9, "waves.wind.count = 9.223372036854776e+18 is out of range"},
        {"NegativeSeed", "[waves.wind]\nseed = -1\n", 2, 8, "waves.wind.seed = -1 is out of range"},
        {"ZeroDepth", "[waves]\ndepth_m = 0.0\n", 2, 11, "waves.depth_m = 0 is out of range; allowed > 0 m"},
        {"PitchTooSteep", "[camera]\npitch_deg = 90.0\n", 2, 13, "camera.pitch_deg = 90 is out of range; allowed -89..89 deg"},
        {"WaveAmplitude", "[[waves.list]]\namplitude_m = -0.5\n", 2, 15, "waves.list[0].amplitude_m = -0.5 is out of range"},
        {"ZeroWaveDirection", "[[waves.list]]\ndirection = [0.0, 0.0]\n", 2, 13,
         "waves.list[0].direction is [0, 0]; a direction must not be zero"},
        {"ZeroSunDirection", "[sun]\ndirection = [0, 0, 0]\n", 2, 13, "sun.direction is [0, 0, 0]"},
        {"UnknownChoice", "debug_view = \"wireframes\"\n", 1, 14, "debug_view = \"wireframes\" is not a choice; allowed \"shaded\""},
        {"UnknownChoiceSuggestion", "debug_view = \"wireframes\"\n", 1, 14, "did you mean \"wireframe\"?"},
        {"UnknownReflectionMode", "[reflection]\nmode = \"mirror\"\n", 2, 8,
         "reflection.mode = \"mirror\" is not a choice; allowed \"fixed\" or \"raymarch\""},
        // Cross-field rules
        {"FogEndBeforeStart", "[fog]\nstart_m = 500.0\nend_m = 400.0\n", 3, 9,
         "fog.end_m (400 m) must be greater than fog.start_m (500 m)"},
        {"FogStartPastDefaultEnd", "[fog]\nstart_m = 7000.0\n", 2, 11, "fog.end_m (6000 m) must be greater than fog.start_m"},
        {"GridFadeReversed", "[grid]\nfade_start_m = 900.0\nfade_end_m = 850.0\n", 3, 14,
         "grid.fade_end_m (850 m) must be greater than grid.fade_start_m (900 m)"},
        {"GridFadePastRadius", "[grid]\nradius_m = 1000.0\n", 2, 12, "grid.fade_end_m (1900 m) must not exceed grid.radius_m"},
        {"CameraFarBeforeNear", "[camera]\nnear_m = 10.0\nfar_m = 5.0\n", 3, 9,
         "camera.far_m (5 m) must be greater than camera.near_m (10 m)"},
        {"CameraPathUnsorted", "[[camera.path]]\ntime_s = 5.0\n[[camera.path]]\ntime_s = 2.0\n", 4, 10,
         "camera.path[1].time_s (2 s) must be later than camera.path[0].time_s (5 s)"},
        {"CameraPathRepeatedTime", "[[camera.path]]\ntime_s = 1.0\n[[camera.path]]\ntime_s = 1.0\n", 4, 10,
         "camera.path[1].time_s"},
        {"WindAndList", "[waves.wind]\nspeed_mps = 5.0\n[[waves.list]]\nwavelength_m = 10.0\n", 3, 1,
         "waves.list and waves.wind exclude each other"},
        // Sizes
        {"TooManyWaves", repeat("[[waves.list]]\nwavelength_m = 10.0\n", SWELL_MAX_WAVES + 1), 2 * SWELL_MAX_WAVES + 1, 1,
         "waves.list has 65 entries; at most 64"},
        {"TooManyObjects", repeat("[[objects]]\npath = \"builtin:buoy\"\n", static_cast<int>(kMaxSceneObjects) + 1),
         2 * static_cast<int>(kMaxSceneObjects) + 1, 1, "objects has 257 entries; at most 256"},
        {"TooManyFaces", "[sky]\nfaces = [\"a.png\", \"b.png\"]\n", 2, 9, "sky.faces must list 6 image paths"},
        {"KeyTooDeep", "a.b.c.d.e.f.g.h.i = 1\n", 1, 16, "more than 8 dotted parts"},
        {"HeaderTooDeep", "[a.b.c.d.e.f.g.h.i.j]\n", 1, 17, "more than 8 dotted parts"},
        {"NestingTooDeep", "x = " + repeat("[", 17) + "1" + repeat("]", 17) + "\n", 1, 21, "nested more than 16 deep"},
        {"InlineNestingTooDeep", "x = " + repeat("{a = ", 17) + "1" + repeat("}", 17) + "\n", 1, 85,
         "nested more than 16 deep"},
        // Referenced files and built-ins
        {"UnknownBuiltin", "[[objects]]\npath = \"builtin:ship\"\n", 2, 8,
         "objects[0].path = \"builtin:ship\" is not a built-in object; the built-ins are \"builtin:buoy\""},
        {"MissingModel", "[[objects]]\npath = \"models/missing.glb\"\n", 2, 8, "objects[0].path: file '"},
        {"ModelIsAFolder", "[[objects]]\npath = \"folder.glb\"\n", 2, 8, "objects[0].path: '"},
        {"ModelIsAFolderMessage", "[[objects]]\npath = \"folder.glb\"\n", 2, 8, "' is a folder, not a file"},
        {"NotAModel", "[[objects]]\npath = \"models/boat.obj\"\n", 2, 8,
         "objects[0].path = \"models/boat.obj\" is not a glTF model"},
        {"ObjectWithoutPath", "[[objects]]\nscale = 2.0\n", 1, 1, "objects[0] needs a path"},
        {"EmptyPath", "[[objects]]\npath = \"\"\n", 2, 8, "objects[0].path is empty"},
        {"ControlCharacterInPath", "[[objects]]\npath = \"builtin:buoy\\u0000\"\n", 2, 8,
         "objects[0].path contains a control character"},
        {"MissingSkyFace", "[sky]\n" + kSixFaces, 2, 52, "sky.faces[3]: file '"},
        {"SkyFaceNotAString", "[sky]\nfaces = [1, 2, 3, 4, 5, 6]\n", 2, 10, "sky.faces[0] must be a string"},
    };
}

class MalformedScene : public testing::TestWithParam<Malformed> {};

} // namespace

TEST_P(MalformedScene, ThrowsInputErrorAtThePlace)
{
    const Malformed& c = GetParam();
    try {
        parseScene(c.toml, inlinePath());
        ADD_FAILURE() << "no error for:\n" << c.toml.substr(0, 400);
    } catch (const InputError& e) {
        EXPECT_EQ(e.place().path, inlinePath());
        EXPECT_EQ(e.place().line, c.line) << e.what();
        EXPECT_EQ(e.place().column, c.column) << e.what();
        EXPECT_NE(e.message().find(c.message), std::string::npos) << "message: " << e.message();
        EXPECT_EQ(std::string(e.what()), e.place().str() + ": " + e.message());
    }
}

INSTANTIATE_TEST_SUITE_P(SceneFile, MalformedScene, testing::ValuesIn(malformedCases()),
                         [](const testing::TestParamInfo<Malformed>& param) { return std::string(param.param.name); });

// ---------------------------------------------------------------------------
// Malformed files

namespace {

using test::expectInputError;

} // namespace

// A loaded scene keeps each key's place (Scene::keyPlaces), so a check made
// after loading (a scene changed in code, a sweep's sample) names the line.
TEST(SceneFile, ValidateSceneNamesTheLineOfALoadedKey)
{
    swell::Scene scene = swell::parseScene("[fog]\nstart_m = 100.0\nend_m = 2000.0\n", "places.toml");
    scene.fog.start_m = 3000.0;
    try {
        swell::validateScene(scene, "places.toml");
        FAIL() << "fog.end_m below fog.start_m was taken";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().path, "places.toml");
        EXPECT_EQ(e.place().line, 3);
    }
}

TEST(SceneFile, MissingFile)
{
    fs::path path = workFolder() / "does-not-exist.toml";
    InputError e = expectInputError([&] { loadScene(path); });
    EXPECT_EQ(e.place().path, path.string());
    EXPECT_EQ(e.place().line, 0);
    EXPECT_EQ(e.place().column, 0);
    EXPECT_NE(e.message().find("not found"), std::string::npos);
}

TEST(SceneFile, FolderInsteadOfFile)
{
    InputError e = expectInputError([&] { loadScene(workFolder()); });
    EXPECT_EQ(e.place().path, workFolder().string());
    EXPECT_EQ(e.place().line, 0);
    EXPECT_NE(e.message().find("folder"), std::string::npos);
}

TEST(SceneFile, UnreadableFile)
{
    // A regular file that open() refuses to read. For other users, one with
    // no permissions; root is not stopped by those, but the kernel's
    // write-only settings under /proc/sys refuse reading even to root.
    fs::path path = workFolder() / "unreadable.toml";
    const bool root = ::geteuid() == 0;
    if (root) {
        fs::remove(path);
        ASSERT_TRUE(fs::is_regular_file("/proc/sys/vm/drop_caches")) << "no write-only file to read";
        fs::create_symlink("/proc/sys/vm/drop_caches", path);
    } else {
        writeFile(path, "terrain = true\n");
        fs::permissions(path, fs::perms::none);
    }
    InputError e = expectInputError([&] { loadScene(path); });
    if (root)
        fs::remove(path);
    else
        fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(e.place().path, path.string());
    EXPECT_NE(e.message().find("cannot read"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("Permission denied"), std::string::npos) << e.message();
}

TEST(SceneFile, BinaryGarbage)
{
    // A PNG-like header, then bytes from a fixed seed: never valid TOML.
    std::string bytes = "\x89PNG\r\n\x1a\n";
    std::mt19937 rng(42);
    for (int i = 0; i < 4096; ++i)
        bytes += static_cast<char>(rng() & 0xFF);
    fs::path path = workFolder() / "garbage.toml";
    writeFile(path, bytes);
    InputError e = expectInputError([&] { loadScene(path); });
    EXPECT_EQ(e.place().path, path.string());
    // The 0x89 that opens a PNG is not UTF-8: the first byte is reported.
    EXPECT_EQ(e.place().line, 1);
    EXPECT_EQ(e.place().column, 1);
    EXPECT_NE(e.message().find("byte 0x89 is not UTF-8"), std::string::npos) << e.message();

    // All zeros: the NUL check names it.
    fs::path zeros = workFolder() / "zeros.toml";
    writeFile(zeros, std::string(1000, '\0'));
    InputError z = expectInputError([&] { loadScene(zeros); });
    EXPECT_EQ(z.place().line, 1);
    EXPECT_EQ(z.place().column, 1);
    EXPECT_NE(z.message().find("NUL byte"), std::string::npos);
}

TEST(SceneFile, HugeFileIsRefusedBeforeParsing)
{
    // Valid TOML, just too much of it: a comment line repeated past 4 MiB.
    fs::path path = workFolder() / "huge.toml";
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        const std::string line = "# " + std::string(1000, 'x') + "\n";
        for (std::size_t written = 0; written <= kMaxSceneFileBytes; written += line.size())
            out << line;
    }
    InputError e = expectInputError([&] { loadScene(path); });
    EXPECT_EQ(e.place().path, path.string());
    EXPECT_EQ(e.place().line, 0);
    EXPECT_EQ(e.place().column, 0);
    EXPECT_NE(e.message().find("at most"), std::string::npos) << e.message();
    fs::remove(path);

    // The same limit holds for text handed over in memory.
    std::string text(kMaxSceneFileBytes + 1, ' ');
    InputError m = expectInputError([&] { parseScene(text, "memory.toml"); });
    EXPECT_EQ(m.place().path, "memory.toml");
    EXPECT_NE(m.message().find("4 MiB"), std::string::npos);
}

TEST(SceneFile, DeepStructuresDoNotCrash)
{
    // A million dotted parts in one key, or one header: the parser would
    // recurse once per part; the structure scan stops it first.
    std::string key = "a";
    for (int i = 0; i < 1000000; ++i)
        key += ".a";
    for (const std::string& text : {key + " = 1\n", "[" + key + "]\n", "[[" + key + "]]\n"}) {
        InputError e = expectInputError([&] { parseScene(text, "deep.toml"); });
        EXPECT_EQ(e.place().line, 1);
        EXPECT_NE(e.message().find("dotted parts"), std::string::npos);
    }
    // A million nested arrays and inline tables.
    for (const std::string& open : {std::string("["), std::string("{a="), std::string("[{a=")}) {
        std::string text = "x = " + repeat(open, 100000);
        InputError e = expectInputError([&] { parseScene(text, "deep.toml"); });
        EXPECT_NE(e.message().find("nested"), std::string::npos) << e.message();
    }
    // A long array is fine for the parser, and then over the limit for the scene.
    std::string many;
    for (std::size_t i = 0; i <= kMaxCameraKeys; ++i)
        many += fmt::format("[[camera.path]]\ntime_s = {}.0\n", i);
    InputError e = expectInputError([&] { parseScene(many, "long.toml"); });
    EXPECT_NE(e.message().find("camera.path has 10001 entries"), std::string::npos) << e.message();
    EXPECT_EQ(e.place().line, 2 * static_cast<int>(kMaxCameraKeys) + 1);
}

TEST(SceneFile, MutatedPresetsNeverCrash)
{
    // Random damage to the presets: every outcome is a scene or an InputError
    // with a place in the file; nothing else escapes and nothing crashes.
    const fs::path folder = fs::path(SWELL_SOURCE_DIR) / "scenes";
    std::vector<std::string> sources;
    for (const char* name : {"calm.toml", "storm.toml", "sunset.toml"})
        sources.push_back(readFile(folder / name));
    const std::string alphabet = "[]{}=.,\"'#\n 0-9ae_\x01\x80\xff";
    std::mt19937 rng(1234);
    int errors = 0;
    for (int round = 0; round < 1500; ++round) {
        std::string text = sources[rng() % sources.size()];
        int edits = 1 + static_cast<int>(rng() % 4);
        for (int k = 0; k < edits && !text.empty(); ++k) {
            std::size_t at = rng() % text.size();
            char c = alphabet[rng() % alphabet.size()];
            switch (rng() % 4) {
            case 0: text[at] = c; break;
            case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c); break;
            case 2: text.erase(at, 1 + rng() % 8); break;
            case 3: text.resize(at); break;
            }
        }
        try {
            parseScene(text, folder / "mutated.toml");
        } catch (const InputError& e) {
            ++errors;
            EXPECT_EQ(e.place().path, (folder / "mutated.toml").string());
            EXPECT_FALSE(e.message().empty());
        } catch (const std::exception& e) {
            ADD_FAILURE() << "unexpected " << e.what() << " for:\n" << text;
        }
    }
    EXPECT_GT(errors, 100); // the damage really was damage
}

// ---------------------------------------------------------------------------
// Saving to disk

TEST(SceneFile, SaveFileWritesAndReplaces)
{
    fs::path folder = workFolder() / "save";
    fs::remove_all(folder);
    fs::create_directories(folder);
    fs::path path = folder / "scene.toml";

    writeFile(path, "# the user's old scene\n");
    ::chmod(path.c_str(), 0640);
    Scene scene = defaultScene();
    scene.fog.start_m = 321.0;
    saveSceneFile(scene, path);
    expectSameScene(loadScene(path), scene);

    // Replaced in place: permissions kept, and no temporary files left behind.
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    int files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++files;
    EXPECT_EQ(files, 1);
}

TEST(SceneFile, FailedSaveKeepsTheOldFile)
{
    // Nowhere to write: the error names the path.
    fs::path nowhere = workFolder() / "no-such-folder" / "scene.toml";
    InputError e = expectInputError([&] { saveSceneFile(defaultScene(), nowhere); });
    EXPECT_EQ(e.place().path, nowhere.string());
    EXPECT_NE(e.message().find("cannot save"), std::string::npos);
    EXPECT_FALSE(fs::exists(nowhere));

    // A write that fails halfway (the file size limit stands in for a full
    // disk, and stops root too): the old file stays, and no temporary is left.
    fs::path folder = workFolder() / "full";
    fs::remove_all(folder);
    fs::create_directories(folder);
    fs::path path = folder / "scene.toml";
    writeFile(path, "# precious\n");
    struct rlimit old {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    struct rlimit small = old;
    small.rlim_cur = 64; // bytes; a saved scene is a few KiB
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // get EFBIG instead of the signal
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    bool threw = false;
    try {
        saveSceneFile(defaultScene(), path);
    } catch (const InputError& error) {
        threw = true;
        EXPECT_EQ(error.place().path, path.string());
    }
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_TRUE(threw);
    EXPECT_EQ(readFile(path), "# precious\n");
    int files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++files;
    EXPECT_EQ(files, 1);
}

TEST(SceneFile, ValidateSceneNamesTheKey)
{
    Scene scene = defaultScene();
    scene.objects[1].scale = -1.0;
    InputError e = expectInputError([&] { validateScene(scene, "edited.toml"); });
    EXPECT_EQ(e.place().path, "edited.toml");
    EXPECT_EQ(e.place().line, 0);
    EXPECT_NE(e.message().find("objects[1].scale = -1 is out of range"), std::string::npos) << e.message();

    Scene waves;
    waves.waves.listed.waves.resize(SWELL_MAX_WAVES + 1);
    InputError w = expectInputError([&] { validateScene(waves, "edited.toml"); });
    EXPECT_NE(w.message().find("waves.list has 65 waves"), std::string::npos) << w.message();
}

// ---------------------------------------------------------------------------
// The fuzzer's corpus (fuzz/corpus/scene, docs/FUZZING.md): valid_* files
// load, invalid_* files throw InputError, and crash-* files, inputs that
// once crashed the parser or broke its promises, do either but nothing else,
// and a scene that loads saves to a file that loads again. The texts are
// parsed as if they lay in a folder that holds model.gltf and model.glb, as
// the fuzz target's does.

TEST(SceneFile, FuzzCorpus)
{
    const fs::path corpus = fs::path(SWELL_SOURCE_DIR) / "fuzz" / "corpus" / "scene";
    const fs::path folder = workFolder() / "fuzz";
    fs::create_directories(folder);
    std::ofstream(folder / "model.gltf");
    std::ofstream(folder / "model.glb");
    int valid = 0, invalid = 0;
    for (const auto& entry : fs::directory_iterator(corpus)) {
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        const fs::path path = folder / name;
        try {
            const Scene scene = parseScene(readFile(entry.path()), path);
            EXPECT_FALSE(name.starts_with("invalid_")) << "loaded without error";
            valid += name.starts_with("valid_");
            EXPECT_NO_THROW(validateScene(scene, path));
            EXPECT_NO_THROW(parseScene(saveScene(scene), path));
        } catch (const InputError& e) {
            EXPECT_FALSE(name.starts_with("valid_")) << e.what();
            invalid += name.starts_with("invalid_");
            EXPECT_EQ(e.place().path, path.string()) << e.what();
        }
    }
    EXPECT_GE(valid, 10);
    EXPECT_GE(invalid, 15);
}
