// User assets through a scene file: six cubemap face images, and a glTF model
// placed in the world. Both are written here, with colours and a shape chosen
// so the rendered pixels can be predicted.
#include "support/camera_rays.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"
#include "support/golden.h"
#include "swell/error.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <glm/common.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

using swell::test::srgbLevel;
using swell::test::srgbToLinear;

namespace fs = std::filesystem;

class UserAssets : public swell::test::GlTest {};

constexpr glm::ivec2 kUserAssetsSize{160, 120};

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

void writeSolidPng(const fs::path& path, int size, std::array<std::uint8_t, 3> rgb)
{
    swell::Image image;
    image.width = image.height = size;
    for (int i = 0; i < size * size; ++i)
        image.rgba.insert(image.rgba.end(), {rgb[0], rgb[1], rgb[2], 255});
    swell::writePng(image, path);
}

// The face files in cubemap order (+x, -x, +y, -y, +z, -z) and their sRGB colours.
const std::array<const char*, 6> kFaceFiles{"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"};
const std::array<std::array<std::uint8_t, 3>, 6> kFaceColours{{
    {220, 40, 40}, {40, 200, 40}, {40, 60, 220}, {230, 220, 30}, {210, 40, 200}, {30, 210, 210}}};

// A scene file over six face images in `folder`, with no sun (its disc and
// highlight would add to the faces) and the fog out of the way.
fs::path writeSkyScene(const fs::path& folder, const std::array<const char*, 6>& faces)
{
    const fs::path scene = folder / "scene.toml";
    std::ofstream out(scene);
    out << "terrain = false\n\n[sun]\nintensity = 0.0\n\n[fog]\nstart_m = 100000.0\nend_m = 200000.0\n\n[sky]\nfaces = [";
    for (size_t i = 0; i < faces.size(); ++i)
        out << (i ? ", " : "") << '"' << faces[i] << '"';
    out << "]\n";
    return scene;
}

TEST_F(UserAssets, EachCubemapFaceShowsAlongItsAxis)
{
    const fs::path folder = freshFolder("user_sky");
    for (int f = 0; f < 6; ++f)
        writeSolidPng(folder / kFaceFiles[size_t(f)], 16, kFaceColours[size_t(f)]);
    const swell::Scene scene = swell::loadScene(writeSkyScene(folder, kFaceFiles));
    swell::Renderer renderer(scene);
    // Yaw and pitch that look mostly along each axis. Horizontal axes are
    // viewed 30 degrees up: the sky's fog layer makes the horizon itself fog
    // coloured. The -y face is not checked: below the horizon the sky lies
    // behind the water and is fully fogged by design (shaders/fog.glsl).
    struct View { int face; double yaw_deg, pitch_deg; };
    const View views[] = {{0, 90, 30}, {1, -90, 30}, {2, 0, 89}, {4, 180, 30}, {5, 0, 30}};
    for (const View& v : views) {
        swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
        camera.yaw_deg = v.yaw_deg;
        camera.pitch_deg = v.pitch_deg;
        const swell::Image image = renderer.renderImage(camera, 0.0, kUserAssetsSize);
        const std::string name = std::string("user_sky_") + kFaceFiles[size_t(v.face)];
        // 2 levels: sRGB decode in the sampler and encode in the shader round
        // to 8 bits once each. A face in another slot is off by over 100.
        for (int y = kUserAssetsSize.y / 2 - 4; y <= kUserAssetsSize.y / 2 + 4; y += 2)
            for (int x = kUserAssetsSize.x / 2 - 4; x <= kUserAssetsSize.x / 2 + 4; x += 2)
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(image.pixel(x, y)[c], kFaceColours[size_t(v.face)][size_t(c)], 2)
                        << "looking along face " << kFaceFiles[size_t(v.face)] << ", pixel " << x << "," << y
                        << " channel " << c << ": " << swell::test::saveTestImage(image, name);
    }
}

TEST_F(UserAssets, AFaceOfTheWrongSizeIsAnInputErrorNamingIt)
{
    const fs::path folder = freshFolder("user_sky_wrong_size");
    for (int f = 0; f < 6; ++f)
        writeSolidPng(folder / kFaceFiles[size_t(f)], f == 5 ? 8 : 16, kFaceColours[size_t(f)]);
    const swell::Scene scene = swell::loadScene(writeSkyScene(folder, kFaceFiles));
    try {
        swell::Renderer renderer(scene);
        FAIL() << "a 8x8 face among 16x16 ones was accepted";
    } catch (const swell::InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find((folder / "nz.png").string()), std::string::npos) << message;
        EXPECT_NE(message.find("8x8"), std::string::npos) << message;
    }
}

