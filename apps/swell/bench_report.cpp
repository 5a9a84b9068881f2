// `swell bench`: the machine it ran on, the table on stdout and the JSON file.
#include "bench.h"

#include "swell/error.h"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

// One figure of a pass (or of the whole frame) over the frames that have it:
// in each frame, the sum over the pass's runs (a stage of the wave model's
// may run more than once in a frame).
std::vector<double> passSeries(const std::vector<FrameSample>& frames, const std::string& name, double PassSample::*field)
{
    std::vector<double> out;
    for (const FrameSample& f : frames) {
        double sum = 0.0;
        bool found = false;
        for (const PassSample& p : f.passes)
            if (p.name == name) {
                sum += p.*field;
                found = true;
            }
        if (found)
            out.push_back(sum);
    }
    return out;
}

std::vector<double> passGpu(const std::vector<FrameSample>& frames, const std::string& name)
{
    std::vector<double> out;
    for (const FrameSample& f : frames) {
        double sum = 0.0;
        bool found = false;
        for (const PassSample& p : f.passes)
            if (p.name == name && p.gpu_ms) {
                sum += *p.gpu_ms;
                found = true;
            }
        if (found)
            out.push_back(sum);
    }
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
        for (const PassSample& p : f.passes)
            if (p.name == name)
                total += p.counters;
    return total;
}

double ratio(double real, double floor) { return floor > 0.0 ? real / floor : 0.0; }

// With --labels, each measured frame's labelled sample as `swell dataset`
// draws one: the colour frame and its label pass, summed frame by frame.
std::vector<double> labelledSampleSeries(const Results& r, double FrameSample::*field)
{
    std::vector<double> out;
    for (size_t i = 0; i < r.real.size() && i < r.labels.size(); ++i)
        out.push_back(r.real[i].*field + r.labels[i].*field);
    return out;
}

// The project's goals, in one place for the table and the JSON file.
constexpr double kGoalFrameRatio = 2.0;        // real/floor of the whole frame, at most
constexpr double kGoalInFrustum = 0.80;        // share of water triangles in the frustum, at least
constexpr double kGoalMedianArea_px2[2] = {8.0, 64.0}; // median projected triangle area, px²

bool areaGoalMet(const LodSample& s)
{
    return s.areaMedian_px2 >= kGoalMedianArea_px2[0] && s.areaMedian_px2 <= kGoalMedianArea_px2[1];
}

// nlohmann's ordered_json keeps the keys in the order written, so the file
// reads like the table. Non-finite numbers become null.
using Json = nlohmann::ordered_json;

Json summaryJson(const Summary& s) { return {{"min", s.min}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}}; }

Json countersJson(const PassCounters& c, bool statistics)
{
    Json j = Json::object();
    if (statistics) {
        j["vertex_shader_invocations"] = c.vertexShaderInvocations;
        j["fragment_shader_invocations"] = c.fragmentShaderInvocations;
        j["primitives_submitted"] = c.primitivesSubmitted;
        j["clipping_input_primitives"] = c.clippingInputPrimitives;
        j["clipping_output_primitives"] = c.clippingOutputPrimitives;
    }
    j["samples_passed"] = c.samplesPassed;
    return j;
}

