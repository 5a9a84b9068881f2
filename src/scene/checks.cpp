// The scene as a whole (checks.h).
#include "scene/checks.h"

#include "core/asset_path.h"
#include "core/fleet.h"
#include "core/input_file.h"
#include "core/seabed_shapes.h"
#include "swell/dataset/labels.h"
#include "swell/gpu/limits.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace swell::detail::scenefile {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------
// Step 4: the scene as a whole.

// The key of parameter p for one item, as the user sees it: "objects[2].scale".
std::string shownKey(const Parameter& p, std::size_t item)
{
    if (p.list == ParameterList::None)
        return std::string(p.key);
    std::string_view list = listKey(p.list);
    return fmt::format("{}[{}]{}", list, item, p.key.substr(list.size()));
}

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// A file the scene refers to must lie in the scene's folder (or below it),
// exist, and be a regular file that can be read now, so that the renderer
// does not find out halfway through loading. `base` is the folder as given,
// `resolved` the same with links followed (resolvedFolder).
void checkFile(const fs::path& base, const fs::path& resolved, const std::string& relative, const std::string& name,
               const SourcePlace& place)
{
    const std::optional<fs::path> inside = resolveInside(resolved, relative);
    if (!inside)
        fail(place, fmt::format("{}: '{}' lies outside the scene's folder '{}'; a scene may name only files in its "
                                "folder or below it, links included",
                                name, shortText(relative), base.string()));
    const fs::path file = fs::path(relative).is_absolute() ? fs::path(relative) : base / relative;
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (fs::is_directory(status))
        fail(place, fmt::format("{}: '{}' is a folder, not a file", name, shortText(file.string())));
    if (!fs::exists(status) && !fs::is_symlink(fs::symlink_status(file, ec)))
        fail(place, fmt::format("{}: file '{}' not found (relative paths start at the scene file's folder)", name,
                                shortText(file.string())));
    try {
        checkInputFile(file, "file");
    } catch (const InputError& e) {
        fail(place, fmt::format("{}: '{}': {}", name, shortText(file.string()), e.message()));
    }
}

// An object's class (empty: its model's name) names no class the labels
// give the sea, the sky or the island: one id a name in the labels and COCO.
void checkClass(const SceneObject& o, std::size_t i, const Places& places)
{
    if (o.className.empty())
        return;
    const std::string key = fmt::format("objects[{}].class", i);
    if (hasControlCharacter(o.className))
        fail(places.first({key, fmt::format("objects[{}]", i)}), fmt::format("{} contains a control character", key));
    std::vector<std::string> fixed = labelClassesOf(Scene{});
    std::erase(fixed, std::string());
    if (std::find(fixed.begin(), fixed.end(), o.className) != fixed.end())
        fail(places.first({key, fmt::format("objects[{}]", i)}),
             fmt::format("{} = \"{}\" is the name of a class the labels give to what is not an object ({}); name "
                         "the object's own",
                         key, o.className, fmt::join(fixed, ", ")));
}

// The rig's cameras (docs/SCENE.md, [[camera.rig]]): each named, its name
// usable in its files' names and its own (two cameras of one name would
// write the same files), its field of view the [camera]'s (0) or a lens's.
void checkRig(const std::vector<RigCamera>& rig, const Places& places)
{
    if (rig.size() > kMaxRigCameras)
        fail(places.first({"camera.rig", "camera"}),
             fmt::format("camera.rig has {} cameras; at most {} are allowed", rig.size(), kMaxRigCameras));
    for (std::size_t i = 0; i < rig.size(); ++i) {
        const std::string item = fmt::format("camera.rig[{}]", i);
        const std::string& name = rig[i].name;
        const bool allowed = std::all_of(name.begin(), name.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
        });
        if (name.empty() || name.size() > 32 || !allowed)
            fail(places.first({item + ".name", item, "camera.rig"}),
                 fmt::format("{}.name = \"{}\": a rig camera's name is part of its files' names: 1 to 32 letters, "
                             "digits, '_' or '-'",
                             item, shortText(name)));
        for (std::size_t j = 0; j < i; ++j)
            if (rig[j].name == name) {
                const std::string other = fmt::format("camera.rig[{}].name", j);
                const std::string where = places.has(other) ? fmt::format(" (at {})", places.at(other).str()) : "";
                fail(places.first({item + ".name", item, "camera.rig"}),
                     fmt::format("{}.name = \"{}\": {} has that name too{}; each camera of a rig needs its own "
                                 "name, which its files carry",
                                 item, name, other, where));
            }
    }
}

