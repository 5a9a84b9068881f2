#include "flow_files.h"

#include "swell/dataset/atomic_file.h"

#include <fmt/format.h>

#include <bit>

namespace swell::app {

namespace fs = std::filesystem;

std::vector<fs::path> flowFilePaths(const fs::path& colour)
{
    const fs::path folder = colour.parent_path();
    const std::string stem = colour.stem().string();
    return {folder / fmt::format("{}.flow.npy", stem), folder / fmt::format("{}.flow_valid.npy", stem)};
}

void writeFlowFiles(const FrameFlow& flow, const fs::path& colour)
{
    const std::vector<fs::path> paths = flowFilePaths(colour);
    const int w = flow.size.x, h = flow.size.y;
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    static_assert(std::endian::native == std::endian::little, "the .npy descriptors say little-endian");
    writeFileAtomically(paths[0], npyBytes(flow.flow_px.data(), pixels * sizeof(glm::vec2), "<f4", {h, w, 2}));
    writeFileAtomically(paths[1], npyBytes(flow.valid.data(), pixels, "|u1", {h, w}));
}

Json flowJson(const FrameFlow& flow, double time_s)
{
    return {{"interval_s", flow.interval_s}, {"next_time_s", time_s + flow.interval_s}};
}

} // namespace swell::app
