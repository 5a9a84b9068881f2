// The sea floor (swell/scene/seabed.h, docs/SCENE.md [seabed]): each shape's
// height against its formula at chosen points (a slope of the wrong sign,
// an azimuth measured from another axis, go red), the shapes combined by
// the highest, the island equal to its drawn mesh's vertices, the heightmap
// read through the image loader, the drawn mesh's vertices on
// elevation_m(), and the refusals.
#include "assets/island_terrain.h"
#include "support/numbers.h"
#include "assets/mesh_data.h"
#include "assets/seabed_mesh.h"
#include "swell/error.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cstdint>
#include <cstdlib>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

// stb_image_write's deflate, compiled into the library with the image loader.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

namespace fs = std::filesystem;
using namespace swell;

namespace {

using swell::test::kInf;

// A scene with nothing but its sea floor: no island.
Scene floorScene(double depth_m = kInf)
{
    Scene scene;
    scene.showTerrain = false;
    scene.sea.depth_m = depth_m;
    return scene;
}

fs::path outputFolder()
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "seabed";
    fs::create_directories(folder);
    return folder;
}

// An 8-bit grey PNG of the given pixels, row 0 first.
fs::path writeGrey(const std::string& name, int width, int height, const std::vector<unsigned char>& pixels)
{
    const fs::path file = outputFolder() / name;
    EXPECT_NE(stbi_write_png(file.c_str(), width, height, 1, pixels.data(), width), 0);
    return file;
}

