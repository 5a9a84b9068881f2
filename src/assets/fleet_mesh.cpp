// The fleet's models in a scene's look (assets/fleet_mesh.h).
#include "assets/fleet_mesh.h"

#include "core/fleet.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

namespace swell::detail {

namespace {

// Stretches a mesh along x and z; normals by the inverse transpose, so a
// side stays at right angles to its stretched surface.
void stretch(MeshData& mesh, double along, double across)
{
    const glm::vec3 scale(float(along), 1.0f, float(across));
    for (MeshVertex& v : mesh.vertices) {
        v.position *= scale;
        const glm::vec3 n = v.normal / scale;
        v.normal = glm::length(n) > 0.0f ? glm::normalize(n) : v.normal;
    }
}

void paint(nlohmann::json& doc, std::string_view material, const glm::dvec3& rgb)
{
    if (rgb.x < 0.0)
        return;
    for (nlohmann::json& m : doc.at("materials"))
        if (m.value("name", "") == material)
            m["pbrMetallicRoughness"]["baseColorFactor"] = {rgb.x, rgb.y, rgb.z, 1.0};
}

} // namespace

FleetLook fleetLookOf(const SceneObject& object)
{
    const FleetDesign& design = fleetDesign(std::string_view(object.path).substr(kBuiltinObjectPrefix.size()));
    FleetLook look;
    look.lengthScale = object.length_m > 0.0 ? object.length_m / design.length_m : 1.0;
    look.beamScale = object.beam_m > 0.0 ? object.beam_m / design.beam_m : 1.0;
    look.hullColor = object.hullColor;
    look.superstructureColor = object.superstructureColor;
    look.superstructure = object.superstructure;
    return look;
}

std::string fleetLookKey(const FleetLook& look)
{
    return fmt::format("{} {} {} {} {} {} {} {} {}", look.lengthScale, look.beamScale, look.hullColor.x,
                       look.hullColor.y, look.hullColor.z, look.superstructureColor.x, look.superstructureColor.y,
                       look.superstructureColor.z, look.superstructure);
}

GltfModel makeFleetModel(std::string_view name, const FleetLook& look)
{
    const std::string shown = fmt::format("builtin:{}", name);
    const std::string_view text = fleetModelText(name);
    GltfModel model;
    if (look.hullColor.x < 0.0 && look.superstructureColor.x < 0.0 && look.superstructure) {
        model = loadEmbeddedGltf(shown, text, "hull");
    } else {
        // Repainted or stripped: the script's file with its materials'
        // colours changed and the superstructure node's mesh taken away.
        nlohmann::json doc = nlohmann::json::parse(text);
        paint(doc, "hull", look.hullColor);
        paint(doc, "superstructure", look.superstructureColor);
        if (!look.superstructure)
            for (nlohmann::json& node : doc.at("nodes"))
                if (node.value("name", "") == "superstructure")
                    node.erase("mesh");
        model = loadEmbeddedGltf(shown, doc.dump(), "hull");
    }
    if (look.lengthScale != 1.0 || look.beamScale != 1.0) {
        stretch(model.mesh, look.lengthScale, look.beamScale);
        stretch(model.hull, look.lengthScale, look.beamScale);
    }
    return model;
}

} // namespace swell::detail
