// `swell bench`: the machine it ran on, the table on stdout and the JSON file.
#include "bench.h"

#include "swell/error.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace swell::app::bench {

double percentile(std::vector<double>& values, double q)
{
    if (values.empty())
        return 0.0;
    const auto rank = size_t(std::ceil(q * double(values.size())));
    const size_t index = std::clamp<size_t>(rank, 1, values.size()) - 1;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(index), values.end());
    return values[index];
}

double median(std::vector<double>& values)
{
    if (values.empty())
        return 0.0;
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1)
        return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(mid));
    return 0.5 * (lower + upper);
}

Summary summarize(std::vector<double> values)
{
    Summary s;
    if (values.empty())
        return s;
    s.min = *std::min_element(values.begin(), values.end());
    s.max = *std::max_element(values.begin(), values.end());
    s.p95 = percentile(values, 0.95);
    s.median = median(values);
    return s;
}

namespace {

std::string trim(std::string s)
{
    const size_t begin = s.find_first_not_of(" \t\r\n");
    const size_t end = s.find_last_not_of(" \t\r\n");
    return begin == std::string::npos ? std::string() : s.substr(begin, end - begin + 1);
}

std::string cpuModel()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
            return trim(line.substr(line.find(':') + 1));
    return "unknown";
}

// The short hash of the source tree's HEAD, read when the benchmark runs.
std::string sourceCommit()
{
    FILE* pipe = ::popen("git -C '" SWELL_SOURCE_DIR "' rev-parse --short HEAD 2>/dev/null", "r");
    if (!pipe)
        return "unknown";
    char buffer[128] = {};
    std::string text;
    while (std::fgets(buffer, sizeof buffer, pipe))
        text += buffer;
    const int status = ::pclose(pipe);
    text = trim(text);
    return status == 0 && !text.empty() ? text : "unknown";
}

std::string glString(GLenum name)
{
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "unknown";
}

// Pass names in the order they first appear.
std::vector<std::string> passNames(const std::vector<FrameSample>& frames)
{
    std::vector<std::string> names;
    for (const FrameSample& f : frames)
        for (const PassSample& p : f.passes)
            if (std::find(names.begin(), names.end(), p.name) == names.end())
                names.push_back(p.name);
    return names;
}

int passDepth(const std::vector<FrameSample>& frames, const std::string& name)
{
    for (const FrameSample& f : frames)
        if (const PassSample* p = f.find(name))
            return p->depth;
    return 0;
}

std::string passParent(const std::vector<FrameSample>& frames, const std::string& name)
{
    for (const FrameSample& f : frames)
        if (const PassSample* p = f.find(name))
            return p->parent;
    return {};
}

// One figure of a pass (or of the whole frame) over the frames that have it.
std::vector<double> passSeries(const std::vector<FrameSample>& frames, const std::string& name, double PassSample::*field)
{
    std::vector<double> out;
    for (const FrameSample& f : frames)
        if (const PassSample* p = f.find(name))
            out.push_back(p->*field);
    return out;
}

std::vector<double> passGpu(const std::vector<FrameSample>& frames, const std::string& name)
{
    std::vector<double> out;
    for (const FrameSample& f : frames)
        if (const PassSample* p = f.find(name); p && p->gpu_ms)
            out.push_back(*p->gpu_ms);
    return out;
}

std::vector<double> frameSeries(const std::vector<FrameSample>& frames, double FrameSample::*field)
{
    std::vector<double> out;
    for (const FrameSample& f : frames)
        out.push_back(f.*field);
    return out;
}

PassCounters passTotal(const std::vector<FrameSample>& frames, const std::string& name)
{
    PassCounters total;
    for (const FrameSample& f : frames)
        if (const PassSample* p = f.find(name))
            total += p->counters;
    return total;
}

double ratio(double real, double floor) { return floor > 0.0 ? real / floor : 0.0; }

// The project's goals, in one place for the table and the JSON file.
constexpr double kGoalFrameRatio = 2.0;        // real/floor of the whole frame, at most
constexpr double kGoalInFrustum = 0.80;        // share of water triangles in the frustum, at least
constexpr double kGoalMedianArea_px2[2] = {8.0, 64.0}; // median projected triangle area, px²