// A 16-bit grey PNG of the given values, row 0 first, written by hand
// (stb writes 8 bits only): its chunks, their CRC-32s and stb's deflate.
fs::path writeGrey16(const std::string& name, int width, int height, const std::vector<std::uint16_t>& values)
{
    const auto bigEndian = [](std::string& out, std::uint32_t x) {
        for (int shift = 24; shift >= 0; shift -= 8)
            out += char((x >> shift) & 0xffu);
    };
    const auto chunk = [&](std::string& out, const std::string& type, const std::string& data) {
        bigEndian(out, std::uint32_t(data.size()));
        std::uint32_t crc = 0xffffffffu;
        for (unsigned char c : type + data) {
            crc ^= c;
            for (int k = 0; k < 8; ++k)
                crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        out += type + data;
        bigEndian(out, crc ^ 0xffffffffu);
    };
    std::string rows;
    for (int y = 0; y < height; ++y) {
        rows += '\0'; // no filter
        for (int x = 0; x < width; ++x) {
            const std::uint16_t v = values[std::size_t(y * width + x)];
            rows += char(v >> 8);
            rows += char(v & 0xff);
        }
    }
    int packedSize = 0;
    unsigned char* packed = stbi_zlib_compress(reinterpret_cast<unsigned char*>(rows.data()), int(rows.size()), &packedSize, 8);
    std::string header, png = "\x89PNG\r\n\x1a\n";
    bigEndian(header, std::uint32_t(width));
    bigEndian(header, std::uint32_t(height));
    header += std::string("\x10\0\0\0\0", 5); // 16 bits, grey, deflate, no filter method, no interlace
    chunk(png, "IHDR", header);
    chunk(png, "IDAT", std::string(reinterpret_cast<const char*>(packed), std::size_t(packedSize)));
    chunk(png, "IEND", "");
    std::free(packed);
    const fs::path file = outputFolder() / name;
    std::ofstream(file, std::ios::binary) << png;
    return file;
}

// What the refusal says, or "" when there is none.
template <class Make>
std::string refusal(Make make)
{
    try {
        make();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

// docs/SCENE.md: azimuths like a heading, from -z (north) towards +x (east).
TEST(Seabed, AzimuthsAreHeadings)
{
    EXPECT_NEAR(azimuthDirection(0.0).x, 0.0, 1e-12);
    EXPECT_NEAR(azimuthDirection(0.0).y, -1.0, 1e-12); // north: -z
    EXPECT_NEAR(azimuthDirection(90.0).x, 1.0, 1e-12); // east: +x
    EXPECT_NEAR(azimuthDirection(90.0).y, 0.0, 1e-12);
}

// A 1:50 beach facing east from (100, 200): -slope * u seaward, the top
// and the flat land behind it, nothing past its ends or its toe.
TEST(Seabed, PlaneBeachFollowsItsSlope)
{
    Scene scene = floorScene();
    scene.seabed.toeDepth_m = 20.0;
    scene.seabed.beaches.push_back(SeabedBeach{.shorePoint_m = {100.0, 200.0}, .seawardAzimuth_deg = 90.0,
                                               .slope = 0.02, .length_m = 1000.0, .top_m = 3.0, .landWidth_m = 50.0});
    const Seabed seabed(scene);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({100.0, 200.0}), 0.0);     // the shoreline
    EXPECT_NEAR(seabed.elevation_m({600.0, 200.0}), -10.0, 1e-9);   // 500 m seaward
    EXPECT_NEAR(seabed.elevation_m({600.0, 650.0}), -10.0, 1e-9);   // along the shore, inside its length
    EXPECT_NEAR(seabed.elevation_m({0.0, 200.0}), 2.0, 1e-9);       // 100 m landward
    EXPECT_NEAR(seabed.elevation_m({-70.0, 200.0}), 3.0, 1e-9);     // on the flat land behind the top
    EXPECT_NEAR(seabed.elevation_m({1099.0, 200.0}), -19.98, 1e-9); // just before the toe (1000 m out)
    EXPECT_EQ(seabed.elevation_m({1101.0, 200.0}), -kInf);          // past the toe: deep water
    EXPECT_EQ(seabed.elevation_m({600.0, 800.0}), -kInf);           // past the beach's end
    EXPECT_EQ(seabed.elevation_m({-120.0, 200.0}), -kInf);          // behind its land
    EXPECT_DOUBLE_EQ(seabed.toeDepth_m(), 20.0);
}

// The same beach facing north: seaward is -z.
TEST(Seabed, BeachFacingNorthFallsTowardsMinusZ)
{
    Scene scene = floorScene();
    scene.seabed.beaches.push_back(SeabedBeach{.shorePoint_m = {0.0, 0.0}, .seawardAzimuth_deg = 0.0, .slope = 0.05});
    const Seabed seabed(scene);
    EXPECT_NEAR(seabed.elevation_m({0.0, -100.0}), -5.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({0.0, 40.0}), 2.0, 1e-9);
}

// A sea of finite depth: the beach ends where it reaches the sea's floor,
// and the floor beyond is the sea's depth.
TEST(Seabed, FiniteSeaEndsTheSlopeAtItsDepth)
{
    Scene scene = floorScene(12.0);
    scene.seabed.beaches.push_back(SeabedBeach{.seawardAzimuth_deg = 180.0, .slope = 0.02});
    const Seabed seabed(scene);
    EXPECT_DOUBLE_EQ(seabed.toeDepth_m(), 12.0);
    EXPECT_NEAR(seabed.elevation_m({0.0, 300.0}), -6.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({0.0, 600.0}), -12.0, 1e-9);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({0.0, 5000.0}), -12.0);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({9000.0, 0.0}), -12.0);
}

// A shelf 10 m deep facing south (+z): flat landward of its edge, falling
// at its slope seaward to the toe.
TEST(Seabed, ShelfIsFlatThenFallsAtItsEdge)
{
    Scene scene = floorScene(50.0);
    scene.seabed.shelves.push_back(SeabedShelf{.edgePoint_m = {0.0, 0.0}, .seawardAzimuth_deg = 180.0, .depth_m = 10.0,
                                               .slope = 0.05, .width_m = 500.0, .length_m = 1000.0});
    const Seabed seabed(scene);
    EXPECT_NEAR(seabed.elevation_m({0.0, -100.0}), -10.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({200.0, -499.0}), -10.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({0.0, 200.0}), -20.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({0.0, 700.0}), -45.0, 1e-9);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({0.0, 900.0}), -50.0); // past the toe: the sea's floor
    EXPECT_DOUBLE_EQ(seabed.elevation_m({0.0, -600.0}), -50.0); // behind its flat top
}

