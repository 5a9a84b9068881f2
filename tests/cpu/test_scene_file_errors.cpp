// Scene files that must be refused: malformed inputs, each of which must
// throw InputError at the right file, line and column with a message that
// names the key; missing, unreadable, binary, huge and deeply nested files,
// and randomly damaged presets, none of which may crash; saving to disk,
// where a failed write keeps the old file; a scene edited in code, which
// validateScene refuses naming the key; and the fuzzer's corpus. The
// parameter table and round trips are in test_scene_file.cpp; what both
// share is in scene_file_fixtures.h.
#include "scene_file_fixtures.h"

#include "swell/error.h"
#include "swell/gpu/limits.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>
#include "support/expect_input_error.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <csignal>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace swell;
using namespace swell::test::scene_files;

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
        {"RigCameraNamedTwice",
         "[camera]\nfov_y_deg = 50.0\n[[camera.rig]]\nname = \"left\"\n[[camera.rig]]\nname = \"left\"\n", 6, 8,
         "camera.rig[1].name = \"left\": camera.rig[0].name has that name too (at "},
        {"RigCameraWithoutName", "[[camera.rig]]\nposition_m = [0.1, 0.0, 0.0]\n", 1, 1, "camera.rig[0] needs a name"},
        {"RigCameraNameNotAFileName", "[[camera.rig]]\nname = \"left/eye\"\n", 2, 8,
         "a rig camera's name is part of its files' names"},
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
    waves.waves.listed.resize(SWELL_MAX_WAVES + 1);
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