// A floating object's body keys agree: it gives its mass one way, and its
// inertia is a solid's. On an object that does not float they mean nothing
// (docs/SCENE.md) and are left as they are, like every key a scene does not
// use, so a viewer can turn floats on and off without losing them.
void checkBody(const SceneObject& o, std::size_t i, const Places& places)
{
    const std::string item = fmt::format("objects[{}]", i);
    if (!o.hullNode.empty() && o.path.starts_with(kBuiltinObjectPrefix))
        fail(places.first({item + ".hull_node", item}),
             fmt::format("{}.hull_node names a node of a glTF file; the built-in '{}' brings its own hull", item,
                         o.path));
    if (!o.floats)
        return;
    if (o.mass_kg > 0.0 && o.density_kg_per_m3 > 0.0)
        fail(places.first({item + ".density_kg_per_m3", item + ".mass_kg", item}),
             fmt::format("{} gives both mass_kg ({} kg) and density_kg_per_m3 ({} kg/m^3); give one, the other "
                         "follows from the model's volume",
                         item, o.mass_kg, o.density_kg_per_m3));
    const glm::dvec3 I = o.inertia_kg_m2;
    const bool given = I.x > 0.0 || I.y > 0.0 || I.z > 0.0;
    if (given && !(I.x > 0.0 && I.y > 0.0 && I.z > 0.0))
        fail(places.first({item + ".inertia_kg_m2", item}),
             fmt::format("{}.inertia_kg_m2 = [{}, {}, {}]: give all three principal moments > 0, or [0, 0, 0] to "
                         "take them from the mesh",
                         item, I.x, I.y, I.z));
    if (given && (I.x + I.y < I.z || I.y + I.z < I.x || I.z + I.x < I.y))
        fail(places.first({item + ".inertia_kg_m2", item}),
             fmt::format("{}.inertia_kg_m2 = [{}, {}, {}] is no solid's: each principal moment must be at most the "
                         "sum of the other two",
                         item, I.x, I.y, I.z));
}

// The fleet's keys (docs/SCENE.md, "The fleet"): only on one of the fleet,
// stretched within its bounds, painted in colours or left at the model's own.
void checkFleet(const SceneObject& o, std::size_t i, const Places& places)
{
    const std::string item = fmt::format("objects[{}]", i);
    const auto refuse = [&](const std::string& key, const std::string& message) {
        fail(places.first({item + "." + key, item}), fmt::format("{}.{} {}", item, key, message));
    };
    if (!isFleetPath(o.path)) {
        const std::string fleet = fmt::format("builtin:{}", fmt::join(kFleetObjects, ", builtin:"));
        const std::string why =
            fmt::format("is for the fleet's built-ins, which carry their design's length, beam, draft and paints "
                        "({}); '{}' is not one of them",
                        fleet, o.path);
        if (o.length_m > 0.0)
            refuse("length_m", why);
        if (o.beam_m > 0.0)
            refuse("beam_m", why);
        if (o.hullColor != glm::dvec3(-1.0))
            refuse("hull_color", why);
        if (o.superstructureColor != glm::dvec3(-1.0))
            refuse("superstructure_color", why);
        if (!o.superstructure)
            refuse("superstructure", why);
        return;
    }
    const FleetDesign& design = fleetDesign(std::string_view(o.path).substr(kBuiltinObjectPrefix.size()));
    const auto stretch = [&](const char* key, double value_m, double design_m, const double (&range)[2]) {
        if (value_m > 0.0 && (value_m < range[0] * design_m || value_m > range[1] * design_m))
            refuse(key, fmt::format("= {} m is outside {:.3g} to {:.3g} m: {} to {} times the design's {} m of {} "
                                    "(0: the design's)",
                                    value_m, range[0] * design_m, range[1] * design_m, range[0], range[1], design_m,
                                    o.path));
    };
    stretch("length_m", o.length_m, design.length_m, kFleetLengthRange);
    stretch("beam_m", o.beam_m, design.beam_m, kFleetBeamRange);
    const auto colour = [&](const char* key, const glm::dvec3& rgb) {
        const bool own = rgb == glm::dvec3(-1.0);
        const bool paint = rgb.x >= 0.0 && rgb.y >= 0.0 && rgb.z >= 0.0 && rgb.x <= 1.0 && rgb.y <= 1.0 && rgb.z <= 1.0;
        if (!own && !paint)
            refuse(key, fmt::format("= [{}, {}, {}]: give a linear RGB colour, each channel 0..1, or [-1, -1, -1] for "
                                    "the model's own",
                                    rgb.x, rgb.y, rgb.z));
    };
    colour("hull_color", o.hullColor);
    colour("superstructure_color", o.superstructureColor);
}