Json cameraJson(const Camera& c)
{
    return {{"position_m", {c.position_m.x, c.position_m.y, c.position_m.z}},
            {"yaw_deg", c.yaw_deg},
            {"pitch_deg", c.pitch_deg}};
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
    // The headline first: frames per second from the median whole frame.
    const Summary frameWall = summarize(frameSeries(r.real, &FrameSample::wall_ms));
    const Summary frameCpu = summarize(frameSeries(r.real, &FrameSample::cpu_ms));
    std::printf("%.2f frames per second (median frame %.1f ms wall, %.1f ms CPU) at %dx%d, %d measured frames\n",
                frameWall.median > 0.0 ? 1000.0 / frameWall.median : 0.0, frameWall.median, frameCpu.median, r.size.x,
                r.size.y, r.frames);
    printSimulationCpuLine(r);
    std::printf("\n");
    std::printf("swell bench: %dx%d (reflection and refraction %dx%d), %s, %dx%d water cells\n", r.size.x,
                r.size.y, r.passSize.x, r.passSize.y, r.surface.c_str(), r.gridCells, r.gridCells);
    std::printf("output: %s\n", r.output.c_str());
    std::printf("  %d measured frames after %d warm-up, %.4g s of simulation apart; commit %s\n", r.frames, r.warmup,
                r.frameStep_s, r.machine.commit.c_str());
    std::printf("  %s, %d cores; %s, %s\n\n", r.machine.cpu.c_str(), r.machine.cores, r.machine.glRenderer.c_str(),
                r.machine.glVersion.c_str());

    std::printf("Time per pass, ms. wall: steady clock between glFinish calls; CPU: process CPU time (all\n"
                "threads) over the same span. floor: the same pass with trivial shading (least)%s\n",
                r.gpuTimers ? "; GPU: GL_TIME_ELAPSED (median)" : "");
    std::printf("  %-16s %29s %9s | %17s | %14s%s\n", "", "------------ wall -----------", "CPU", "----- floor -----",
                "- real/floor -", r.gpuTimers ? " |       GPU" : "");
    std::printf("  %-16s %9s %9s %9s %9s | %8s %8s | %6s %7s%s\n", "pass", "median", "p95", "max", "median", "wall",
                "CPU", "wall", "CPU", r.gpuTimers ? " |    median" : "");
    auto row = [&](const std::string& label, const std::vector<double>& wall, const std::vector<double>& cpu,
                   const std::vector<double>& floorWall, const std::vector<double>& floorCpu,
                   const std::vector<double>& gpu) {
        const Summary w = summarize(wall), c = summarize(cpu), fw = summarize(floorWall), fc = summarize(floorCpu);
        std::string gpuColumn;
        if (r.gpuTimers)
            gpuColumn = gpu.empty() ? fmt::format(" | {:>9}", "-") : fmt::format(" | {:9.3f}", summarize(gpu).median);
        // A pass the floor frame does not have (a wave model's stages): no floor, no ratio.
        const std::string floorColumns =
            floorWall.empty() ? fmt::format("{:>8} {:>8} | {:>6} {:>7}", "-", "-", "-", "-")
                              : fmt::format("{:8.3f} {:8.3f} | {:6.1f} {:7.1f}", floorCost(fw), floorCost(fc),
                                            ratio(w.median, floorCost(fw)), ratio(c.median, floorCost(fc)));
        std::printf("  %-16s %9.3f %9.3f %9.3f %9.3f | %s%s\n", label.c_str(), w.median, w.p95, w.max, c.median,
                    floorColumns.c_str(), gpuColumn.c_str());
    };
    for (const std::string& name : names) {
        const int depth = passDepth(r.real, name);
        row(std::string(size_t(depth) * 2, ' ') + name, passSeries(r.real, name, &PassSample::wall_ms),
            passSeries(r.real, name, &PassSample::cpu_ms), passSeries(r.floor, name, &PassSample::wall_ms),
            passSeries(r.floor, name, &PassSample::cpu_ms), passGpu(r.real, name));
    }
    row("frame", frameSeries(r.real, &FrameSample::wall_ms), frameSeries(r.real, &FrameSample::cpu_ms),
        frameSeries(r.floor, &FrameSample::wall_ms), frameSeries(r.floor, &FrameSample::cpu_ms), {});
    if (!r.labels.empty()) {
        // No floor: the floor frame has no label pass.
        row(kLabelsPass, passSeries(r.labels, kLabelsPass, &PassSample::wall_ms),
            passSeries(r.labels, kLabelsPass, &PassSample::cpu_ms), {}, {}, passGpu(r.labels, kLabelsPass));
        row("frame + labels", labelledSampleSeries(r, &FrameSample::wall_ms),
            labelledSampleSeries(r, &FrameSample::cpu_ms), {}, {}, {});
        if (!r.flow.empty())
            row(kFlowPass, passSeries(r.flow, kFlowPass, &PassSample::wall_ms),
                passSeries(r.flow, kFlowPass, &PassSample::cpu_ms), {}, {}, {});
    }
    if (!r.sensor.empty())
        row(kSensorPass, passSeries(r.sensor, kSensorPass, &PassSample::wall_ms),
            passSeries(r.sensor, kSensorPass, &PassSample::cpu_ms), {}, {}, passGpu(r.sensor, kSensorPass));
    if (!r.motionVectors.empty())
        row(kMotionVectorsPass, passSeries(r.motionVectors, kMotionVectorsPass, &PassSample::wall_ms),
            passSeries(r.motionVectors, kMotionVectorsPass, &PassSample::cpu_ms), {}, {},
            passGpu(r.motionVectors, kMotionVectorsPass));
    std::printf("  (an inner pass is part of the pass above it; the floor is each pass's target cleared and covered\n"
                "   by one full-screen triangle of a constant colour)\n");
    if (!r.labels.empty())
        std::printf("  (--labels: \"labels\" is the label pass drawn after each frame for its camera and time, its\n"
                    "   arrays read back, apart from the frame; \"frame + labels\" their sum a frame: a labelled sample;\n"
                    "   \"flow\" the optical flow from the frame before's labels to these, on the CPU)\n");
    if (!r.sensor.empty())
        std::printf("  (--sensor: \"sensor\" is the frame drawn again through the camera's sensor, as `swell render`\n"
                    "   draws it: %d draw%s a frame through the lens, the shutter and the readout)\n",
                    r.sensorDraws, r.sensorDraws == 1 ? "" : "s");
    if (!r.motionVectors.empty()) {
        const FrameCounters& c = r.motionVectorCounters.front();
        std::printf("  (--motion-vectors: \"motion vectors\" is their pass after the frame drawn again into a host's\n"
                    "   framebuffer with Swell's world and sky, DrawOptions::motionVectors: %d draws, %lld triangles a frame)\n",
                    c.motionVectorDraws, c.motionVectorTriangles);
    }
    long long steps = 0;
    for (long long s : r.bodySteps)
        steps += s;
    std::printf("  bodies: %d floating rigid bodies, %lld integration steps of 1/120 s over the measured frames\n",
                r.floatingBodies, steps);
    long long wakeSteps = 0;
    double wake_ms = 0.0;
    for (size_t f = 0; f < r.wakeSteps.size(); ++f) {
        wakeSteps += r.wakeSteps[f];
        wake_ms += r.wakeSteps_ms[f];
    }
    if (wakeSteps > 0)
        std::printf("  wake: %lld steps of 1/30 s over the measured frames (within \"bodies\" or on the bodies' worker), %.2f ms a step, "
                    "%.2f ms a frame on average (wall)\n",
                    wakeSteps, wake_ms / double(wakeSteps), wake_ms / double(r.wakeSteps.size()));
    else
        std::printf("  wake: none (no floating body under way, or wake.enabled = false)\n");
    std::printf("\n");

    if (!r.reflectionModes.empty()) {
        std::printf("Reflection lookup: the water pass with each reflection.mode, frame for frame in turn\n");
        std::printf("  %-14s %9s %9s\n", "mode", "wall med", "CPU med");
        for (const ReflectionModeCost& c : r.reflectionModes)
            std::printf("  %-14s %9.3f %9.3f\n", c.mode.c_str(), summarize(c.waterWall_ms).median,
                        summarize(c.waterCpu_ms).median);
        std::printf("\n");
    }

    std::printf("Counters summed over the %d measured frames (exact: equal in every run)\n", r.frames);
    if (!r.pipelineStatistics)
        std::printf("  (no GL_ARB_pipeline_statistics_query: samples passed only)\n");
    std::printf("  %-16s %14s %14s %12s %12s %12s %14s\n", "pass", "VS invocations", "FS invocations", "primitives",
                "clip in", "clip out", "samples passed");
    auto counterRow = [](const std::string& label, const PassCounters& c) {
        std::printf("  %-16s %14llu %14llu %12llu %12llu %12llu %14llu\n", label.c_str(),
                    (unsigned long long)c.vertexShaderInvocations, (unsigned long long)c.fragmentShaderInvocations,
                    (unsigned long long)c.primitivesSubmitted, (unsigned long long)c.clippingInputPrimitives,
                    (unsigned long long)c.clippingOutputPrimitives, (unsigned long long)c.samplesPassed);
    };
    for (const std::string& name : names)
        counterRow(std::string(size_t(passDepth(r.real, name)) * 2, ' ') + name, passTotal(r.real, name));
    if (!r.labels.empty())
        counterRow(kLabelsPass, passTotal(r.labels, kLabelsPass));
    printGpuWork(r);

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

    std::printf("\nThe project's goals (docs/PERFORMANCE.md, \"Goals\")\n");
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
    j["machine"] = {{"cpu", r.machine.cpu},
                    {"cores", r.machine.cores},
                    {"gl_renderer", r.machine.glRenderer},
                    {"gl_version", r.machine.glVersion}};
    j["commit"] = r.machine.commit;
    j["size"] = {r.size.x, r.size.y};
    j["pass_size"] = {r.passSize.x, r.passSize.y};
    j["output"] = r.output;
    j["surface"] = r.surface;
    j["grid_cells"] = r.gridCells;
    j["frames"] = r.frames;
    const double frameWall_ms = summarize(frameSeries(r.real, &FrameSample::wall_ms)).median;
    j["frames_per_second"] = frameWall_ms > 0.0 ? 1000.0 / frameWall_ms : 0.0; // from the median frame, wall
    j["simulation_cpu_ms"] = simulationCpuJson(r); // the calling thread's, by part (median, p95)
    j["warmup"] = r.warmup;
    j["frame_step_s"] = r.frameStep_s;
    j["pipeline_statistics"] = r.pipelineStatistics;
    j["gpu_timers"] = r.gpuTimers;

    Json reflectionModes = Json::object();
    for (const ReflectionModeCost& c : r.reflectionModes)
        reflectionModes[c.mode] = {{"water_wall_ms", summaryJson(summarize(c.waterWall_ms))},
                                   {"water_cpu_ms", summaryJson(summarize(c.waterCpu_ms))}};
    j["reflection_modes"] = reflectionModes;

    Json passes = Json::object();
    for (const std::string& name : passNames(r.real)) {
        const Summary realWall = summarize(passSeries(r.real, name, &PassSample::wall_ms));
        const Summary floorWall = summarize(passSeries(r.floor, name, &PassSample::wall_ms));
        const Summary realCpu = summarize(passSeries(r.real, name, &PassSample::cpu_ms));
        const Summary floorCpu = summarize(passSeries(r.floor, name, &PassSample::cpu_ms));
        const std::vector<double> gpu = passGpu(r.real, name);
        const std::string parent = passParent(r.real, name);
        Json& pass = passes[name];
        pass["inside"] = parent.empty() ? Json(nullptr) : Json(parent);
        pass["wall_ms"] = summaryJson(realWall);
        pass["cpu_ms"] = summaryJson(realCpu);
        pass["gpu_ms"] = gpu.empty() ? Json(nullptr) : summaryJson(summarize(gpu));
        // A pass the floor frame does not have (a wave model's stages): null.
        const bool inFloor = !passSeries(r.floor, name, &PassSample::wall_ms).empty();
        pass["floor_wall_ms"] = inFloor ? summaryJson(floorWall) : Json(nullptr);
        pass["floor_cpu_ms"] = inFloor ? summaryJson(floorCpu) : Json(nullptr);
        pass["real_over_floor"] = inFloor ? Json(ratio(realWall.median, floorCost(floorWall))) : Json(nullptr);
        pass["real_over_floor_cpu"] = inFloor ? Json(ratio(realCpu.median, floorCost(floorCpu))) : Json(nullptr);
        pass["counters_total"] = countersJson(passTotal(r.real, name), r.pipelineStatistics);
        pass["floor_counters_total"] = countersJson(passTotal(r.floor, name), r.pipelineStatistics);
    }
    j["passes"] = std::move(passes);
    j["floating_bodies"] = r.floatingBodies;
    j["body_steps_per_frame"] = r.bodySteps;
    j["wake_steps_per_frame"] = r.wakeSteps;
    j["wake_steps_ms_per_frame"] = r.wakeSteps_ms;

    const Summary frameReal = summarize(frameSeries(r.real, &FrameSample::wall_ms));
    const Summary frameFloor = summarize(frameSeries(r.floor, &FrameSample::wall_ms));
    const Summary frameRealCpu = summarize(frameSeries(r.real, &FrameSample::cpu_ms));
    const Summary frameFloorCpu = summarize(frameSeries(r.floor, &FrameSample::cpu_ms));
    j["frame"] = {{"wall_ms", summaryJson(frameReal)},
                  {"cpu_ms", summaryJson(frameRealCpu)},
                  {"floor_wall_ms", summaryJson(frameFloor)},
                  {"floor_cpu_ms", summaryJson(frameFloorCpu)},
                  {"real_over_floor", ratio(frameReal.median, floorCost(frameFloor))},
                  {"real_over_floor_cpu", ratio(frameRealCpu.median, floorCost(frameFloorCpu))}};

    // --labels: the label pass (null without), and the labelled sample it
    // makes with the colour frame.
    if (r.labels.empty()) {
        j["labels"] = nullptr;
    } else {
        const std::vector<double> gpu = passGpu(r.labels, kLabelsPass);
        j["labels"] = {{"wall_ms", summaryJson(summarize(passSeries(r.labels, kLabelsPass, &PassSample::wall_ms)))},
                       {"cpu_ms", summaryJson(summarize(passSeries(r.labels, kLabelsPass, &PassSample::cpu_ms)))},
                       {"gpu_ms", gpu.empty() ? Json(nullptr) : summaryJson(summarize(gpu))},
                       {"counters_total", countersJson(passTotal(r.labels, kLabelsPass), r.pipelineStatistics)},
                       {"labelled_sample",
                        {{"wall_ms", summaryJson(summarize(labelledSampleSeries(r, &FrameSample::wall_ms)))},
                         {"cpu_ms", summaryJson(summarize(labelledSampleSeries(r, &FrameSample::cpu_ms)))}}}};
        j["labels"]["flow"] =
            r.flow.empty() ? Json(nullptr)
                           : Json{{"wall_ms", summaryJson(summarize(passSeries(r.flow, kFlowPass, &PassSample::wall_ms)))},
                                  {"cpu_ms", summaryJson(summarize(passSeries(r.flow, kFlowPass, &PassSample::cpu_ms)))}};
    }

    j["sensor"] = r.sensor.empty()
                      ? Json(nullptr)
                      : Json{{"draws", r.sensorDraws},
                             {"wall_ms", summaryJson(summarize(passSeries(r.sensor, kSensorPass, &PassSample::wall_ms)))},
                             {"cpu_ms", summaryJson(summarize(passSeries(r.sensor, kSensorPass, &PassSample::cpu_ms)))}};

    j["motion_vectors"] =
        r.motionVectors.empty()
            ? Json(nullptr)
            : Json{{"draws", r.motionVectorCounters.front().motionVectorDraws},
                   {"triangles", r.motionVectorCounters.front().motionVectorTriangles},
                   {"wall_ms", summaryJson(summarize(passSeries(r.motionVectors, kMotionVectorsPass, &PassSample::wall_ms)))},
                   {"cpu_ms", summaryJson(summarize(passSeries(r.motionVectors, kMotionVectorsPass, &PassSample::cpu_ms)))}};

    Json lod = Json::array();
    for (const LodSample& s : r.lod) {
        Json sample;
        sample["frame"] = s.frame;
        sample["camera"] = cameraJson(s.camera);
        sample["triangles"] = s.triangles;
        sample["in_frustum"] = s.inFrustum;
        sample["in_frustum_share"] = s.inFrustumShare;
        if (s.clipShare) {
            sample["clip_input"] = s.clipInput;
            sample["clip_output"] = s.clipOutput;
            sample["clip_output_over_input"] = *s.clipShare;
        } else {
            sample["clip_output_over_input"] = nullptr;
        }
        sample["area_px2"] = {{"p10", s.areaP10_px2}, {"median", s.areaMedian_px2}, {"p90", s.areaP90_px2}};
        sample["longest_edge_median_px"] = s.edgeMedian_px;
        sample["sub_pixel_share"] = s.subPixelShare;
        lod.push_back(std::move(sample));
    }
    j["lod"] = std::move(lod);

    j["goals"] = {{"frame_real_over_floor_max", kGoalFrameRatio},
                  {"in_frustum_share_min", kGoalInFrustum},
                  {"median_area_px2", {kGoalMedianArea_px2[0], kGoalMedianArea_px2[1]}}};

    Json measured = Json::array();
    for (size_t i = 0; i < r.real.size(); ++i) {
        const FrameSample& f = r.real[i];
        Json frame;
        frame["index"] = int(i);
        if (i < r.realTimes_s.size())
            frame["time_s"] = r.realTimes_s[i];
        if (i < r.realCameras.size())
            frame["camera"] = cameraJson(r.realCameras[i]);
        frame["wall_ms"] = f.wall_ms;
        frame["cpu_ms"] = f.cpu_ms;
        // A pass run more than once in the frame (a wave model's stage): the sums.
        std::vector<PassSample> merged;
        for (const PassSample& p : f.passes) {
            auto same = std::find_if(merged.begin(), merged.end(), [&](const PassSample& m) { return m.name == p.name; });
            if (same == merged.end()) {
                merged.push_back(p);
                continue;
            }
            same->wall_ms += p.wall_ms;
            same->cpu_ms += p.cpu_ms;
            if (p.gpu_ms)
                same->gpu_ms = same->gpu_ms.value_or(0.0) + *p.gpu_ms;
            same->counters += p.counters;
        }
        Json framePasses = Json::object();
        for (const PassSample& p : merged)
            framePasses[p.name] = {{"wall_ms", p.wall_ms},
                                   {"cpu_ms", p.cpu_ms},
                                   {"gpu_ms", p.gpu_ms ? Json(*p.gpu_ms) : Json(nullptr)},
                                   {"counters", countersJson(p.counters, r.pipelineStatistics)}};
        frame["passes"] = std::move(framePasses);
        if (i < r.labels.size())
            if (const PassSample* p = r.labels[i].find(kLabelsPass))
                frame["labels"] = {{"wall_ms", p->wall_ms},
                                   {"cpu_ms", p->cpu_ms},
                                   {"gpu_ms", p->gpu_ms ? Json(*p->gpu_ms) : Json(nullptr)},
                                   {"counters", countersJson(p->counters, r.pipelineStatistics)}};
        if (i < r.counters.size()) {
            frame["simulation_cpu_ms"] = frameSimulationCpuJson(r.counters[i]);
            frame["gpu_work"] = frameGpuWorkJson(r.counters[i]);
            frame["culling"] = frameCullingJson(r.counters[i]);
        }
        measured.push_back(std::move(frame));
    }
    j["measured_frames"] = std::move(measured);
    j["water_terms"] = termsJson(r);

    std::ofstream out(path, std::ios::binary);
    out << j.dump(2) << '\n';
    if (!out)
        throw Error(fmt::format("swell bench: cannot write '{}'", path));
}

} // namespace swell::app::bench
