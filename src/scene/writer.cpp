// Scenes as TOML text (saveScene in swell/scene/scene_file.h), written by hand
// section by section so the file reads like the docs: one key per line with
// its range in a comment.
#include "swell/scene/scene_file.h"

#include "swell/scene/parameters.h"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace swell {
namespace {


std::string tomlString(std::string_view s)
{
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\b': out += "\\b"; break;
        case '\t': out += "\\t"; break;
        case '\n': out += "\\n"; break;
        case '\f': out += "\\f"; break;
        case '\r': out += "\\r"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
            else
                out += c;
        }
    }
    return out + "\"";
}

// The table a single-valued parameter sits in: "waves.wind" for "waves.wind.speed_mps".
std::string_view tableOf(std::string_view key)
{
    auto dot = key.rfind('.');
    return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

void writeLine(std::string& out, std::string_view name, const std::string& value, const std::string& comment)
{
    std::string line = fmt::format("{} = {}", name, value);
    if (!comment.empty())
        line = fmt::format("{:<40} # {}", line, comment);
    out += line;
    out += '\n';
}

void writeParameters(std::string& out, const Scene& scene, std::string_view table, ParameterList list, std::size_t item)
{
    for (const Parameter& p : parameters()) {
        if (p.list != list || !isPresent(p, scene))
            continue;
        std::string_view owner = list == ParameterList::None ? tableOf(p.key) : listKey(list);
        if (owner != table)
            continue;
        std::string_view name = table.empty() ? p.key : p.key.substr(table.size() + 1);
        writeLine(out, name, formatValue(p, p.get(scene, item)), rangeText(p));
    }
}

// The sea floor, when the scene has one: its toe depth, each shape, its heightmap.
void writeSeabed(std::string& out, const Scene& scene)
{
    const SeabedSettings& seabed = scene.seabed;
    if (seabed.empty())
        return;
    out += "\n[seabed]\n";
    writeParameters(out, scene, "seabed", ParameterList::None, 0);
    const auto writeList = [&](ParameterList list, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            out += fmt::format("\n[[{}]]\n", listKey(list));
            writeParameters(out, scene, listKey(list), list, i);
        }
    };
    writeList(ParameterList::SeabedBeaches, seabed.beaches.size());
    writeList(ParameterList::SeabedShelves, seabed.shelves.size());
    writeList(ParameterList::SeabedBreakwaters, seabed.breakwaters.size());
    if (!seabed.heightmap.path.empty()) {
        out += "\n[seabed.heightmap]\n";
        writeLine(out, "path", tomlString(seabed.heightmap.path), "a grey PNG, 8 or 16 bits");
        writeParameters(out, scene, "seabed.heightmap", ParameterList::None, 0);
    }
}

} // namespace

std::string saveScene(const Scene& scene)
{
    std::string out = "# Swell scene. Every key is described in docs/SCENE.md; the comments give each range.\n\n";
    writeParameters(out, scene, "", ParameterList::None, 0);

    out += "\n[waves]\n";
    writeParameters(out, scene, "waves", ParameterList::None, 0);
    if (scene.sea.wind) {
        out += "\n[waves.wind]\n";
        writeParameters(out, scene, "waves.wind", ParameterList::None, 0);
        if (scene.sea.wind->swell) {
            out += "\n[waves.swell]\n";
            writeParameters(out, scene, "waves.swell", ParameterList::None, 0);
        }
    } else {
        for (std::size_t i = 0; i < scene.waves.listed.size(); ++i) {
            out += "\n[[waves.list]]\n";
            writeParameters(out, scene, "waves.list", ParameterList::Waves, i);
        }
    }

    // The other tables in the parameter table's order; the waves above and the
    // camera below (its path follows it) are written by hand.
    for (const std::string& table : parameterTables(ParameterList::None)) {
        if (table == "camera" || table == "waves" || table.starts_with("waves.") || table == "seabed"
            || table.starts_with("seabed."))
            continue;
        out += fmt::format("\n[{}]\n", table);
        if (table == "sky" && !scene.sky.cubemapFaces.empty()) {
            std::string faces = "[";
            for (std::size_t i = 0; i < scene.sky.cubemapFaces.size(); ++i)
                faces += (i > 0 ? ", " : "") + tomlString(scene.sky.cubemapFaces[i]);
            writeLine(out, "faces", faces + "]", "+x, -x, +y, -y, +z, -z");
        }
        writeParameters(out, scene, table, ParameterList::None, 0);
    }

    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        out += "\n[[objects]]\n";
        writeLine(out, "path", tomlString(scene.objects[i].path), "");
        if (!scene.objects[i].hullNode.empty())
            writeLine(out, "hull_node", tomlString(scene.objects[i].hullNode), "the glTF node of the closed hull volume");
        if (!scene.objects[i].className.empty())
            writeLine(out, "class", tomlString(scene.objects[i].className), "its class in the labels");
        writeParameters(out, scene, "objects", ParameterList::Objects, i);
    }

    writeSeabed(out, scene);

    out += "\n[camera]\n";
    writeParameters(out, scene, "camera", ParameterList::None, 0);
    for (std::size_t i = 0; i < scene.camera.path.size(); ++i) {
        out += "\n[[camera.path]]\n";
        writeParameters(out, scene, "camera.path", ParameterList::CameraPath, i);
    }
    for (std::size_t i = 0; i < scene.camera.rig.size(); ++i) {
        out += "\n[[camera.rig]]\n";
        writeLine(out, "name", tomlString(scene.camera.rig[i].name), "its files: NAME.<name>.png, ...");
        writeParameters(out, scene, "camera.rig", ParameterList::CameraRig, i);
    }
    return out;
}

} // namespace swell