void checkObjectPath(const fs::path& base, const fs::path& resolved, const std::string& path, const std::string& name,
                     const SourcePlace& place)
{
    if (path.empty())
        fail(place, fmt::format("{} is empty; it must name a file", name));
    if (path.starts_with(kBuiltinObjectPrefix)) {
        std::string_view builtin = std::string_view(path).substr(kBuiltinObjectPrefix.size());
        if (std::find(kBuiltinObjects.begin(), kBuiltinObjects.end(), builtin) != kBuiltinObjects.end())
            return;
        std::string known;
        for (std::string_view b : kBuiltinObjects)
            known += fmt::format("{}\"{}{}\"", known.empty() ? "" : ", ", kBuiltinObjectPrefix, b);
        fail(place, fmt::format("{} = \"{}\" is not a built-in object; the built-ins are {}", name, shortText(path), known));
    }
    std::string extension = lowercase(fs::path(path).extension().string());
    if (extension != ".gltf" && extension != ".glb")
        fail(place, fmt::format("{} = \"{}\" is not a glTF model; use a .gltf or .glb file, or \"builtin:NAME\"", name,
                                shortText(path)));
    checkFile(base, resolved, path, name, place);
}

void checkWaves(const Scene& scene, const Places& places)
{
    if (scene.waves.model == WaveModelKind::Spectral && !scene.sea.wind)
        fail(places.first({"waves.model", "waves"}),
             "waves.model = \"spectral\" samples the wind's spectrum: add a [waves.wind] table");
    if (scene.waves.listed.size() > SWELL_MAX_WAVES)
        fail(places.first({"waves.list", "waves"}),
             fmt::format("waves.list has {} waves; at most {} are allowed", scene.waves.listed.size(), SWELL_MAX_WAVES));
    SourcePlace place = scene.sea.wind ? places.first({"waves.wind", "waves"}) : places.first({"waves.list", "waves"});
    const char* source = scene.sea.wind ? "the waves generated from waves.wind" : "waves.list";
    WaveSet waves;
    try {
        waves = resolveWaves(scene);
    } catch (const InputError& e) {
        fail(place, fmt::format("{}: {}", source, e.message()));
    } catch (const std::invalid_argument& e) {
        fail(place, fmt::format("{}: {}", source, e.what()));
    }
    if (std::string problem = validate(waves); !problem.empty())
        fail(place, fmt::format("{} are not usable: {}", source, problem));
}

