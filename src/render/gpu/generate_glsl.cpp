// The build's GLSL generator: writes every file of render/gpu/glsl_files.h
// under the folder given (the shaders' staging folder, whose files are
// embedded in the library), or fails, writing nothing, when a block's C++
// layout is not the one std140 gives its description.
//   generate_glsl <folder>
#include "render/gpu/glsl_files.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <folder>\n", argv[0]);
        return 2;
    }
    std::string problems;
    const std::vector<swell::detail::GeneratedGlslFile> files = swell::detail::generatedGlslFiles(problems);
    if (!problems.empty()) {
        std::fprintf(stderr, "generate_glsl: the C++ blocks disagree with std140:\n%s", problems.c_str());
        return 1;
    }
    for (const swell::detail::GeneratedGlslFile& f : files) {
        const std::filesystem::path path = std::filesystem::path(argv[1]) / f.name;
        std::filesystem::create_directories(path.parent_path());
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << f.text;
        if (!out) {
            std::fprintf(stderr, "generate_glsl: cannot write %s\n", path.string().c_str());
            return 1;
        }
    }
    return 0;
}
