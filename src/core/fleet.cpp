// The fleet's design numbers from the embedded model files (core/fleet.h).
#include "core/fleet.h"

#include "embedded_files.h"
#include "swell/error.h"
#include "swell/scene/scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace swell::detail {

std::string_view fleetModelText(std::string_view name)
{
    const std::string path = fmt::format("fleet/{}.gltf", name);
    for (const EmbeddedFile& file : embeddedModelFiles())
        if (file.path == path)
            return file.text;
    throw Error(fmt::format("builtin:{}: the library was built without assets/models/{}", name, path));
}

const FleetDesign& fleetDesign(std::string_view name)
{
    static const std::map<std::string, FleetDesign, std::less<>> designs = [] {
        std::map<std::string, FleetDesign, std::less<>> all;
        for (std::string_view model : kFleetObjects) {
            const nlohmann::json doc = nlohmann::json::parse(fleetModelText(model));
            const nlohmann::json& root = doc.at("nodes").at(doc.at("scenes").at(0).at("nodes").at(0).get<std::size_t>());
            const nlohmann::json& e = root.at("extras");
            const nlohmann::json& c = e.at("center_of_mass_m");
            all[std::string(model)] = {e.at("length_m").get<double>(), e.at("beam_m").get<double>(),
                                       e.at("draft_m").get<double>(), e.at("displacement_kg").get<double>(),
                                       {c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>()}};
        }
        return all;
    }();
    const auto found = designs.find(name);
    if (found == designs.end())
        throw Error(fmt::format("builtin:{} is not one of the fleet", name));
    return found->second;
}

} // namespace swell::detail