bool areaGoalMet(const LodSample& s)
{
    return s.areaMedian_px2 >= kGoalMedianArea_px2[0] && s.areaMedian_px2 <= kGoalMedianArea_px2[1];
}

// A minimal JSON writer: objects and arrays with commas and indentation.
class Json {
public:
    void open(char bracket, const std::string& key = {})
    {
        prefix(key);
        out_ += bracket;
        first_.push_back(true);
    }
    void close(char bracket)
    {
        first_.pop_back();
        out_ += '\n' + std::string(first_.size() * 2, ' ') + bracket;
    }
    void field(const std::string& key, const std::string& value) { prefix(key); out_ += quoted(value); }
    void field(const std::string& key, const char* value) { field(key, std::string(value)); }
    void field(const std::string& key, double value)
    {
        prefix(key);
        out_ += std::isfinite(value) ? fmt::format("{}", value) : "null";
    }
    void field(const std::string& key, int value) { prefix(key); out_ += fmt::format("{}", value); }
    void field(const std::string& key, long long value) { prefix(key); out_ += fmt::format("{}", value); }
    void field(const std::string& key, std::uint64_t value) { prefix(key); out_ += fmt::format("{}", value); }
    void field(const std::string& key, bool value) { prefix(key); out_ += value ? "true" : "false"; }
    void null(const std::string& key) { prefix(key); out_ += "null"; }
    const std::string& text() const { return out_; }

private:
    void prefix(const std::string& key)
    {
        if (!first_.empty()) {
            if (!first_.back())
                out_ += ',';
            first_.back() = false;
            out_ += '\n' + std::string(first_.size() * 2, ' ');
        }
        if (!key.empty())
            out_ += quoted(key) + ": ";
    }
    static std::string quoted(const std::string& s)
    {
        std::string q = "\"";
        for (const char c : s) {
            if (c == '"' || c == '\\')
                q += {'\\', c};
            else if (static_cast<unsigned char>(c) < 0x20)
                q += fmt::format("\\u{:04x}", int(c));
            else
                q += c;
        }
        return q + '"';
    }
    std::string out_;
    std::vector<bool> first_;
};

void writeSummary(Json& j, const std::string& key, const Summary& s)
{
    j.open('{', key);
    j.field("min", s.min);
    j.field("median", s.median);
    j.field("p95", s.p95);
    j.field("max", s.max);
    j.close('}');
}

void writeCounters(Json& j, const std::string& key, const PassCounters& c, bool statistics)
{
    j.open('{', key);
    if (statistics) {
        j.field("vertex_shader_invocations", c.vertexShaderInvocations);
        j.field("fragment_shader_invocations", c.fragmentShaderInvocations);
        j.field("primitives_submitted", c.primitivesSubmitted);
        j.field("clipping_input_primitives", c.clippingInputPrimitives);
        j.field("clipping_output_primitives", c.clippingOutputPrimitives);
    }
    j.field("samples_passed", c.samplesPassed);
    j.close('}');
}

void writeCamera(Json& j, const Camera& c)
{
    j.open('{', "camera");
    j.open('[', "position_m");
    j.field("", c.position_m.x);
    j.field("", c.position_m.y);
    j.field("", c.position_m.z);
    j.close(']');
    j.field("yaw_deg", c.yaw_deg);
    j.field("pitch_deg", c.pitch_deg);
    j.close('}');
}

} // namespace

Machine describeMachine()
{
    Machine m;
    m.cpu = cpuModel();
    m.cores = int(::sysconf(_SC_NPROCESSORS_ONLN));
    m.glRenderer = glString(GL_RENDERER);
    m.glVersion = glString(GL_VERSION);
    m.commit = sourceCommit();
    return m;
}