// A breakwater along +x: its crest, its sides at their slope, its round
// head, and the floor beside it.
TEST(Seabed, BreakwaterIsATrapezoidWithRoundHeads)
{
    Scene scene = floorScene(20.0);
    scene.seabed.breakwaters.push_back(SeabedBreakwater{.start_m = {0.0, 0.0}, .end_m = {100.0, 0.0}, .crest_m = 3.0,
                                                        .crestWidth_m = 6.0, .sideSlope = 0.5});
    const Seabed seabed(scene);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({50.0, 0.0}), 3.0);
    EXPECT_DOUBLE_EQ(seabed.elevation_m({50.0, -3.0}), 3.0);
    EXPECT_NEAR(seabed.elevation_m({50.0, 7.0}), 1.0, 1e-12);   // 4 m down the side
    EXPECT_NEAR(seabed.elevation_m({110.0, 0.0}), -0.5, 1e-12); // 10 m off its head
    EXPECT_NEAR(seabed.elevation_m({-6.0, 8.0}), -0.5, 1e-12);  // round the other head
    EXPECT_DOUBLE_EQ(seabed.elevation_m({50.0, 100.0}), -20.0);
}

// Shapes that overlap: the floor is the highest of them.
TEST(Seabed, TheHighestShapeIsTheFloor)
{
    Scene scene = floorScene();
    scene.seabed.beaches.push_back(SeabedBeach{.seawardAzimuth_deg = 180.0, .slope = 0.02});
    scene.seabed.shelves.push_back(SeabedShelf{.edgePoint_m = {0.0, 500.0}, .seawardAzimuth_deg = 180.0, .depth_m = 6.0});
    scene.seabed.breakwaters.push_back(SeabedBreakwater{.start_m = {0.0, 200.0}, .end_m = {0.0, 260.0}});
    const Seabed seabed(scene);
    EXPECT_NEAR(seabed.elevation_m({0.0, 100.0}), -2.0, 1e-9); // the beach above the shelf's -6
    EXPECT_NEAR(seabed.elevation_m({0.0, 400.0}), -6.0, 1e-9); // the shelf above the beach's -8
    EXPECT_NEAR(seabed.elevation_m({0.0, 230.0}), 3.0, 1e-9);  // the breakwater's crest
    const std::optional<SeabedExtent> extent = seabed.extent();
    ASSERT_TRUE(extent.has_value());
    EXPECT_LE(extent->min_m.y, -150.0 - 50.0); // the beach's land
    EXPECT_GE(extent->max_m.y, 500.0 + (100.0 - 6.0) / 0.05); // the shelf's toe
}

TEST(Seabed, FlatWithoutShapesOrIsland)
{
    const Seabed seabed(floorScene(30.0));
    EXPECT_FALSE(seabed.extent().has_value());
    EXPECT_DOUBLE_EQ(seabed.elevation_m({0.0, 0.0}), -30.0);
    EXPECT_EQ(Seabed().elevation_m({5.0, 5.0}), -kInf);
}

// One height function for the island's mesh and the sea floor: at every
// vertex of the mesh, the seabed is the vertex's height.
TEST(Seabed, IslandEqualsItsMeshVertices)
{
    Scene scene;
    scene.showTerrain = true;
    const Seabed seabed(scene);
    constexpr int kResolution = 48;
    const detail::MeshData mesh = detail::makeIsland(detail::kIslandSize_m, detail::kIslandPeak_m, kResolution);
    ASSERT_EQ(mesh.vertices.size(), std::size_t(kResolution + 1) * std::size_t(kResolution + 1));
    const glm::dvec2 centre(detail::kIslandPosition_m.x, detail::kIslandPosition_m.z);
    double worst = 0.0;
    for (const detail::MeshVertex& v : mesh.vertices) {
        const double h = seabed.elevation_m(centre + glm::dvec2(v.position.x, v.position.z));
        worst = std::max(worst, std::abs(h - double(v.position.y)));
    }
    // float vertices of heights up to 70 m: 1e-5 m steps.
    EXPECT_LT(worst, 1e-4);
    const std::optional<SeabedExtent> extent = seabed.extent();
    ASSERT_TRUE(extent.has_value());
    EXPECT_DOUBLE_EQ(extent->max_m.x - extent->min_m.x, detail::kIslandSize_m);
}

