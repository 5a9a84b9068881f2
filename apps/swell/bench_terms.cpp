// What each term of the water shading costs: the water pass's CPU time with
// the term left out, against the full frame of the same camera and time.
#include "bench.h"

#include "swell/gpu/variants.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace swell::app::bench {

namespace {

const PassSample* waterOf(const FrameSample& frame) { return frame.find("water"); }

// Per frame, full minus variant, of a field of the water pass; frames
// without a water pass are skipped.
std::vector<double> savedPerFrame(const std::vector<FrameSample>& full, const std::vector<FrameSample>& variant,
                                  double PassSample::*field)
{
    std::vector<double> saved;
    for (size_t k = 0; k < full.size() && k < variant.size(); ++k)
        if (const PassSample *a = waterOf(full[k]), *b = waterOf(variant[k]); a && b)
            saved.push_back(a->*field - b->*field);
    return saved;
}

std::vector<double> waterSeries(const std::vector<FrameSample>& frames, double PassSample::*field)
{
    std::vector<double> values;
    for (const FrameSample& f : frames)
        if (const PassSample* w = waterOf(f))
            values.push_back(w->*field);
    return values;
}

// Water fragments shaded per frame (FS invocations of the water pass, or of
// its shading pass when it is drawn in two), median.
double fragmentsPerFrame(const std::vector<FrameSample>& frames)
{
    std::vector<double> values;
    for (const FrameSample& f : frames) {
        const PassSample* shading = f.find("water shading");
        if (const PassSample* w = shading ? shading : waterOf(f))
            values.push_back(double(w->counters.fragmentShaderInvocations));
    }
    return median(values);
}

struct TermRow {
    double waterCpu_ms, savedCpu_ms, savedShare, savedPerFragment_ns;
};

TermRow rowOf(const Results& r, const TermVariant& t)
{
    std::vector<double> fullCpu = waterSeries(r.real, &PassSample::cpu_ms);
    std::vector<double> variantCpu = waterSeries(t.frames, &PassSample::cpu_ms);
    std::vector<double> saved = savedPerFrame(r.real, t.frames, &PassSample::cpu_ms);
    const double full = median(fullCpu), fragments = fragmentsPerFrame(r.real);
    TermRow row{median(variantCpu), median(saved), 0.0, 0.0};
    row.savedShare = full > 0.0 ? row.savedCpu_ms / full : 0.0;
    row.savedPerFragment_ns = fragments > 0.0 ? row.savedCpu_ms * 1.0e6 / fragments : 0.0;
    return row;
}

} // namespace

std::vector<TermVariant> termVariants()
{
    return {{"wave normals", SWELL_TERM_WAVE_NORMALS, {}}, {"reflection", SWELL_TERM_REFLECTION, {}},
            {"refraction", SWELL_TERM_REFRACTION, {}},     {"lighting", SWELL_TERM_LIGHTING, {}},
            {"foam", SWELL_TERM_FOAM, {}},                 {"fog", SWELL_TERM_FOG, {}},
            {"subsurface", SWELL_TERM_SUBSURFACE, {}},     {"filtering", SWELL_TERM_FILTERING, {}},
            {"every term", SWELL_TERM_ALL, {}}};
}

void printTermReport(const Results& r)
{
    if (r.terms.empty())
        return;
    std::vector<double> fullCpu = waterSeries(r.real, &PassSample::cpu_ms);
    const double full = median(fullCpu), fragments = fragmentsPerFrame(r.real);
    std::printf("\nWater shading terms: the water pass with one term left out (its cheapest stand-in), each frame\n"
                "rendered right after the full frame of the same camera and time. saved: median over the frames\n"
                "of (full - without), CPU time. Full water pass: %.3f ms CPU, %.0f fragments, %.1f ns per fragment\n",
                full, fragments, fragments > 0.0 ? full * 1.0e6 / fragments : 0.0);
    std::printf("  %-14s %12s %10s %8s %12s\n", "left out", "water CPU ms", "saved ms", "saved", "ns/fragment");
    for (const TermVariant& t : r.terms) {
        const TermRow row = rowOf(r, t);
        std::printf("  %-14s %12.3f %10.3f %7.1f%% %12.1f\n", t.name.c_str(), row.waterCpu_ms, row.savedCpu_ms,
                    row.savedShare * 100.0, row.savedPerFragment_ns);
    }
    std::printf("  (terms share work, e.g. the lighting and the foam both use the normal, so the savings need not add up)\n");
    std::fflush(stdout);
}

nlohmann::ordered_json termsJson(const Results& r)
{
    nlohmann::ordered_json terms = nlohmann::ordered_json::array();
    for (const TermVariant& t : r.terms) {
        const TermRow row = rowOf(r, t);
        terms.push_back({{"left_out", t.name},
                         {"bits", t.omitted},
                         {"water_cpu_ms_median", row.waterCpu_ms},
                         {"saved_cpu_ms_median", row.savedCpu_ms},
                         {"saved_share", row.savedShare},
                         {"saved_ns_per_fragment", row.savedPerFragment_ns}});
    }
    return terms;
}

} // namespace swell::app::bench