void printReport(const Results& r)
{
    const std::vector<std::string> names = passNames(r.real);
    std::printf("swell bench: %dx%d (reflection and refraction %dx%d), %s, %dx%d water cells\n", r.size.x,
                r.size.y, r.passSize.x, r.passSize.y, r.surface.c_str(), r.gridCells, r.gridCells);
    std::printf("  %d measured frames after %d warm-up, %.4g s of simulation apart; commit %s\n", r.frames, r.warmup,
                r.frameStep_s, r.machine.commit.c_str());
    std::printf("  %s, %d cores; %s, %s\n\n", r.machine.cpu.c_str(), r.machine.cores, r.machine.glRenderer.c_str(),
                r.machine.glVersion.c_str());

    std::printf("Time per pass, ms. wall: steady clock between glFinish calls; CPU: process CPU time (all\n"
                "threads) over the same span. floor: the same pass with trivial shading (least)%s\n",
                r.gpuTimers ? "; GPU: GL_TIME_ELAPSED (median)" : "");
    std::printf("  %-14s %29s %9s | %17s | %14s%s\n", "", "------------ wall -----------", "CPU", "----- floor -----",
                "- real/floor -", r.gpuTimers ? " |       GPU" : "");
    std::printf("  %-14s %9s %9s %9s %9s | %8s %8s | %6s %7s%s\n", "pass", "median", "p95", "max", "median", "wall",
                "CPU", "wall", "CPU", r.gpuTimers ? " |    median" : "");
    auto row = [&](const std::string& label, const std::vector<double>& wall, const std::vector<double>& cpu,
                   const std::vector<double>& floorWall, const std::vector<double>& floorCpu,
                   const std::vector<double>& gpu) {
        const Summary w = summarize(wall), c = summarize(cpu), fw = summarize(floorWall), fc = summarize(floorCpu);
        std::string gpuColumn;
        if (r.gpuTimers)
            gpuColumn = gpu.empty() ? fmt::format(" | {:>9}", "-") : fmt::format(" | {:9.3f}", summarize(gpu).median);
        std::printf("  %-14s %9.3f %9.3f %9.3f %9.3f | %8.3f %8.3f | %6.1f %7.1f%s\n", label.c_str(), w.median, w.p95,
                    w.max, c.median, floorCost(fw), floorCost(fc), ratio(w.median, floorCost(fw)), ratio(c.median, floorCost(fc)),
                    gpuColumn.c_str());
    };
    for (const std::string& name : names) {
        const int depth = passDepth(r.real, name);
        row(std::string(size_t(depth) * 2, ' ') + name, passSeries(r.real, name, &PassSample::wall_ms),
            passSeries(r.real, name, &PassSample::cpu_ms), passSeries(r.floor, name, &PassSample::wall_ms),
            passSeries(r.floor, name, &PassSample::cpu_ms), passGpu(r.real, name));
    }
    row("frame", frameSeries(r.real, &FrameSample::wall_ms), frameSeries(r.real, &FrameSample::cpu_ms),
        frameSeries(r.floor, &FrameSample::wall_ms), frameSeries(r.floor, &FrameSample::cpu_ms), {});
    std::printf("  (an inner pass is part of the pass above it; the floor is each pass's target cleared and covered\n"
                "   by one full-screen triangle of a constant colour)\n\n");

    std::printf("Counters summed over the %d measured frames (exact: equal in every run)\n", r.frames);
    if (!r.pipelineStatistics)
        std::printf("  (no GL_ARB_pipeline_statistics_query: samples passed only)\n");
    std::printf("  %-14s %14s %14s %12s %12s %12s %14s\n", "pass", "VS invocations", "FS invocations", "primitives",
                "clip in", "clip out", "samples passed");
    for (const std::string& name : names) {
        const PassCounters c = passTotal(r.real, name);
        const std::string label = std::string(size_t(passDepth(r.real, name)) * 2, ' ') + name;
        std::printf("  %-14s %14llu %14llu %12llu %12llu %12llu %14llu\n", label.c_str(),
                    (unsigned long long)c.vertexShaderInvocations, (unsigned long long)c.fragmentShaderInvocations,
                    (unsigned long long)c.primitivesSubmitted, (unsigned long long)c.clippingInputPrimitives,
                    (unsigned long long)c.clippingOutputPrimitives, (unsigned long long)c.samplesPassed);
    }

    if (!r.lod.empty()) {
        std::printf("\nWater grid LOD: %lld triangles submitted per frame; size = projected area in px^2 of the\n"
                    "triangles at least partly in the frustum (cut at the near plane)\n",
                    r.lod.front().triangles);
        std::printf("  %5s %24s %6s %6s | %10s %11s | %8s %8s %8s | %8s %7s\n", "frame", "camera x,y,z m", "yaw",
                    "pitch", "in frustum", "clip out/in", "p10", "median", "p90", "edge px", "<1 px^2");
        for (const LodSample& s : r.lod) {
            const std::string position =
                fmt::format("{:.1f},{:.1f},{:.1f}", s.camera.position_m.x, s.camera.position_m.y, s.camera.position_m.z);
            const std::string clip = s.clipShare ? fmt::format("{:.1f}%", *s.clipShare * 100.0) : "-";
            std::printf("  %5d %24s %6.1f %6.1f | %9.1f%% %11s | %8.2f %8.2f %8.1f | %8.2f %6.1f%%\n", s.frame,
                        position.c_str(), s.camera.yaw_deg, s.camera.pitch_deg, s.inFrustumShare * 100.0, clip.c_str(),
                        s.areaP10_px2, s.areaMedian_px2, s.areaP90_px2, s.edgeMedian_px, s.subPixelShare * 100.0);
        }
    }

    std::printf("\nGoals\n");
    const double frameRatio = ratio(summarize(frameSeries(r.real, &FrameSample::wall_ms)).median,
                                    floorCost(summarize(frameSeries(r.floor, &FrameSample::wall_ms))));
    const double frameCpuRatio = ratio(summarize(frameSeries(r.real, &FrameSample::cpu_ms)).median,
                                       floorCost(summarize(frameSeries(r.floor, &FrameSample::cpu_ms))));
    std::printf("  frame real/floor <= %.0f: %s (wall %.1f, CPU %.1f)\n", kGoalFrameRatio,
                frameRatio <= kGoalFrameRatio ? "met" : "not met", frameRatio, frameCpuRatio);
    if (!r.lod.empty()) {
        const auto n = r.lod.size();
        const auto inFrustum = std::count_if(r.lod.begin(), r.lod.end(),
                                             [](const LodSample& s) { return s.inFrustumShare >= kGoalInFrustum; });
        const auto sized = std::count_if(r.lod.begin(), r.lod.end(), areaGoalMet);
        std::printf("  water triangles in frustum >= %.0f%%: met in %d of %d sampled frames\n", kGoalInFrustum * 100.0,
                    int(inFrustum), int(n));
        std::printf("  median triangle %.0f..%.0f px^2: met in %d of %d sampled frames\n", kGoalMedianArea_px2[0],
                    kGoalMedianArea_px2[1], int(sized), int(n));
    }
    std::fflush(stdout);
}

