// Scenes: loading (a file, TOML text, the default), every value read and
// written through the parameter table (swell/scene/parameters.h), keyed as scene
// files and error messages write them ("fog.start_m", "objects[1].scale"),
// checked against the table's range on the way in; objects added and
// removed; the checks a renderer relies on; saving.
#include "bindings.h"
#include "convert.h"
#include "scene.h"

#include "swell/camera.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace swell::python {

namespace {

// A key as the user wrote it, resolved against the table and the scene.
struct ResolvedKey {
    const Parameter* parameter = nullptr;
    std::size_t item = 0;
};

// Every key this scene has a value for, list items spelt out.
std::vector<std::string> keysOf(const Scene& scene)
{
    std::vector<std::string> keys;
    for (const Parameter& p : parameters()) {
        if (p.list == ParameterList::None) {
            if (isPresent(p, scene))
                keys.emplace_back(p.key);
            continue;
        }
        const std::string_view list = listKey(p.list);
        const std::string_view rest = p.key.substr(list.size() + 1);
        for (std::size_t i = 0; i < listSize(scene, p.list); ++i)
            keys.push_back(std::string(list) + "[" + std::to_string(i) + "]." + std::string(rest));
    }
    return keys;
}

[[noreturn]] void unknownKey(const std::string& key)
{
    std::vector<std::string> known;
    for (const Parameter& p : parameters())
        known.emplace_back(p.key);
    const py::list close = py::module_::import("difflib").attr("get_close_matches")(key, known, 1);
    std::string message = key + ": no such scene key";
    if (!close.empty())
        message += "; did you mean " + close[0].cast<std::string>() + "?";
    throw py::key_error(message + " (swell.parameter_keys() lists them)");
}

// "objects[2].scale" -> objects.scale, item 2. Lists' parameters need the
// item; the others refuse one.
ResolvedKey resolveKey(const Scene& scene, const std::string& key)
{
    std::string tableKey = key;
    std::string listPart;
    std::size_t item = 0;
    const std::size_t open = key.find('[');
    if (open != std::string::npos) {
        const std::size_t close = key.find(']', open);
        const std::string digits = close == std::string::npos ? "" : key.substr(open + 1, close - open - 1);
        const bool wellFormed = close != std::string::npos && close + 2 < key.size() && key[close + 1] == '.'
                                && !digits.empty() && digits.size() <= 6
                                && std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); });
        if (!wellFormed)
            throw py::key_error(key + ": not a scene key; an item of a list is keyed like objects[0].scale");
        item = std::stoul(digits);
        listPart = key.substr(0, open);
        tableKey = listPart + "." + key.substr(close + 2);
    }
    const Parameter* p = findParameter(tableKey);
    if (!p)
        unknownKey(key);
    const std::string_view list = listKey(p->list);
    if (p->list == ParameterList::None) {
        if (!listPart.empty())
            throw py::key_error(key + ": " + tableKey + " is one value per scene, not a list's: write " + tableKey);
        return {p, 0};
    }
    if (listPart != list) {
        const std::string example = std::string(list) + "[0]." + std::string(p->key.substr(list.size() + 1));
        throw py::key_error(key + ": " + std::string(p->key) + " is one value per item of " + std::string(list)
                            + ": write " + example);
    }
    const std::size_t size = listSize(scene, p->list);
    if (item >= size)
        throw py::index_error(key + ": the scene has " + std::to_string(size) + " item" + (size == 1 ? "" : "s") + " in "
                              + std::string(list));
    return {p, item};
}

bool isBool(py::handle v)
{
    return py::isinstance<py::bool_>(v) || py::str(py::type::of(v).attr("__name__")).cast<std::string>() == "bool_";
}

std::string typeName(py::handle v) { return py::str(py::type::of(v).attr("__name__")); }

