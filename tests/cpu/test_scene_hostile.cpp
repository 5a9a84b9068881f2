// Hostile scene files (issue #6): inputs built to make the loader allocate
// without bound, and files that cannot be read even by root. Each must end
// in an InputError at a place, found before the TOML parser builds anything
// for it. The item-by-item map of hostile inputs to tests is in
// docs/TESTING.md.
#include "swell/error.h"
#include "swell/gpu/limits.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace swell;

namespace {

std::string repeat(const std::string& s, std::size_t n)
{
    std::string out;
    out.reserve(s.size() * n);
    for (std::size_t i = 0; i < n; ++i)
        out += s;
    return out;
}

InputError parseError(const std::string& text)
{
    try {
        (void)parseScene(text, "hostile.toml");
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError({}, "");
}

} // namespace

// As many waves as 4 MiB of TOML can list, about 1.4 million, as inline
// tables: refused at the 10001st entry by the structure scan, before the
// parser makes a node for each (which took 0.5 GB and 6 s under ASan).
TEST(SceneHostile, MillionsOfInlineWavesAreRefusedBeforeParsing)
{
    const std::size_t count = (kMaxSceneFileBytes - 64) / 3;
    ASSERT_GT(count, std::size_t{1000000});
    const std::string text = "[waves]\nlist = [" + repeat("{},", count) + "]\n";
    ASSERT_LE(text.size(), kMaxSceneFileBytes);
    const InputError e = parseError(text);
    EXPECT_EQ(e.place().line, 2);
    // The comma after entry 10001 (10000 commas could end a list of 10000
    // with a trailing comma): "list = [" is 8 columns, each entry 3.
    EXPECT_EQ(e.place().column, 8 + 3 * (static_cast<int>(kMaxSceneArrayItems) + 1));
    EXPECT_NE(e.message().find("an array with more than 10000 entries"), std::string::npos) << e.message();
}

// The same as [[waves.list]] headers (15 bytes each, some 280,000 fit):
// refused at the header past every list's limit together.
TEST(SceneHostile, HundredsOfThousandsOfWaveHeadersAreRefusedBeforeParsing)
{
    const std::string text = repeat("[[waves.list]]\n", (kMaxSceneFileBytes - 64) / 15);
    const InputError e = parseError(text);
    EXPECT_EQ(e.place().line, kMaxSceneTableArrayHeaders + 1);
    EXPECT_EQ(e.place().column, 2);
    EXPECT_NE(e.message().find("more than 10320 [[...]] headers"), std::string::npos) << e.message();
}

// Just under the structural limits the reader's own, more precise limits
// speak: the scan must not be what refuses a file that is merely too long
// for one list.
TEST(SceneHostile, ListsAtTheStructuralLimitReachTheReader)
{
    const std::string inlineWaves = "[waves]\nlist = [" + repeat("{},", kMaxSceneArrayItems) + "]\n";
    const InputError e = parseError(inlineWaves);
    EXPECT_NE(e.message().find("waves.list has 10000 entries; at most 64"), std::string::npos) << e.message();

    const std::string headers = repeat("[[objects]]\npath = \"builtin:buoy\"\n", kMaxSceneObjects) +
                                repeat("[[waves.list]]\n", SWELL_MAX_WAVES) +
                                repeat("[[camera.path]]\n", kMaxCameraKeys);
    // Every header is allowed; camera keys without distinct times are what is wrong.
    const InputError h = parseError(headers);
    EXPECT_NE(h.message().find("camera.path[1].time_s"), std::string::npos) << h.message();
}

// An enormous grid is refused by its range, read as the integer it is.
TEST(SceneHostile, EnormousGridResolution)
{
    for (const char* value : {"2049", "4294967297", "9223372036854775807", "-9223372036854775808"}) {
        const InputError e = parseError(std::string("[grid]\nresolution = ") + value + "\n");
        EXPECT_EQ(e.place().line, 2) << value;
        EXPECT_EQ(e.place().column, 14) << value;
        EXPECT_NE(e.message().find("grid.resolution"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("allowed 16..2048"), std::string::npos) << e.message();
    }
    // As a float, it is the wrong type, whatever its size.
    const InputError f = parseError("[grid]\nresolution = 1e300\n");
    EXPECT_NE(f.message().find("whole number"), std::string::npos) << f.message();
}

// Zero and negative wavelengths, listed and in the wind.
TEST(SceneHostile, ZeroAndNegativeWavelengths)
{
    for (const char* value : {"0.0", "-3.0", "-inf"}) {
        const InputError e = parseError(std::string("[[waves.list]]\nwavelength_m = ") + value + "\n");
        EXPECT_EQ(e.place().line, 2) << value;
        EXPECT_EQ(e.place().column, 16) << value;
        EXPECT_NE(e.message().find("waves.list[0].wavelength_m"), std::string::npos) << e.message();
    }
    // Positive but so short that the wavenumber 2 pi / L overflows to inf.
    const InputError tiny = parseError("[[waves.list]]\nwavelength_m = 1e-320\n");
    EXPECT_NE(tiny.message().find("waves.list"), std::string::npos) << tiny.message();
    for (const char* value : {"0.0", "-1.0"}) {
        const InputError e = parseError(std::string("[waves.wind]\nmin_wavelength_m = ") + value + "\n");
        EXPECT_EQ(e.place().line, 2) << value;
        EXPECT_NE(e.message().find("waves.wind.min_wavelength_m"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("out of range"), std::string::npos) << e.message();
    }
}

// Huge and negative sizes of things in the world.
TEST(SceneHostile, HugeAndNegativeSizes)
{
    struct Case {
        const char* toml;
        const char* key;
    };
    for (const Case& c : {Case{"[grid]\nradius_m = 1e308\n", "grid.radius_m"},
                          Case{"[grid]\nradius_m = -2000.0\n", "grid.radius_m"},
                          Case{"[[objects]]\npath = \"builtin:buoy\"\nscale = 1e300\n", "objects[0].scale"},
                          Case{"[[objects]]\npath = \"builtin:buoy\"\nscale = -1.0\n", "objects[0].scale"},
                          Case{"[[objects]]\npath = \"builtin:buoy\"\nposition_m = [1e30, 0, 0]\n", "objects[0].position_m"},
                          Case{"[camera]\nfar_m = 1e300\n", "camera.far_m"},
                          Case{"[fog]\nend_m = -1.0\n", "fog.end_m"},
                          Case{"[[waves.list]]\namplitude_m = 1e6\n", "waves.list[0].amplitude_m"}}) {
        const InputError e = parseError(c.toml);
        EXPECT_GE(e.place().line, 2) << c.toml;
        EXPECT_NE(e.message().find(c.key), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("out of range"), std::string::npos) << e.message();
    }
}

// A file that open() refuses even to root: a Unix socket. (chmod 000 does not
// stop root; SceneFile.UnreadableFile covers it for other users.)
TEST(SceneHostile, SocketInsteadOfFile)
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "scene_hostile";
    fs::create_directories(folder);
    const fs::path path = folder / "socket.toml";
    fs::remove(path);
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(path.string().size(), sizeof address.sun_path) << "the build folder's path is too long for a socket";
    path.string().copy(address.sun_path, sizeof address.sun_path - 1);
    ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    try {
        (void)loadScene(path);
        ADD_FAILURE() << "a socket loaded as a scene";
    } catch (const InputError& e) {
        EXPECT_EQ(e.place().path, path.string());
        EXPECT_EQ(e.place().line, 0);
        EXPECT_NE(e.message().find("cannot read the scene file"), std::string::npos) << e.message();
    }
    ::close(fd);
    fs::remove(path);
}

// (Issue #14, class 4) A quoted key is one name, dots included: at the top
// level "fog.start_m" = 10.0 is a key named fog.start_m, not start_m in
// [fog], and must not pass for it, alone or beside the real one.
TEST(SceneHostile, QuotedDottedKeysAreUnknownKeys)
{
    struct Case {
        std::string toml;
        int line, column;
        std::string message;
    };
    for (const Case& c : {Case{"\"fog.start_m\" = 10.0\n", 1, 1, "unknown key '\"fog.start_m\"'"},
                          Case{"'fog.start_m' = 10.0\n", 1, 1, "to set fog.start_m, write the key without quotes"},
                          Case{"[fog]\nstart_m = 20.0\n[water]\n\"fog.start_m\" = 10.0\n", 4, 1,
                               "unknown key 'water.\"fog.start_m\"'"},
                          Case{"\"fog.start_m\" = 10.0\n[fog]\nstart_m = 20.0\n", 1, 1, "a quoted key is one name"},
                          Case{"[fog]\n\"start_m.x\" = 1.0\n", 2, 1, "unknown key 'fog.\"start_m.x\"'"},
                          Case{"[\"waves.wind\"]\nspeed_mps = 3.0\n", 1, 2, "unknown key '\"waves.wind\"'"}}) {
        const InputError e = parseError(c.toml);
        EXPECT_EQ(e.place().line, c.line) << c.toml;
        EXPECT_EQ(e.place().column, c.column) << c.toml;
        EXPECT_NE(e.message().find(c.message), std::string::npos) << c.toml << e.message();
    }
    // Quotes around a name without dots change nothing in TOML, and are fine.
    EXPECT_EQ(parseScene("[fog]\n\"start_m\" = 10.0\n", "quoted.toml").fog.start_m, 10.0);
}

// (Issue #14, class 5) Directions are normalised on use, in floats too, so
// a length is required (1e-12; docs/SCENE.md), and the message quotes the
// components as written, not as a rounded [0, 0, 0].
TEST(SceneHostile, TinyDirectionsAreRefusedQuotingThem)
{
    struct Case {
        std::string toml;
        std::string message;
    };
    for (const Case& c :
         {Case{"[sun]\ndirection = [1e-300, 1e-300, 0]\n", "sun.direction is [1e-300, 1e-300, 0], of length 1.4142135623730952e-300"},
          Case{"[sun]\ndirection = [0, -1e-13, 0]\n", "sun.direction is [0, -1e-13, 0], of length 1e-13; a direction must be at least 1e-12 long"},
          Case{"[[waves.list]]\ndirection = [5e-324, 0.0]\n", "waves.list[0].direction is [5e-324, 0]"},
          Case{"[sun]\ndirection = [0, 0, 0]\n", "sun.direction is [0, 0, 0]; a direction must not be zero"}}) {
        const InputError e = parseError(c.toml);
        EXPECT_EQ(e.place().line, 2) << c.toml;
        EXPECT_NE(e.message().find(c.message), std::string::npos) << c.toml << e.message();
    }
    // The shortest accepted, and a long one, are fine; both in files and in code.
    EXPECT_EQ(parseScene("[sun]\ndirection = [0, 1e-12, 0]\n", "short.toml").sun.direction.y, 1e-12);
    EXPECT_EQ(parseScene("[sun]\ndirection = [1e3, 1e3, 1e3]\n", "long.toml").sun.direction.x, 1e3);
    Scene scene;
    scene.sun.direction = {1e-200, 0.0, 0.0};
    try {
        validateScene(scene, "code.toml");
        ADD_FAILURE() << "a tiny direction built in code was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("sun.direction is [1e-200, 0, 0]"), std::string::npos) << e.message();
    }
}