void writeJson(const Results& r, const std::string& path)
{
    Json j;
    j.open('{');
    j.open('{', "machine");
    j.field("cpu", r.machine.cpu);
    j.field("cores", r.machine.cores);
    j.field("gl_renderer", r.machine.glRenderer);
    j.field("gl_version", r.machine.glVersion);
    j.close('}');
    j.field("commit", r.machine.commit);
    j.open('[', "size");
    j.field("", r.size.x);
    j.field("", r.size.y);
    j.close(']');
    j.open('[', "pass_size");
    j.field("", r.passSize.x);
    j.field("", r.passSize.y);
    j.close(']');
    j.field("surface", r.surface);
    j.field("grid_cells", r.gridCells);
    j.field("frames", r.frames);
    j.field("warmup", r.warmup);
    j.field("frame_step_s", r.frameStep_s);
    j.field("pipeline_statistics", r.pipelineStatistics);
    j.field("gpu_timers", r.gpuTimers);

    const std::vector<std::string> names = passNames(r.real);
    j.open('{', "passes");
    for (const std::string& name : names) {
        j.open('{', name);
        if (const std::string parent = passParent(r.real, name); !parent.empty())
            j.field("inside", parent);
        else
            j.null("inside");
        const Summary realWall = summarize(passSeries(r.real, name, &PassSample::wall_ms));
        const Summary floorWall = summarize(passSeries(r.floor, name, &PassSample::wall_ms));
        const Summary realCpu = summarize(passSeries(r.real, name, &PassSample::cpu_ms));
        const Summary floorCpu = summarize(passSeries(r.floor, name, &PassSample::cpu_ms));
        writeSummary(j, "wall_ms", realWall);
        writeSummary(j, "cpu_ms", realCpu);
        const std::vector<double> gpu = passGpu(r.real, name);
        if (gpu.empty())
            j.null("gpu_ms");
        else
            writeSummary(j, "gpu_ms", summarize(gpu));
        writeSummary(j, "floor_wall_ms", floorWall);
        writeSummary(j, "floor_cpu_ms", floorCpu);
        j.field("real_over_floor", ratio(realWall.median, floorCost(floorWall)));
        j.field("real_over_floor_cpu", ratio(realCpu.median, floorCost(floorCpu)));
        writeCounters(j, "counters_total", passTotal(r.real, name), r.pipelineStatistics);
        writeCounters(j, "floor_counters_total", passTotal(r.floor, name), r.pipelineStatistics);
        j.close('}');
    }
    j.close('}');

    const Summary frameReal = summarize(frameSeries(r.real, &FrameSample::wall_ms));
    const Summary frameFloor = summarize(frameSeries(r.floor, &FrameSample::wall_ms));
    const Summary frameRealCpu = summarize(frameSeries(r.real, &FrameSample::cpu_ms));
    const Summary frameFloorCpu = summarize(frameSeries(r.floor, &FrameSample::cpu_ms));
    j.open('{', "frame");
    writeSummary(j, "wall_ms", frameReal);
    writeSummary(j, "cpu_ms", frameRealCpu);
    writeSummary(j, "floor_wall_ms", frameFloor);
    writeSummary(j, "floor_cpu_ms", frameFloorCpu);
    j.field("real_over_floor", ratio(frameReal.median, floorCost(frameFloor)));
    j.field("real_over_floor_cpu", ratio(frameRealCpu.median, floorCost(frameFloorCpu)));
    j.close('}');

    j.open('[', "lod");
    for (const LodSample& s : r.lod) {
        j.open('{');
        j.field("frame", s.frame);
        writeCamera(j, s.camera);
        j.field("triangles", s.triangles);
        j.field("in_frustum", s.inFrustum);
        j.field("in_frustum_share", s.inFrustumShare);
        if (s.clipShare) {
            j.field("clip_input", s.clipInput);
            j.field("clip_output", s.clipOutput);
            j.field("clip_output_over_input", *s.clipShare);
        } else {
            j.null("clip_output_over_input");
        }
        j.open('{', "area_px2");
        j.field("p10", s.areaP10_px2);
        j.field("median", s.areaMedian_px2);
        j.field("p90", s.areaP90_px2);
        j.close('}');
        j.field("longest_edge_median_px", s.edgeMedian_px);
        j.field("sub_pixel_share", s.subPixelShare);
        j.close('}');
    }
    j.close(']');

    j.open('{', "goals");
    j.field("frame_real_over_floor_max", kGoalFrameRatio);
    j.field("in_frustum_share_min", kGoalInFrustum);
    j.open('[', "median_area_px2");
    j.field("", kGoalMedianArea_px2[0]);
    j.field("", kGoalMedianArea_px2[1]);
    j.close(']');
    j.close('}');

    j.open('[', "measured_frames");
    for (size_t i = 0; i < r.real.size(); ++i) {
        const FrameSample& f = r.real[i];
        j.open('{');
        j.field("index", int(i));
        if (i < r.realTimes_s.size())
            j.field("time_s", r.realTimes_s[i]);
        if (i < r.realCameras.size())
            writeCamera(j, r.realCameras[i]);
        j.field("wall_ms", f.wall_ms);
        j.field("cpu_ms", f.cpu_ms);
        j.open('{', "passes");
        for (const PassSample& p : f.passes) {
            j.open('{', p.name);
            j.field("wall_ms", p.wall_ms);
            j.field("cpu_ms", p.cpu_ms);
            if (p.gpu_ms)
                j.field("gpu_ms", *p.gpu_ms);
            else
                j.null("gpu_ms");
            writeCounters(j, "counters", p.counters, r.pipelineStatistics);
            j.close('}');
        }
        j.close('}');
        j.close('}');
    }
    j.close(']');
    j.close('}');

    std::ofstream out(path, std::ios::binary);
    out << j.text() << '\n';
    if (!out)
        throw Error(fmt::format("swell bench: cannot write '{}'", path));
}

} // namespace swell::app::bench
