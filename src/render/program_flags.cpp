// Each program's flags as the #define lines its shaders read.
#include "render/program_flags.h"

#include "swell/gpu/variants.h"

#include <fmt/format.h>

namespace swell::detail {

namespace {

std::string flagDefine(const char* name, bool on) { return fmt::format("{} {}", name, on ? 1 : 0); }

std::string labelPassDefine(bool labelPass) { return flagDefine("SWELL_LABEL_PASS", labelPass); }

} // namespace

int debugViewDefine(DebugView v)
{
    switch (v) {
    case DebugView::Shaded: return SWELL_VIEW_SHADED;
    case DebugView::Normals: return SWELL_VIEW_NORMALS;
    case DebugView::Reflection: return SWELL_VIEW_REFLECTION;
    case DebugView::Refraction: return SWELL_VIEW_REFRACTION;
    case DebugView::Lod: return SWELL_VIEW_LOD;
    case DebugView::Wireframe: return SWELL_VIEW_WIREFRAME;
    case DebugView::Foam: return SWELL_VIEW_FOAM;
    }
    return SWELL_VIEW_SHADED;
}

void SurfaceFlags::addDefines(std::vector<std::string>& defines) const
{
    defines.push_back(fmt::format("SWELL_GRID_LAYOUT {}",
                                  gridLayout == GridLayout::Paper ? "SWELL_GRID_PAPER" : "SWELL_GRID_GEOMETRIC"));
    defines.push_back(fmt::format("SWELL_OCEAN_FILE \"{}\"", oceanFile));
    defines.push_back(fmt::format("SWELL_SURFACE_SOURCES {}", surfaceSources.size()));
    defines.push_back(flagDefine("SWELL_WATER_CACHES_VERTICES", cachesVertices));
}

void UnderwaterFlags::addDefines(std::vector<std::string>& defines) const
{
    defines.push_back(flagDefine("SWELL_CAUSTICS", caustics));
    defines.push_back(flagDefine("SWELL_SHAFTS", shafts));
    defines.push_back(flagDefine("SWELL_CLOUD_SHADOWS", cloudShadows));
    defines.push_back(flagDefine("SWELL_SEEN_FROM_BELOW", seenFromBelow));
}

std::vector<std::string> WaterFlags::defines() const
{
    std::vector<std::string> d{
        fmt::format("SWELL_DEBUG_VIEW {}", debugViewDefine(debugView)),
        fmt::format("SWELL_REFLECTION_MODE {}", reflection == ReflectionMode::FixedDistance ? "SWELL_REFLECTION_FIXED"
                                                                                              : "SWELL_REFLECTION_RAYMARCH"),
        fmt::format("SWELL_OMITTED_TERMS {}", omittedTerms),
        labelPassDefine(labelPass),
        flagDefine("SWELL_WATER_DEFERRED", deferred),
    };
    surface.addDefines(d);
    underwater.addDefines(d);
    return d;
}

std::vector<std::string> WaterlineFlags::defines() const
{
    std::vector<std::string> d;
    surface.addDefines(d);
    underwater.addDefines(d);
    return d;
}

std::vector<std::string> WaterVertexFlags::defines() const
{
    std::vector<std::string> d;
    surface.addDefines(d);
    return d;
}

std::vector<std::string> SkyFlags::defines() const
{
    std::vector<std::string> d{labelPassDefine(labelPass)};
    underwater.addDefines(d);
    return d;
}

std::vector<std::string> UnderwaterHostFlags::defines() const
{
    std::vector<std::string> d;
    underwater.addDefines(d);
    return d;
}

std::vector<std::string> MeshFlags::defines() const
{
    std::vector<std::string> d{fmt::format("SWELL_DEBUG_VIEW {}", debugViewDefine(debugView)),
                               labelPassDefine(labelPass), flagDefine("SWELL_MOTION_PASS", motionPass)};
    underwater.addDefines(d);
    return d;
}

std::vector<std::string> CausticsFlags::defines() const
{
    return {fmt::format("SWELL_OCEAN_FILE \"{}\"", oceanFile), flagDefine("SWELL_CAUSTICS", true)};
}

std::vector<std::string> CrestSprayFlags::defines() const
{
    return {fmt::format("SWELL_OCEAN_FILE \"{}\"", oceanFile), flagDefine("SWELL_CLOUD_SHADOWS", cloudShadows)};
}

std::vector<std::string> BowSprayFlags::defines() const
{
    return {"SWELL_BOW_SPRAY 1", flagDefine("SWELL_CLOUD_SHADOWS", cloudShadows)};
}

std::vector<std::string> SkyBakeFlags::defines() const { return {flagDefine("SWELL_SKY_PHYSICAL", physical)}; }

} // namespace swell::detail