// The Python value as the parameter's alternative, checked against its range.
ParameterValue toParameterValue(const Parameter& p, py::handle v, const std::string& name)
{
    ParameterValue value;
    switch (p.kind) {
    case ParameterKind::Real:
        if (isBool(v) || !PyNumber_Check(v.ptr()) || !py::hasattr(v, "__float__"))
            throw py::type_error(name + ": expected a number" + (p.unit.empty() ? "" : " (" + std::string(p.unit) + ")")
                                 + ", got " + typeName(v));
        value = numberOf(v, name);
        break;
    case ParameterKind::Integer: {
        if (isBool(v) || !PyIndex_Check(v.ptr()))
            throw py::type_error(name + ": expected a whole number, got " + typeName(v));
        const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
        if (!index)
            throw py::error_already_set();
        int overflow = 0;
        const long long x = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
        if (overflow != 0)
            throw py::value_error(name + " is out of range; allowed " + rangeText(p));
        value = std::int64_t(x);
        break;
    }
    case ParameterKind::Flag:
        if (!isBool(v))
            throw py::type_error(name + ": expected True or False, got " + typeName(v));
        value = v.cast<bool>();
        break;
    case ParameterKind::Choice: {
        if (!py::isinstance<py::str>(v))
            throw py::type_error(name + ": expected one of " + rangeText(p) + ", got " + typeName(v));
        const std::string s = v.cast<std::string>();
        const auto found = std::find(p.choices.begin(), p.choices.end(), s);
        if (found == p.choices.end())
            throw py::value_error(name + " = \"" + s + "\" is not allowed; allowed " + rangeText(p));
        value = std::int64_t(found - p.choices.begin());
        break;
    }
    case ParameterKind::Colour:
    case ParameterKind::Direction3:
    case ParameterKind::Vector3:
        value = toVec3(v, name);
        break;
    case ParameterKind::Direction2:
    case ParameterKind::Vector2:
        value = toVec2(v, name);
        break;
    case ParameterKind::DateTime:
        // Seconds since 1970-01-01T00:00:00Z, as datetime.timestamp() gives.
        if (isBool(v) || !PyNumber_Check(v.ptr()) || !py::hasattr(v, "__float__"))
            throw py::type_error(name + ": expected seconds since 1970-01-01T00:00:00Z (datetime.timestamp()), got "
                                 + typeName(v));
        value = numberOf(v, name);
        break;
    }
    if (const std::string problem = valueProblem(p, value, name); !problem.empty())
        throw py::value_error(problem);
    return value;
}

py::object toPython(const Parameter& p, const ParameterValue& value)
{
    switch (p.kind) {
    case ParameterKind::Real:
    case ParameterKind::DateTime: return py::float_(std::get<double>(value));
    case ParameterKind::Integer: return py::int_(std::get<std::int64_t>(value));
    case ParameterKind::Flag: return py::bool_(std::get<bool>(value));
    case ParameterKind::Choice: {
        const std::int64_t i = std::get<std::int64_t>(value);
        return i >= 0 && std::size_t(i) < p.choices.size() ? py::str(std::string(p.choices[std::size_t(i)]))
                                                           : py::str("");
    }
    case ParameterKind::Colour:
    case ParameterKind::Direction3:
    case ParameterKind::Vector3: return toTuple(std::get<glm::dvec3>(value));
    case ParameterKind::Direction2:
    case ParameterKind::Vector2: return toTuple(std::get<glm::dvec2>(value));
    }
    return py::none();
}

py::object getValue(const PyScene& s, const std::string& key)
{
    const ResolvedKey k = resolveKey(s.scene, key);
    if (!isPresent(*k.parameter, s.scene))
        throw py::key_error(key + ": not used by this scene as it is (a waves.wind key when the waves are listed, "
                                  "a waves.swell key without a swell, a spectral key with the Gerstner model, a "
                                  "sun key of another form than the sun's: sun.direction, sun.elevation_deg with "
                                  "sun.azimuth_deg, or sun.time with its place); setting a waves.wind or waves.swell "
                                  "key turns that part on, and setting a sun key gives the sun that form");
    return toPython(*k.parameter, k.parameter->get(s.scene, k.item));
}

void setValue(PyScene& s, const std::string& key, py::handle value)
{
    const ResolvedKey k = resolveKey(s.scene, key);
    k.parameter->set(s.scene, k.item, toParameterValue(*k.parameter, value, key));
    // The file no longer says this value: a check that refuses it names the key, not the file's line.
    const Parameter& p = *k.parameter;
    const std::string_view list = listKey(p.list);
    s.scene.keyPlaces.erase(p.list == ParameterList::None
                                ? std::string(p.key)
                                : std::string(list) + "[" + std::to_string(k.item) + "]" + std::string(p.key.substr(list.size())));
}