TEST_F(UserAssets, AMissingFaceIsAnInputErrorNamingIt)
{
    const fs::path folder = freshFolder("user_sky_missing");
    for (int f = 0; f < 6; ++f)
        writeSolidPng(folder / kFaceFiles[size_t(f)], 16, kFaceColours[size_t(f)]);
    std::array<const char*, 6> faces = kFaceFiles;
    faces[3] = "absent.png";
    // The scene file checks its paths when it loads...
    EXPECT_THROW(
        {
            try {
                swell::loadScene(writeSkyScene(folder, faces));
            } catch (const swell::InputError& e) {
                EXPECT_NE(std::string(e.what()).find("absent.png"), std::string::npos) << e.what();
                throw;
            }
        },
        swell::InputError);
    // ...and a scene built in code fails in the renderer, naming the file.
    swell::Scene scene = swell::loadScene(writeSkyScene(folder, kFaceFiles));
    scene.sky.cubemapFaces[3] = "absent.png";
    try {
        swell::Renderer renderer(scene);
        FAIL() << "a missing face was accepted";
    } catch (const swell::InputError& e) {
        EXPECT_NE(std::string(e.what()).find((folder / "absent.png").string()), std::string::npos) << e.what();
    }
}

bool near(const std::uint8_t* p, glm::dvec3 expected, double tolerance)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(p[c] - expected[c]) > tolerance)
            return false;
    return true;
}

TEST_F(UserAssets, AGltfModelRendersWhereTheSceneFilePlacesIt)
{
    const fs::path folder = freshFolder("user_model");
    // A 2 m box, scaled 2 by the scene to 4 m, its centre at (3, 4, -30) m.
    const glm::vec3 albedo(0.8f, 0.1f, 0.6f);
    swell::test::writeGltf(swell::test::makeBox(1.0f, albedo), folder / "box.gltf");
    {
        std::ofstream(folder / "scene.toml") << "terrain = false\n\n[sun]\nintensity = 0.0\n\n"
                                                "[[objects]]\npath = \"box.gltf\"\nposition_m = [3.0, 4.0, -30.0]\nscale = 2.0\n\n"
                                                "[camera]\nposition_m = [0.0, 4.0, 0.0]\npitch_deg = 0.0\n";
    }
    swell::Scene scene = swell::loadScene(folder / "scene.toml");
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const swell::Image image = renderer.renderImage(camera, 0.0, kUserAssetsSize);
    const std::string path = swell::test::saveTestImage(image, "user_gltf_box");
    // The face towards the camera (normal +z) with no sun: albedo times the
    // sky ambient halfway between horizon and zenith (shaders/mesh.frag), no fog at 28 m.
    const glm::dvec3 ambient = glm::mix(scene.sky.horizonColor, scene.sky.zenithColor, 0.5) * 0.45;
    const glm::dvec3 lit = glm::dvec3(albedo) * ambient;
    const glm::dvec3 expected(srgbLevel(lit.r), srgbLevel(lit.g), srgbLevel(lit.b));
    // 3 levels: 8-bit rounding and float arithmetic in the shader.
    const double tolerance = 3.0;
    auto pixelAt = [&](glm::dvec3 p) {
        const glm::dvec2 px = swell::test::projectToPixel(camera, kUserAssetsSize, p);
        return image.pixel(int(px.x), int(px.y));
    };
    // The front face spans x 1..5 m and y 2..6 m at z = -28 m; its centre and
    // points 0.4 m inside its left, right and top edges show the box...
    for (glm::dvec3 p : {glm::dvec3(3.0, 4.0, -28.0), glm::dvec3(1.4, 4.0, -28.0), glm::dvec3(4.6, 4.0, -28.0),
                         glm::dvec3(3.0, 5.6, -28.0)})
        EXPECT_TRUE(near(pixelAt(p), expected, tolerance))
            << "no box at " << p.x << "," << p.y << "," << p.z << ": " << path;
    // ...and points 0.4 m outside those edges do not (placement and scale).
    for (glm::dvec3 p : {glm::dvec3(0.6, 4.0, -28.0), glm::dvec3(5.4, 4.0, -28.0), glm::dvec3(3.0, 6.4, -28.0)})
        EXPECT_FALSE(near(pixelAt(p), expected, 30.0)) << "box colour outside the box at " << p.x << "," << p.y << ": " << path;

    scene.objects.clear();
    renderer.setScene(scene);
    const swell::Image without = renderer.renderImage(camera, 0.0, kUserAssetsSize);
    const glm::dvec2 centre = swell::test::projectToPixel(camera, kUserAssetsSize, {3.0, 4.0, -28.0});
    EXPECT_FALSE(near(without.pixel(int(centre.x), int(centre.y)), expected, 30.0))
        << "the box is still drawn after it was removed: " << swell::test::saveTestImage(without, "user_gltf_removed");
}

} // namespace
