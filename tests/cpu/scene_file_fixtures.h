// What the scene-file tests share (test_scene_file.cpp, the table and round
// trips; test_scene_file_errors.cpp, the inputs that must be refused): a
// folder of their own holding the files inline scenes refer to, whole-file
// reads and writes, and a comparison of two scenes parameter by parameter.
#pragma once

#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swell::test::scene_files {

// A folder of the scene-file tests' own, with the files the inline scenes refer to.
inline std::filesystem::path workFolder()
{
    namespace fs = std::filesystem;
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
inline std::string inlinePath() { return (workFolder() / "inline.toml").string(); }

inline void writeFile(const std::filesystem::path& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
    ASSERT_TRUE(out.good()) << path;
}

inline std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every parameter of every item, the lists' lengths and the strings.
inline void expectSameScene(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.sea.wind.has_value(), b.sea.wind.has_value());
    if (a.sea.wind) {
        EXPECT_EQ(a.sea.wind->depth_m, b.sea.wind->depth_m);
    }
    ASSERT_EQ(a.waves.listed.size(), b.waves.listed.size());
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

} // namespace swell::test::scene_files