// After objects[index] is removed the later objects move down one: the
// places of every object from there on no longer say where their keys are.
void forgetObjectPlaces(Scene& scene, std::size_t from)
{
    for (auto it = scene.keyPlaces.begin(); it != scene.keyPlaces.end();) {
        std::size_t item = 0;
        const bool object = it->first.starts_with("objects[") && std::sscanf(it->first.c_str(), "objects[%zu]", &item) == 1;
        it = object && item >= from ? scene.keyPlaces.erase(it) : std::next(it);
    }
}

std::string_view kindName(ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Real: return "real";
    case ParameterKind::Integer: return "integer";
    case ParameterKind::Flag: return "flag";
    case ParameterKind::Choice: return "choice";
    case ParameterKind::Colour: return "colour";
    case ParameterKind::Direction3: return "direction3";
    case ParameterKind::Vector3: return "vector3";
    case ParameterKind::Direction2: return "direction2";
    case ParameterKind::Vector2: return "vector2";
    case ParameterKind::DateTime: return "datetime";
    }
    return "";
}

py::dict describe(const Parameter& p)
{
    py::dict d;
    d["key"] = std::string(p.key);
    d["list"] = std::string(listKey(p.list));
    d["kind"] = std::string(kindName(p.kind));
    d["unit"] = std::string(p.unit);
    d["min"] = p.min;
    d["max"] = p.max;
    d["min_exclusive"] = p.minExclusive;
    d["range"] = rangeText(p);
    d["description"] = std::string(p.description);
    py::list choices;
    for (std::string_view c : p.choices)
        choices.append(std::string(c));
    d["choices"] = choices;
    d["default"] = toPython(p, p.defaultValue);
    return d;
}

} // namespace