// The heightmap: black and white at their heights, row 0 the north edge,
// bilinear between pixels, nothing outside its rectangle.
TEST(Seabed, HeightmapMapsGreyToHeights)
{
    // 3 x 2: row 0 (north) black, grey, white; row 1 white, white, white.
    const fs::path file = writeGrey("map.png", 3, 2, {0, 51, 255, 255, 255, 255});
    Scene scene = floorScene();
    scene.seabed.heightmap = SeabedHeightmap{.path = file.string(), .center_m = {1000.0, 0.0}, .size_m = {200.0, 100.0},
                                             .blackHeight_m = -20.0, .whiteHeight_m = 10.0};
    const Seabed seabed(scene);
    EXPECT_NEAR(seabed.elevation_m({900.0, -50.0}), -20.0, 1e-5); // north-west corner: black
    EXPECT_NEAR(seabed.elevation_m({1100.0, -50.0}), 10.0, 1e-5); // north-east: white
    EXPECT_NEAR(seabed.elevation_m({900.0, 50.0}), 10.0, 1e-5);   // south-west: white
    EXPECT_NEAR(seabed.elevation_m({1000.0, -50.0}), -14.0, 1e-5); // grey 51 = 0.2
    EXPECT_NEAR(seabed.elevation_m({950.0, 0.0}), 0.5 * (-17.0 + 10.0), 1e-5); // bilinear
    EXPECT_EQ(seabed.elevation_m({1101.0, 0.0}), -kInf);
}

// A 16-bit heightmap keeps its 65536 levels: 0x1234 is not an 8-bit grey.
TEST(Seabed, SixteenBitHeightmapsKeepTheirLevels)
{
    const fs::path file = writeGrey16("map16.png", 2, 2, {0x0000, 0x1234, 0xffff, 0x8000});
    Scene scene = floorScene();
    scene.seabed.heightmap = SeabedHeightmap{.path = file.string(), .center_m = {0.0, 0.0}, .size_m = {10.0, 10.0},
                                             .blackHeight_m = 0.0, .whiteHeight_m = 6.5535};
    const Seabed seabed(scene); // 0.1 mm a level: 0x1234 would read 0x1212 through 8 bits, 0.34 mm lower
    EXPECT_NEAR(seabed.elevation_m({-5.0, -5.0}), 0.0, 1e-6);
    EXPECT_NEAR(seabed.elevation_m({5.0, -5.0}), 0x1234 * 1e-4, 1e-6);
    EXPECT_NEAR(seabed.elevation_m({-5.0, 5.0}), 6.5535, 1e-6);
    EXPECT_NEAR(seabed.elevation_m({5.0, 5.0}), 0x8000 * 1e-4, 1e-6);
}

// The drawn seabed takes its vertices from the same functions: every
// vertex lies on elevation_m() or on a wall's foot at the toe. Each is
// sampled 1 mm towards the middle: a vertex on the shape's very edge may
// round to just outside it.
TEST(Seabed, MeshVerticesLieOnTheFloor)
{
    Scene scene = floorScene();
    scene.seabed.toeDepth_m = 15.0;
    scene.seabed.beaches.push_back(SeabedBeach{.shorePoint_m = {30.0, -40.0}, .seawardAzimuth_deg = 225.0, .slope = 0.03});
    const Seabed seabed(scene);
    const detail::SeabedMesh drawn = detail::makeSeabedMesh(seabed);
    ASSERT_FALSE(drawn.mesh.indices.empty());
    const glm::dvec2 middle = 0.5 * (seabed.extent()->min_m + seabed.extent()->max_m);
    int onFloor = 0;
    for (const detail::MeshVertex& v : drawn.mesh.vertices) {
        const glm::dvec2 at = drawn.origin_m + glm::dvec2(v.position.x, v.position.z);
        const double h = seabed.elevation_m(at + 1e-3 * glm::normalize(middle - at));
        const bool atFloor = std::abs(double(v.position.y) - h) < 1e-3;
        const bool atToe = std::abs(double(v.position.y) + 15.0) < 1e-3;
        EXPECT_TRUE(atFloor || atToe) << v.position.x << ", " << v.position.y << ", " << v.position.z << ": floor " << h;
        onFloor += atFloor ? 1 : 0;
    }
    EXPECT_GT(onFloor, int(drawn.mesh.vertices.size()) / 2);
    // The sheet's triangles face up.
    int up = 0;
    for (const detail::MeshVertex& v : drawn.mesh.vertices)
        up += v.normal.y > 0.5f ? 1 : 0;
    EXPECT_GT(up, int(drawn.mesh.vertices.size()) / 3);
}