// The sea floor's lists within their limits, no breakwater without a
// length, and the heightmap's file (when `files`) in the scene's folder. Its
// image is read with the scene's other assets (swell::Seabed), which report
// a file that is not a grey image at this key too. A seabed that stands
// above the camera, or above the whole sea, is allowed: a camera may stand
// on land, and a lake may be all shallows.
void checkSeabed(const Scene& scene, const Places& places, const fs::path& base, bool files)
{
    const SeabedSettings& seabed = scene.seabed;
    for (ParameterList list : {ParameterList::SeabedBeaches, ParameterList::SeabedShelves, ParameterList::SeabedBreakwaters})
        if (listSize(scene, list) > kMaxSeabedShapes)
            fail(places.first({std::string(listKey(list)), "seabed"}),
                 fmt::format("{} has {} entries; at most {} are allowed", listKey(list), listSize(scene, list),
                             kMaxSeabedShapes));
    if (const auto problem = seabedShapeProblem(seabed))
        fail(places.first({problem->key, problem->key.substr(0, problem->key.rfind('.')), "seabed"}), problem->message);
    // A heightmap's keys mean nothing without its image (an empty
    // [seabed.heightmap] is no heightmap, as an empty scene is no scene).
    if (seabed.heightmap.path.empty())
        for (const Parameter& p : parameters())
            if (p.key.starts_with("seabed.heightmap.") && places.has(p.key))
                fail(places.at(p.key),
                     fmt::format("{} sets a heightmap without an image: seabed.heightmap needs a path, a grey PNG "
                                 "(8 or 16 bits) whose black and white are black_height_m and white_height_m",
                                 p.key));
    if (!files || seabed.heightmap.path.empty())
        return;
    const std::string name = "seabed.heightmap.path";
    if (hasControlCharacter(seabed.heightmap.path))
        fail(places.at(name), fmt::format("{} contains a control character", name));
    checkFile(base, resolvedFolder(base), seabed.heightmap.path, name, places.at(name));
}

// A scene sets the coefficients of its lens's model only (docs/SCENE.md,
// "The lens"): a fisheye's beside Brown-Conrady's would be silently unused.
void checkLensModel(const CameraSettings& camera, const Places& places)
{
    const bool fisheye = camera.lens == LensModel::KannalaBrandt;
    const std::pair<const char*, double> others[] = {
        {"camera.distortion_k1", camera.distortionK1}, {"camera.distortion_k2", camera.distortionK2},
        {"camera.distortion_k3", camera.distortionK3}, {"camera.distortion_p1", camera.distortionP1},
        {"camera.distortion_p2", camera.distortionP2}, {"camera.fisheye_k1", camera.fisheyeK1},
        {"camera.fisheye_k2", camera.fisheyeK2},       {"camera.fisheye_k3", camera.fisheyeK3},
        {"camera.fisheye_k4", camera.fisheyeK4}};
    for (const auto& [key, value] : others) {
        const bool fisheyeKey = std::string_view(key).starts_with("camera.fisheye_");
        if (value == 0.0 || fisheyeKey == fisheye)
            continue;
        fail(places.first({key, "camera.lens", "camera"}),
             fisheye ? fmt::format("{} = {:g}: a Brown-Conrady coefficient, but camera.lens = \"kannala_brandt\" "
                                   "(a fisheye takes camera.fisheye_k1 .. k4)",
                                   key, value)
                     : fmt::format("{} = {:g}: a Kannala-Brandt fisheye's coefficient, but camera.lens is "
                                   "\"brown_conrady\" (the default); set camera.lens = \"kannala_brandt\" for a "
                                   "fisheye, or use camera.distortion_*",
                                   key, value));
    }
}

} // namespace