void bindScene(py::module_& m)
{
    py::class_<PyScene>(m, "Scene",
                        "A scene: waves, grid, sun, sky, fog, water, objects and camera (docs/SCENE.md).\n\n"
                        "Values are read and written by their scene-file key through the parameter table, "
                        "which checks each against its unit's range:\n\n"
                        "    scene['waves.wind.speed_mps'] = 12.0\n"
                        "    scene['objects[0].position_m'] = (10.0, 0.0, -40.0)\n\n"
                        "An unknown key raises KeyError, a value of the wrong type TypeError, one out of "
                        "range ValueError naming the key and the range. Cross-field rules (fog.end_m > "
                        "fog.start_m) are checked by validate() and before rendering.")
        .def(py::init([] { return PyScene{defaultScene(), {}}; }), "The built-in default scene.")
        .def_property_readonly(
            "file", [](const PyScene& s) -> py::object { return s.file.empty() ? py::object(py::none()) : py::str(s.file); },
            "The scene file it was loaded from, or None.")
        .def("__getitem__", &getValue, py::arg("key"))
        .def("__setitem__", &setValue, py::arg("key"), py::arg("value"))
        .def("get", &getValue, py::arg("key"),
             "The value of `key` ('fog.start_m', 'objects[0].scale'): float, int, bool, str (a choice) "
             "or a tuple (a vector or colour).")
        .def("set", &setValue, py::arg("key"), py::arg("value"),
             "Sets `key` to `value`, checked against the parameter table's range.")
        .def("keys", [](const PyScene& s) { return keysOf(s.scene); },
             "Every key this scene has a value for, list items spelt out ('objects[0].scale').")
        .def("list_size", [](const PyScene& s, const std::string& list) {
                 for (ParameterList l : {ParameterList::Waves, ParameterList::Objects, ParameterList::CameraPath,
                                         ParameterList::CameraRig, ParameterList::SeabedBeaches, ParameterList::SeabedShelves,
                                         ParameterList::SeabedBreakwaters})
                     if (listKey(l) == list)
                         return listSize(s.scene, l);
                 throw py::key_error(list + ": not a list; the lists are waves.list, objects, camera.path, "
                                            "camera.rig, seabed.beaches, seabed.shelves, seabed.breakwaters");
             },
             py::arg("list"),
             "How many items the list 'waves.list', 'objects', 'camera.path', 'camera.rig' or a seabed's 'seabed.beaches', "
             "'seabed.shelves', 'seabed.breakwaters' holds.")
        .def("add_object",
             [](PyScene& s, const std::string& path) {
                 if (s.scene.objects.size() >= kMaxSceneObjects)
                     throw py::value_error("objects: a scene holds at most " + std::to_string(kMaxSceneObjects));
                 SceneObject object;
                 object.path = path;
                 s.scene.objects.push_back(object);
                 return s.scene.objects.size() - 1;
             },
             py::arg("path"),
             "Adds an object ('builtin:boat', 'builtin:buoy', 'builtin:rock', one of the fleet such as "
             "'builtin:tug' (docs/SCENE.md), or a .gltf/.glb path relative "
             "to the scene's folder) at the origin and returns its index; set its keys with "
             "scene['objects[i]....']. The model is read when a renderer takes the scene.")
        .def("remove_object",
             [](PyScene& s, std::size_t index) {
                 if (index >= s.scene.objects.size())
                     throw py::index_error("objects[" + std::to_string(index) + "]: the scene has "
                                           + std::to_string(s.scene.objects.size()) + " objects");
                 s.scene.objects.erase(s.scene.objects.begin() + std::ptrdiff_t(index));
                 forgetObjectPlaces(s.scene, index);
             },
             py::arg("index"), "Removes objects[index]; later objects move down one.")
        .def("object_path", [](const PyScene& s, std::size_t index) {
                 if (index >= s.scene.objects.size())
                     throw py::index_error("objects[" + std::to_string(index) + "]: the scene has "
                                           + std::to_string(s.scene.objects.size()) + " objects");
                 return s.scene.objects[index].path;
             },
             py::arg("index"), "The model path of objects[index] as the scene names it.")
        .def("validate", [](const PyScene& s) { validateScene(s.scene, s.placeForErrors()); },
             "Checks what a renderer relies on: every value in range, the cross-field rules, the files "
             "the scene names, the wave set. Raises swell.InputError naming the key.")
        .def("camera_at", [](const PyScene& s, double time_s) { return cameraAt(s.scene.camera, frameTime(time_s)); },
             py::arg("time_s") = 0.0, "The scene's camera at time_s: its fixed pose, or its path interpolated.")
        .def("to_toml", [](const PyScene& s) { return saveScene(s.scene); },
             "The scene as scene-file TOML, every value with its unit and range in a comment.")
        .def("save", [](const PyScene& s, const std::filesystem::path& path) { saveSceneFile(s.scene, path); }, py::arg("path"),
             "Writes to_toml() to `path` atomically. Relative model paths are written as they are.")
        .def("copy", [](const PyScene& s) { return s; }, "An independent copy.")
        .def("__copy__", [](const PyScene& s) { return s; })
        .def("__deepcopy__", [](const PyScene& s, py::handle) { return s; }, py::arg("memo"))
        .def("__repr__", [](const PyScene& s) {
            return "<swell.Scene " + (s.file.empty() ? std::string("built in Python") : "from " + s.file) + ", "
                   + std::to_string(s.scene.objects.size()) + " objects>";
        });

    m.def("default_scene", [] { return PyScene{defaultScene(), {}}; },
          "The built-in default scene: an open ocean under a trade wind, with an island.");
    m.def(
        "load_scene",
        [](const std::filesystem::path& path) { return PyScene{loadScene(path), path.string()}; },
        py::arg("path"),
        "Reads and checks a scene file (TOML, docs/SCENE.md). Raises swell.InputError whose message "
        "starts with 'path:line:column:' for anything wrong in it.");
    m.def("parse_scene", [](const std::string& toml, const std::filesystem::path& path) {
              return PyScene{parseScene(toml, path), path.string()};
          },
          py::arg("toml"), py::arg("path") = "<string>",
          "Reads scene TOML held in a string; `path` names it in errors and is the folder relative "
          "model paths are found from.");
    m.def("parameter_keys", [] {
              std::vector<std::string> keys;
              for (const Parameter& p : parameters())
                  keys.emplace_back(p.key);
              return keys;
          },
          "Every key of the parameter table, as the table writes it ('objects.scale' is "
          "'objects[i].scale' in a scene).");
    m.def("parameter", [](const std::string& key) {
              // "objects[3].scale" describes objects.scale: strip the item.
              std::string tableKey = key;
              if (const std::size_t open = key.find('['), close = key.find("]."); open != std::string::npos
                                                                                 && close != std::string::npos && close > open)
                  tableKey = key.substr(0, open) + "." + key.substr(close + 2);
              const Parameter* p = findParameter(tableKey);
              if (!p)
                  unknownKey(key);
              return describe(*p);
          },
          py::arg("key"),
          "What the parameter table says of `key`: its kind, unit, min, max, range in words, "
          "description, choices and default.");
}

} // namespace swell::python
