// Scene files: the parameter table, round trips, the presets in scenes/ and
// the generated table in docs/SCENE.md. The inputs a scene file must refuse
// (malformed text, unreadable files, hostile sizes, the fuzzer's corpus) and
// saving to disk are in test_scene_file_errors.cpp; what both share is in
// scene_file_fixtures.h.
#include "scene_file_fixtures.h"

#include "swell/error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>
#include "support/expect_input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace swell;
using namespace swell::test::scene_files;

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
    EXPECT_FALSE(calm.sea.wind.has_value());
    speed->set(calm, 0, 12.0);
    ASSERT_TRUE(calm.sea.wind.has_value());
    EXPECT_EQ(calm.sea.wind->windSpeed_mps, 12.0);
    EXPECT_TRUE(isPresent(*speed, calm));

    const Parameter* seed = findParameter("waves.wind.seed");
    ASSERT_NE(seed, nullptr);
    seed->set(calm, 0, std::int64_t{4294967295});
    EXPECT_EQ(calm.sea.wind->seed, 4294967295u);
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
    ASSERT_TRUE(scene.sea.wind.has_value());
    EXPECT_NEAR(scene.sea.wind->windSpeed_mps, 8.0, 2.0);
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
    EXPECT_FALSE(parsed.sea.wind.has_value());
    EXPECT_TRUE(parsed.objects.empty());
}

TEST(SceneFile, ResolveWaves)
{
    Scene scene = defaultScene();
    WaveSet generated = resolveWaves(scene);
    EXPECT_EQ(static_cast<int>(generated.waves.size()), scene.sea.wind->waveCount);
    EXPECT_EQ(validate(generated), "");

    scene.sea.depth_m = 20.0;
    EXPECT_EQ(resolveWaves(scene).depth_m, 20.0); // the scene's depth wins over the wind's own

    Scene listed;
    listed.waves.listed.push_back(Wave{{1.0, 0.0}, 12.0, 0.2, 0.5, 0.0});
    listed.sea.depth_m = 30.0;
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
    s.sea.depth_m = 17.25;
    s.waves.listed.push_back(Wave{{0.1 + 0.2, -1.0}, 33.3, 0.123456789012345, 0.7, -3.0});
    s.waves.listed.push_back(Wave{{-0.0, 1e-7}, 1e-3, 0.0, 0.0, 999.0});
    s.grid = {GridLayout::Paper, 512, 3000.5, 1000.0, 2999.0};
    s.sun = {{0.25, 0.5, -1.0}, {1.0, 0.5, 1.0 / 3.0}, 7.5};
    s.sky.cubemapFaces = {"sky/px.png", "sky/nx.png", "sky/py.png", "sky/ny.png", "sky/pz.png", "sky/nz.png"};
    s.sky.zenithColor = {0.0, 0.0, 0.0};
    s.fog = {0.0, 123456.0, {0.5, 0.25, 0.125}, FogModel::Atmosphere};
    s.water = {{0.1, 0.2, 0.3}, {99.0, 0.0, 1.5}, 0.05, 1.0, 10.0, 0.0};
    s.reflection = {ReflectionMode::FixedDistance, 1e-3, 0.1, 0.0};
    s.objects.push_back({"models/boat.glb", {1.5, -2.0, 1e5}, -3600.0, 1e4, true});
    s.objects.push_back({"builtin:rock", {0.0, 0.0, 0.0}, 45.0, 0.001, false});
    s.camera = CameraSettings{};
    s.camera.position_m = {1.0, 2.0, 3.0};
    s.camera.yaw_deg = 90.0;
    s.camera.pitch_deg = 89.0;
    s.camera.fovY_deg = 150.0;
    s.camera.near_m = 1e-4;
    s.camera.far_m = 1e7;
    s.camera.path.push_back({0.0, {0.0, 5.0, 0.0}, 0.0, 0.0});
    s.camera.path.push_back({0.5, {1.0, 5.0, -1.0}, 720.0, -89.0});
    s.debugView = DebugView::Wireframe;
    s.showTerrain = false;

    std::string text = saveScene(s);
    Scene back = parseScene(text, inlinePath());
    expectSameScene(back, s);
    EXPECT_EQ(saveScene(back), text);

    // And with the wind, which replaces the listed waves.
    s.sea.wind = WindSettings{};
    s.sea.wind->windSpeed_mps = 31.5;
    s.sea.wind->seed = 4294967295u;
    s.sea.wind->depth_m = s.sea.depth_m;
    s.waves.listed.clear();
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
                                           "gale-under-way.toml", "coast.toml", "harbour.toml", "fleet.toml"};
    for (const std::string& name : presets) {
        SCOPED_TRACE(name);
        Scene scene;
        try {
            scene = loadScene(folder / name);
        } catch (const InputError& e) {
            ADD_FAILURE() << e.what();
            continue;
        }
        EXPECT_EQ(validate(resolveWaves(scene)), "");
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
    ASSERT_EQ(s.waves.listed.size(), 1u);
    EXPECT_EQ(s.waves.listed[0].wavelength_m, 8.0); // integers are accepted for numbers
    EXPECT_EQ(s.sea.depth_m, 50.0);
    EXPECT_EQ(s.fog.end_m, 20.5);

    Scene w = parseScene("[waves]\nwind = {}\ndepth_m = 40.0\n", inlinePath());
    ASSERT_TRUE(w.sea.wind.has_value()); // an empty wind table means the default wind
    EXPECT_EQ(w.sea.wind->depth_m, 40.0);
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
    {"`[[objects]]`", "path",
     "a .gltf or .glb file, or \"builtin:\" and one of buoy, boat, rock or the fleet's sailing_yacht, rib, "
     "fishing_trawler, tug, container_ship, tanker, kayak, lateral_port_buoy, lateral_starboard_buoy, "
     "cardinal_north_buoy",
     "required", "the object's model, relative to the scene file's folder"},
    {"`[[objects]]`", "hull_node", "a node name of the glTF file", "`\"\"`",
     "the node whose mesh is the closed hull volume: kept dry, and the body's shape"},
    {"`[[objects]]`", "class",
     "a non-empty name, not one of the fixed classes (none, sky, water, whitecap_foam, wake_foam, terrain, surf, wet_sand)",
     "the model's name",
     "its class in the labels and COCO (docs/LABELS.md): \"boat\" for \"builtin:boat\", the file's name without folder "
     "or extension for a model"},
    {"`[[camera.rig]]`", "name", "1 to 32 letters, digits, '_' or '-'; each camera's own", "required",
     "the rig camera's name, in its files' names (NAME.left.png) and its JSON's rig block"},
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
