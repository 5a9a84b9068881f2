// `swell bench`: what the renderer counted of its own frame work
// (Renderer::counters()): the simulation's CPU time on the calling thread,
// by part, and Swell's GPU work (dispatches, barriers, mipmaps, bytes
// written, draw calls), for the table and the JSON file.
#include "bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace swell::app::bench {

namespace {

using Json = nlohmann::ordered_json;

// The simulation's CPU time parts, as the table and the JSON name them.
struct CpuPart {
    const char* label; // in the text
    const char* key;   // in the JSON
    double SimulationCpuTime::*field;
};
constexpr CpuPart kCpuParts[] = {
    {"model", "model", &SimulationCpuTime::model_ms},
    {"bodies and wake", "bodies", &SimulationCpuTime::bodies_ms},
    {"queries", "queries", &SimulationCpuTime::queries_ms},
    {"culling and uniforms", "views", &SimulationCpuTime::views_ms},
};

std::vector<double> cpuSeries(const Results& r, double SimulationCpuTime::*field)
{
    std::vector<double> out;
    for (const FrameCounters& c : r.counters)
        out.push_back(c.simulationCpu.*field);
    return out;
}

std::vector<double> totalSeries(const Results& r)
{
    std::vector<double> out;
    for (const FrameCounters& c : r.counters)
        out.push_back(c.simulationCpu.total_ms());
    return out;
}

// One GPU figure of each measured frame.
template <class Get>
std::vector<long long> gpuSeries(const Results& r, Get get)
{
    std::vector<long long> out;
    for (const FrameCounters& c : r.counters)
        out.push_back(get(c));
    return out;
}

// "median", or "median (min..max)" when the frames differ.
std::string perFrame(std::vector<long long> values)
{
    if (values.empty())
        return "-";
    std::sort(values.begin(), values.end());
    const long long median = values[values.size() / 2];
    if (values.front() == values.back())
        return std::to_string(median);
    return std::to_string(median) + " (" + std::to_string(values.front()) + ".." + std::to_string(values.back()) + ")";
}

struct GpuFigure {
    const char* label;
    const char* key;
    long long (*get)(const GpuWork&);
};
constexpr GpuFigure kGpuFigures[] = {
    {"dispatches", "dispatches", [](const GpuWork& w) { return (long long)w.dispatches; }},
    {"barriers", "barriers", [](const GpuWork& w) { return (long long)w.barriers; }},
    {"mipmaps", "mipmaps", [](const GpuWork& w) { return (long long)w.mipmaps; }},
    {"bytes written", "bytes_written", [](const GpuWork& w) { return w.bytesWritten; }},
};

Json gpuWorkJson(const GpuWork& w)
{
    Json j = Json::object();
    for (const GpuFigure& f : kGpuFigures)
        j[f.key] = f.get(w);
    return j;
}

} // namespace

void printSimulationCpuLine(const Results& r)
{
    const Summary total = summarize(totalSeries(r));
    std::printf("simulation CPU %.2f ms a frame (median; p95 %.2f), the calling thread's:", total.median, total.p95);
    const char* separator = " ";
    for (const CpuPart& part : kCpuParts) {
        const Summary s = summarize(cpuSeries(r, part.field));
        std::printf("%s%s %.2f (p95 %.2f)", separator, part.label, s.median, s.p95);
        separator = ", ";
    }
    std::printf("\n");
    // The bodies' worker thread (Renderer::anticipate): Swell's CPU time
    // too, told beside the calling thread's, never hidden.
    std::vector<double> ahead;
    for (const FrameCounters& c : r.counters)
        ahead.push_back(c.bodiesAheadCpu_ms);
    const Summary a = summarize(ahead);
    if (a.p95 > 0.0) {
        double sum = 0.0;
        for (double v : ahead)
            sum += v;
        std::printf("  and on the bodies' worker thread, stepping ahead of each frame while the one before was drawn: "
                    "%.2f ms a frame (median; p95 %.2f; mean %.2f)\n",
                    a.median, a.p95, sum / double(ahead.size()));
    }
    std::printf("  the frame's water queries: %s answered on the GPU, %s on the CPU (a model whose CPU queries "
                "are cheap, or a triangle beyond the GPU's block)\n",
                perFrame(gpuSeries(r, [](const FrameCounters& c) { return (long long)c.queriesOnGpu; })).c_str(),
                perFrame(gpuSeries(r, [](const FrameCounters& c) { return (long long)c.queriesOnCpu; })).c_str());
    // Exact, unlike the times beside it: a change to the culling shows here
    // whatever the machine's load.
    std::printf("  the views' culling: %s boxes of the water grid tested against the frustum a frame (blocks, "
                "quadtree nodes, tiles)\n",
                perFrame(gpuSeries(r, [](const FrameCounters& c) { return c.cullBoxesTested; })).c_str());
    // The contact pass (its time is the "contact" row above): drawn or left
    // out, which no load changes.
    std::printf("  the contact foam's pass: %s a frame, %s triangles of Swell's world (0: nothing of the world "
                "meets the water near the eye, or the sea is flat)\n",
                perFrame(gpuSeries(r, [](const FrameCounters& c) { return (long long)c.contactMaps; })).c_str(),
                perFrame(gpuSeries(r, [](const FrameCounters& c) { return c.contactTriangles; })).c_str());
}