void checkScene(const Scene& scene, const Places& places, const fs::path& base, ParameterEffect scope)
{
    // Every parameter in range (the reader checked values as it read them;
    // this is for scenes built in code).
    for (const Parameter& p : parameters()) {
        if (!isPresent(p, scene))
            continue;
        std::size_t count = listSize(scene, p.list);
        for (std::size_t i = 0; i < count; ++i) {
            std::string name = shownKey(p, i);
            if (std::string problem = valueProblem(p, p.get(scene, i), name); !problem.empty())
                fail(places.at(name), problem);
        }
    }

    if (scene.objects.size() > kMaxSceneObjects)
        fail(places.at("objects"),
             fmt::format("objects has {} entries; at most {} are allowed", scene.objects.size(), kMaxSceneObjects));
    if (scene.camera.path.size() > kMaxCameraKeys)
        fail(places.at("camera.path"),
             fmt::format("camera.path has {} keys; at most {} are allowed", scene.camera.path.size(), kMaxCameraKeys));

    // Cross-field rules: reported at the second key when the file has it,
    // since that is usually the one to change.
    if (!(scene.grid.fadeEnd_m > scene.grid.fadeStart_m))
        fail(places.first({"grid.fade_end_m", "grid.fade_start_m", "grid"}),
             fmt::format("grid.fade_end_m ({} m) must be greater than grid.fade_start_m ({} m)", scene.grid.fadeEnd_m,
                         scene.grid.fadeStart_m));
    if (scene.grid.fadeEnd_m > scene.grid.radius_m)
        fail(places.first({"grid.fade_end_m", "grid.radius_m", "grid"}),
             fmt::format("grid.fade_end_m ({} m) must not exceed grid.radius_m ({} m): the waves would stop at the "
                         "grid's edge instead of fading out",
                         scene.grid.fadeEnd_m, scene.grid.radius_m));
    if (!(scene.fog.end_m > scene.fog.start_m))
        fail(places.first({"fog.end_m", "fog.start_m", "fog"}),
             fmt::format("fog.end_m ({} m) must be greater than fog.start_m ({} m)", scene.fog.end_m, scene.fog.start_m));
    if (const int mount = scene.camera.mountObject; mount >= 0) {
        if (std::size_t(mount) >= scene.objects.size())
            fail(places.first({"camera.mount_object", "camera"}),
                 fmt::format("camera.mount_object = {}: the scene has {} object(s) (indices from 0)", mount,
                             scene.objects.size()));
        const SceneObject& o = scene.objects[std::size_t(mount)];
        if (o.floats && !o.isRigidBody())
            fail(places.first({"camera.mount_object", "camera"}),
                 fmt::format("camera.mount_object = {}: objects[{}] floats without being a rigid body (it sits on "
                             "the drawn water, which depends on the view); give it mass_kg or density_kg_per_m3, "
                             "or mount the camera on a rigid body or a fixed object",
                             mount, mount));
    }
    checkLensModel(scene.camera, places);
    if (!(scene.camera.far_m > scene.camera.near_m))
        fail(places.first({"camera.far_m", "camera.near_m", "camera"}),
             fmt::format("camera.far_m ({} m) must be greater than camera.near_m ({} m)", scene.camera.far_m,
                         scene.camera.near_m));
    checkRig(scene.camera.rig, places);
    for (std::size_t i = 1; i < scene.camera.path.size(); ++i)
        if (!(scene.camera.path[i].time_s > scene.camera.path[i - 1].time_s)) {
            std::string name = fmt::format("camera.path[{}].time_s", i);
            fail(places.at(name), fmt::format("{} ({} s) must be later than camera.path[{}].time_s ({} s): keys are "
                                              "sorted by time",
                                              name, scene.camera.path[i].time_s, i - 1, scene.camera.path[i - 1].time_s));
        }

    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        checkBody(scene.objects[i], i, places);
        checkClass(scene.objects[i], i, places);
        checkFleet(scene.objects[i], i, places);
    }

    checkSeabed(scene, places, base, hasEffect(scope, ParameterEffect::World) || hasEffect(scope, ParameterEffect::Seabed));
    if (hasEffect(scope, ParameterEffect::Waves))
        checkWaves(scene, places);
    if (!hasEffect(scope, ParameterEffect::World))
        return;

    // Referenced files.
    const bool namesFiles = !scene.sky.cubemapFaces.empty() ||
                            std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
                                return !o.path.starts_with(kBuiltinObjectPrefix);
                            });
    const fs::path resolved = namesFiles ? resolvedFolder(base) : fs::path();
    const auto& faces = scene.sky.cubemapFaces;
    if (!faces.empty() && faces.size() != 6)
        fail(places.at("sky.faces"), fmt::format("sky.faces must list 6 image paths, or none; it lists {}", faces.size()));
    for (std::size_t i = 0; i < faces.size(); ++i) {
        std::string name = fmt::format("sky.faces[{}]", i);
        if (faces[i].empty() || hasControlCharacter(faces[i]))
            fail(places.at(name), fmt::format("{} must name a file", name));
        checkFile(base, resolved, faces[i], name, places.at(name));
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        std::string name = fmt::format("objects[{}].path", i);
        if (hasControlCharacter(scene.objects[i].path))
            fail(places.at(name), fmt::format("{} contains a control character", name));
        checkObjectPath(base, resolved, scene.objects[i].path, name, places.at(name));
    }

}

fs::path baseFolder(const fs::path& sceneFile)
{
    fs::path base = sceneFile.parent_path();
    return base.empty() ? fs::path(".") : base;
}

} // namespace swell::detail::scenefile