TEST(Seabed, RefusesBadSettingsNamingTheKey)
{
    Scene scene = floorScene();
    scene.seabed.beaches.push_back(SeabedBeach{.slope = 0.0});
    EXPECT_NE(refusal([&] { Seabed s(scene); }).find("seabed.beaches[0].slope"), std::string::npos);
    scene.seabed.beaches[0].slope = -0.02;
    EXPECT_NE(refusal([&] { Seabed s(scene); }).find("seabed.beaches[0].slope"), std::string::npos);

    Scene pier = floorScene();
    pier.seabed.breakwaters.push_back(SeabedBreakwater{.start_m = {5.0, 5.0}, .end_m = {5.0, 5.0}});
    EXPECT_NE(refusal([&] { Seabed s(pier); }).find("seabed.breakwaters[0] has no length"), std::string::npos);

    Scene map = floorScene();
    map.seabed.heightmap.blackHeight_m = std::numeric_limits<double>::quiet_NaN();
    map.seabed.heightmap.path = writeGrey("nan.png", 2, 2, {0, 0, 0, 0}).string();
    EXPECT_NE(refusal([&] { Seabed s(map); }).find("seabed.heightmap.black_height_m"), std::string::npos);
}

TEST(Seabed, RefusesHeightmapsThatAreNotGreyImages)
{
    const fs::path folder = outputFolder();
    std::ofstream(folder / "empty.png", std::ios::binary).flush();
    std::ofstream(folder / "text.png", std::ios::binary) << "not an image";
    const unsigned char rgb[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9};
    stbi_write_png((folder / "colour.png").c_str(), 2, 2, 3, rgb, 6);
    const unsigned char one = 7;
    stbi_write_png((folder / "one.png").c_str(), 1, 1, 1, &one, 1);
    // Past the image loader's 4096 pixels a side (swell/image.h), refused from its header.
    const std::vector<unsigned char> wide(std::size_t(4097) * 2, 0);
    stbi_write_png((folder / "huge.png").c_str(), 4097, 2, 1, wide.data(), 4097);
    for (const char* name : {"missing.png", "empty.png", "text.png", "colour.png", "one.png", "huge.png"}) {
        Scene scene = floorScene();
        scene.seabed.heightmap.path = name;
        scene.assetFolder = folder.string();
        scene.keyPlaces["seabed.heightmap.path"] = SourcePlace{"scene.toml", 7, 8};
        const std::string message = refusal([&] { Seabed s(scene); });
        EXPECT_TRUE(message.starts_with("scene.toml:7:8: seabed.heightmap.path: ")) << name << ": " << message;
        EXPECT_NE(message.find(name), std::string::npos) << message;
    }
}

// A host's heights: checked, then joined (world y, made relative to the sea's level).
TEST(Seabed, HostHeightsJoinTheFloor)
{
    SeabedHeights host{.columns = 2, .rows = 2, .heights_m = {104.0, 104.0, 96.0, 96.0}, .min_m = {0.0, 0.0},
                       .max_m = {10.0, 10.0}};
    Scene scene = floorScene();
    scene.sea.level_m = 100.0;
    const Seabed seabed(scene, &host);
    EXPECT_NEAR(seabed.elevation_m({5.0, 0.0}), 4.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({5.0, 5.0}), 0.0, 1e-9);
    EXPECT_NEAR(seabed.elevation_m({5.0, 10.0}), -4.0, 1e-9);

    SeabedHeights wrong = host;
    wrong.heights_m.pop_back();
    EXPECT_NE(refusal([&] { checkSeabedHeights(wrong, "setSeabedHeights()"); }).find("need 4 values"), std::string::npos);
    SeabedHeights nan = host;
    nan.heights_m[2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(refusal([&] { checkSeabedHeights(nan, "setSeabedHeights()"); }).find("height 2"), std::string::npos);
    SeabedHeights flat = host;
    flat.max_m.x = flat.min_m.x;
    EXPECT_NE(refusal([&] { checkSeabedHeights(flat, "setSeabedHeights()"); }).find("no area"), std::string::npos);
    SeabedHeights small = host;
    small.columns = 1;
    EXPECT_NE(refusal([&] { checkSeabedHeights(small, "setSeabedHeights()"); }).find("2..4096"), std::string::npos);
}