void printGpuWork(const Results& r)
{
    std::printf("\nSwell's GPU work a frame, counted by the library where it makes the calls (exact: the same\n"
                "in every run and on every machine); the median frame, (least..most) when the frames differ\n");
    std::printf("  %-12s %12s %12s %12s %20s %12s\n", "part", "dispatches", "barriers", "mipmaps", "bytes written",
                "draw calls");
    for (const bool simulation : {true, false}) {
        const auto work = [simulation](const FrameCounters& c) -> const GpuWork& {
            return simulation ? c.simulationGpu : c.viewsGpu;
        };
        std::printf("  %-12s", simulation ? "simulation" : "views");
        for (const GpuFigure& f : kGpuFigures)
            std::printf(" %*s", f.key == std::string("bytes_written") ? 20 : 12,
                        perFrame(gpuSeries(r, [&](const FrameCounters& c) { return f.get(work(c)); })).c_str());
        std::printf(" %12s\n",
                    simulation ? "-" : perFrame(gpuSeries(r, [](const FrameCounters& c) {
                                     return (long long)c.drawCalls;
                                 })).c_str());
    }
    std::printf("  (simulation: Renderer::advanceTo, the wave model's frame; views: each view drawn. The\n"
                "   spectral model's bytes: the texels its dispatches write, the mipmap levels, clears)\n");
}

nlohmann::ordered_json simulationCpuJson(const Results& r)
{
    Json j = Json::object();
    j["total"] = {{"median", summarize(totalSeries(r)).median}, {"p95", summarize(totalSeries(r)).p95}};
    for (const CpuPart& part : kCpuParts) {
        const Summary s = summarize(cpuSeries(r, part.field));
        j[part.key] = {{"median", s.median}, {"p95", s.p95}};
    }
    std::vector<double> ahead;
    for (const FrameCounters& c : r.counters)
        ahead.push_back(c.bodiesAheadCpu_ms);
    const Summary a = summarize(ahead);
    // Not in "total": the bodies' worker thread's, not the calling thread's.
    j["bodies_ahead_worker"] = {{"median", a.median}, {"p95", a.p95}};
    return j;
}

nlohmann::ordered_json frameSimulationCpuJson(const FrameCounters& c)
{
    Json j = Json::object();
    j["total"] = c.simulationCpu.total_ms();
    for (const CpuPart& part : kCpuParts)
        j[part.key] = c.simulationCpu.*part.field;
    j["bodies_ahead_worker"] = c.bodiesAheadCpu_ms;
    j["queries_on_gpu"] = c.queriesOnGpu;
    j["queries_on_cpu"] = c.queriesOnCpu;
    return j;
}

nlohmann::ordered_json frameCullingJson(const FrameCounters& c)
{
    Json j = Json::object();
    j["boxes_tested"] = c.cullBoxesTested;
    return j;
}

nlohmann::ordered_json frameGpuWorkJson(const FrameCounters& c)
{
    Json j = Json::object();
    j["simulation"] = gpuWorkJson(c.simulationGpu);
    j["views"] = gpuWorkJson(c.viewsGpu);
    j["views"]["draw_calls"] = c.drawCalls;
    j["views"]["contact_maps"] = c.contactMaps;
    j["views"]["contact_triangles"] = c.contactTriangles;
    return j;
}

} // namespace swell::app::bench
