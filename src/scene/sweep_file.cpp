// Sweep files (swell/dataset/sweep.h): read with the scene files' TOML steps
// (scene/toml_text.h), their keys resolved in the parameter table, and each
// sample drawn from per-key random streams.
#include "swell/dataset/sweep.h"

#include "core/asset_path.h"
#include "core/counter_random.h"
#include "core/input_file.h"
#include "scene/checks.h"
#include "scene/places.h"
#include "scene/suggestions.h"
#include "scene/toml_text.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace swell {

namespace fs = std::filesystem;
using detail::scenefile::fail;
using detail::scenefile::Places;

namespace {

const std::vector<std::string> kTopKeys{"scene", "count", "seed", "size", "time_s", "labels", "clip", "vary"};
const std::vector<std::string> kClipKeys{"frames", "fps"};

// A key as written, resolved: its parameter and list item.
struct ResolvedKey {
    const Parameter* parameter = nullptr;
    std::size_t item = 0;
};

// The sun's angles, which a sweep may vary on a base scene that gives its
// sun in any form (the sample's sun is then given by its angles).
bool isSunAngle(const Parameter& p)
{
    return p.key == "sun.elevation_deg" || p.key == "sun.azimuth_deg";
}

std::optional<ResolvedKey> resolve(std::string_view key)
{
    // "objects[1].yaw_deg" -> "objects.yaw_deg", item 1.
    std::string dotted(key);
    std::size_t item = 0;
    if (const std::size_t open = key.find('['); open != std::string_view::npos) {
        const std::size_t close = key.find(']', open);
        if (close == std::string_view::npos)
            return std::nullopt;
        const std::string_view digits = key.substr(open + 1, close - open - 1);
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), item);
        if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
            return std::nullopt;
        dotted = std::string(key.substr(0, open)) + std::string(key.substr(close + 1));
    }
    const Parameter* p = findParameter(dotted);
    if (!p || (p->list == ParameterList::None) != (key.find('[') == std::string_view::npos))
        return std::nullopt;
    return ResolvedKey{p, item};
}

ParameterKind kindOf(const ResolvedKey& k) { return k.parameter->kind; }

// The key as a scene file writes it ("objects[1].yaw_deg", whatever the
// sweep wrote as "objects[01].yaw_deg"): Scene::keyPlaces' spelling.
std::string sceneKeyOf(const ResolvedKey& k)
{
    const Parameter& p = *k.parameter;
    if (p.list == ParameterList::None)
        return std::string(p.key);
    const std::string_view list = listKey(p.list);
    return fmt::format("{}[{}]{}", list, k.item, p.key.substr(list.size()));
}

bool isVector(ParameterKind kind)
{
    return kind == ParameterKind::Colour || kind == ParameterKind::Direction3 || kind == ParameterKind::Vector3;
}

// One TOML value as a parameter's value, or a failure at its place.
ParameterValue valueOf(const toml::node& node, const ResolvedKey& k, const std::string& key, const Places& places)
{
    const ParameterKind kind = kindOf(k);
    const SourcePlace at = places.of(node.source());
    switch (kind) {
    case ParameterKind::Real:
        if (const auto v = node.value<double>(); v && (node.is_floating_point() || node.is_integer()))
            return *v;
        fail(at, fmt::format("vary.\"{}\": a number, not {}", key, detail::scenefile::typeName(node)));
    case ParameterKind::Integer:
        if (const auto v = node.value<std::int64_t>(); v && node.is_integer())
            return *v;
        fail(at, fmt::format("vary.\"{}\": a whole number", key));
    case ParameterKind::Flag:
        if (const auto v = node.value<bool>())
            return *v;
        fail(at, fmt::format("vary.\"{}\": true or false", key));
    case ParameterKind::Choice:
        if (const auto v = node.value<std::string>()) {
            for (std::size_t c = 0; c < k.parameter->choices.size(); ++c)
                if (k.parameter->choices[c] == *v)
                    return std::int64_t(c);
            std::string names;
            for (std::string_view c : k.parameter->choices)
                names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", c);
            fail(at, fmt::format("vary.\"{}\": \"{}\" is not one of {}", key, *v, names));
        }
        fail(at, fmt::format("vary.\"{}\": a string naming one of its choices", key));
    case ParameterKind::Colour:
    case ParameterKind::Direction3:
    case ParameterKind::Vector3:
        if (const toml::array* a = node.as_array(); a && a->size() == 3) {
            glm::dvec3 v(0.0);
            for (std::size_t c = 0; c < 3; ++c) {
                const auto x = (*a)[c].value<double>();
                if (!x)
                    fail(places.of((*a)[c].source()), fmt::format("vary.\"{}\": [x, y, z] of numbers", key));
                v[int(c)] = *x;
            }
            return v;
        }
        fail(at, fmt::format("vary.\"{}\": [x, y, z]", key));
    case ParameterKind::Direction2:
    case ParameterKind::Vector2:
        fail(at, fmt::format("vary.\"{}\": a 2D vector cannot be varied yet", key));
    case ParameterKind::DateTime:
        fail(at, fmt::format("vary.\"{}\": a date-time cannot be varied yet; vary sun.elevation_deg", key));
    }
    fail(at, "unreachable");
}

SweepKey readKey(const std::string& key, const toml::node& node, const Places& places)
{
    const std::optional<ResolvedKey> k = resolve(key);
    const SourcePlace at = places.of(node.source());
    if (!k) {
        std::vector<std::string> known;
        for (const Parameter& p : parameters())
            known.emplace_back(p.key);
        const std::optional<std::string> near = detail::scenefile::closest(key, known);
        fail(at, fmt::format("vary.\"{}\": not a scene parameter (docs/SCENE.md; an item of a list is written "
                             "\"objects[0].yaw_deg\"){}",
                             key, near ? fmt::format("; did you mean \"{}\"?", *near) : ""));
    }
    SweepKey s;
    s.key = key;
    s.place = at;
    const ParameterKind kind = kindOf(*k);
    if (const toml::table* t = node.as_table()) {
        for (const auto& [name, value] : *t)
            if (name.str() != "one_of")
                fail(places.of(name.source()),
                     fmt::format("vary.\"{}\": unknown key '{}' in its table, which holds only one_of = [...], the "
                                 "values to choose from, each as likely (write a value twice to make it twice as likely)",
                                 key, detail::scenefile::shortText(name.str())));
        const toml::array* choices = (*t)["one_of"].as_array();
        if (!choices)
            fail(at, fmt::format("vary.\"{}\": a table holds only one_of = [...], the values to choose from", key));
        if (choices->empty())
            fail(places.of(choices->source()), fmt::format("vary.\"{}\": one_of is empty: nothing to choose from", key));
        s.kind = SweepKey::Kind::OneOf;
        for (const toml::node& c : *choices)
            s.choices.push_back(valueOf(c, *k, key, places));
        return s;
    }
    const toml::array* a = node.as_array();
    const bool range = a && a->size() == 2 && (isVector(kind) ? (*a)[0].is_array() : !(*a)[0].is_array());
    if (!range || kind == ParameterKind::Flag || kind == ParameterKind::Choice) {
        s.kind = SweepKey::Kind::OneOf;
        s.choices.push_back(valueOf(node, *k, key, places));
        return s;
    }
    s.lo = valueOf((*a)[0], *k, key, places);
    s.hi = valueOf((*a)[1], *k, key, places);
    const auto empty = [](const ParameterValue& lo, const ParameterValue& hi) {
        if (const auto* l = std::get_if<double>(&lo))
            return *l > std::get<double>(hi);
        if (const auto* l = std::get_if<std::int64_t>(&lo))
            return *l > std::get<std::int64_t>(hi);
        const glm::dvec3 l = std::get<glm::dvec3>(lo), h = std::get<glm::dvec3>(hi);
        return l.x > h.x || l.y > h.y || l.z > h.z;
    };
    if (empty(s.lo, s.hi))
        fail(at, fmt::format("vary.\"{}\": an empty range: [low, high] with low above high", key));
    return s;
}

// A key's random stream for sample i: FNV-1a of the key, mixed with the seed and i.
class Stream {
public:
    Stream(std::uint64_t seed, int index, std::string_view key)
    {
        std::uint64_t h = 0xcbf29ce484222325ull;
        for (char c : key)
            h = (h ^ std::uint8_t(c)) * 0x100000001b3ull;
        using detail::splitMix64;
        state_ = splitMix64(splitMix64(seed) ^ splitMix64(h) ^ splitMix64(std::uint64_t(index) + 0x51ull));
    }
    // Uniform in [0, 1), 53 bits.
    double next()
    {
        state_ = detail::splitMix64(state_);
        return detail::unitFromBits(state_);
    }

private:
    std::uint64_t state_;
};

ParameterValue draw(const SweepKey& k, Stream& stream)
{
    if (k.kind == SweepKey::Kind::OneOf) {
        const std::size_t n = k.choices.size();
        return k.choices[std::min(n - 1, std::size_t(stream.next() * double(n)))];
    }
    if (const auto* lo = std::get_if<double>(&k.lo))
        return *lo + stream.next() * (std::get<double>(k.hi) - *lo);
    if (const auto* lo = std::get_if<std::int64_t>(&k.lo)) {
        const std::int64_t span = std::get<std::int64_t>(k.hi) - *lo + 1;
        return *lo + std::min(span - 1, std::int64_t(stream.next() * double(span)));
    }
    const glm::dvec3 lo = std::get<glm::dvec3>(k.lo), hi = std::get<glm::dvec3>(k.hi);
    glm::dvec3 v;
    for (int c = 0; c < 3; ++c)
        v[c] = lo[c] + stream.next() * (hi[c] - lo[c]);
    return v;
}

// Every value a key can take, for checking against the parameter's range.
std::vector<ParameterValue> extremes(const SweepKey& k)
{
    return k.kind == SweepKey::Kind::OneOf ? k.choices : std::vector<ParameterValue>{k.lo, k.hi};
}

} // namespace

namespace {

// [clip]: frames (1..kMaxClipFrames) at fps (more than 0, at most 240, as
// `swell render --fps`), each refused at its own place.
SweepClip readClip(const toml::node& node, const Places& places)
{
    const toml::table* t = node.as_table();
    if (!t)
        fail(places.of(node.source()), "clip: a table ([clip]) with frames and fps");
    SweepClip clip;
    clip.place = places.of(node.source());
    for (const auto& [key, value] : *t)
        if (std::find(kClipKeys.begin(), kClipKeys.end(), key.str()) == kClipKeys.end()) {
            const std::optional<std::string> near = detail::scenefile::closest(key.str(), kClipKeys);
            fail(places.of(key.source()), fmt::format("unknown key '{}' in [clip]{}", key.str(),
                                                      near ? fmt::format(" (did you mean '{}'?)", *near) : ""));
        }
    const toml::node* frames = t->get("frames");
    if (!frames || !frames->is_integer() || **frames->as_integer() < 1 || **frames->as_integer() > kMaxClipFrames)
        fail(frames ? places.of(frames->source()) : clip.place,
             fmt::format("clip.frames: the frames of each sample's clip, a whole number from 1 to {}, is missing "
                         "or out of range",
                         kMaxClipFrames));
    clip.frames = int(**frames->as_integer());
    const toml::node* fps = t->get("fps");
    const std::optional<double> rate = fps ? fps->value<double>() : std::nullopt;
    if (!rate || !(*rate > 0.0 && *rate <= 240.0))
        fail(fps ? places.of(fps->source()) : clip.place,
             "clip.fps: the clip's frames per second of simulated time, a number above 0 and at most 240, is "
             "missing or out of range");
    clip.fps = *rate;
    return clip;
}

} // namespace

Sweep loadSweepFile(const fs::path& path)
{
    Sweep sweep;
    sweep.file = path;
    sweep.text = detail::readInputFile(path, kMaxSceneFileBytes, "sweep file");
    const Places places(path.string());
    const toml::table root = detail::scenefile::parseTomlText(sweep.text, places);
    for (const auto& [key, node] : root)
        if (std::find(kTopKeys.begin(), kTopKeys.end(), key.str()) == kTopKeys.end()) {
            const std::optional<std::string> near = detail::scenefile::closest(key.str(), kTopKeys);
            fail(places.of(key.source()), fmt::format("unknown key '{}' in a sweep file{}", key.str(),
                                                      near ? fmt::format(" (did you mean '{}'?)", *near) : ""));
        }
    const SourcePlace file{path.string(), 0, 0};
    const toml::node* scene = root.get("scene");
    if (!scene || !scene->is_string())
        fail(scene ? places.of(scene->source()) : file,
             "scene: the base scene, a scene file relative to the sweep file or a preset's name, is missing");
    sweep.scene = **scene->as_string();
    sweep.scenePlace = places.of(scene->source());
    const toml::node* count = root.get("count");
    if (!count || !count->is_integer() || **count->as_integer() < 1 || **count->as_integer() > kMaxSweepSamples)
        fail(count ? places.of(count->source()) : file,
             fmt::format("count: the number of samples, a whole number from 1 to {}, is missing or out of range",
                         kMaxSweepSamples));
    sweep.count = int(**count->as_integer());
    if (const toml::node* seed = root.get("seed")) {
        if (!seed->is_integer() || **seed->as_integer() < 0)
            fail(places.of(seed->source()), "seed: a whole number, 0 or more");
        sweep.seed = std::uint64_t(**seed->as_integer());
    }
    if (const toml::node* size = root.get("size")) {
        const toml::array* a = size->as_array();
        const auto side = [&](std::size_t i) { return a && a->size() == 2 ? (*a)[i].value<std::int64_t>() : std::nullopt; };
        if (!side(0) || !side(1) || *side(0) < 16 || *side(1) < 16 || *side(0) > 8192 || *side(1) > 8192)
            fail(places.of(size->source()), "size: [width, height] in pixels, each 16..8192");
        sweep.size = glm::ivec2(int(*side(0)), int(*side(1)));
    }
    sweep.timePlace = file;
    if (const toml::node* time = root.get("time_s")) {
        sweep.timePlace = places.of(time->source());
        const toml::array* a = time->as_array();
        const std::optional<double> lo = a && a->size() == 2 ? (*a)[0].value<double>() : time->value<double>();
        const std::optional<double> hi = a && a->size() == 2 ? (*a)[1].value<double>() : time->value<double>();
        if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi) || *lo < 0.0 || *hi > 1.0e6)
            fail(places.of(time->source()), "time_s: seconds 0..1e6, a number or a range [low, high]");
        if (*lo > *hi)
            fail(places.of(time->source()), "time_s: an empty range: [low, high] with low above high");
        sweep.timeMin_s = *lo;
        sweep.timeMax_s = *hi;
    }
    if (const toml::node* labels = root.get("labels")) {
        if (!labels->is_boolean())
            fail(places.of(labels->source()), "labels: true or false");
        sweep.labels = **labels->as_boolean();
    }
    if (const toml::node* clip = root.get("clip"))
        sweep.clip = readClip(*clip, places);
    if (const toml::node* vary = root.get("vary")) {
        const toml::table* t = vary->as_table();
        if (!t)
            fail(places.of(vary->source()), "vary: a table of scene keys and their ranges ([vary])");
        for (const auto& [key, node] : *t)
            sweep.vary.push_back(readKey(std::string(key.str()), node, places));
    }
    return sweep;
}

void checkSweep(const Sweep& sweep, const Scene& base)
{
    const SweepKey* angle = nullptr;
    for (const SweepKey& k : sweep.vary)
        if (isSunAngle(*resolve(k.key)->parameter))
            angle = &k;
    for (const SweepKey& k : sweep.vary) {
        const ResolvedKey r = *resolve(k.key);
        const Parameter& p = *r.parameter;
        // The sun by its angles and by another form in one sample: which wins
        // would depend on the keys' order.
        if (angle && (p.key == "sun.direction" || p.key == "sun.latitude_deg" || p.key == "sun.longitude_deg"))
            fail(k.place, fmt::format("vary.\"{}\": the sun is given by its angles in this sweep ({}); vary those, "
                                      "or the sun's other keys, not both",
                                      k.key, angle->key));
        if (p.list != ParameterList::None && r.item >= listSize(base, p.list))
            fail(k.place, fmt::format("vary.\"{}\": the base scene has {} item(s) in {}", k.key, listSize(base, p.list),
                                      listKey(p.list)));
        if (!isPresent(p, base) && !isSunAngle(p))
            fail(k.place, fmt::format("vary.\"{}\": the base scene does not use it (the wind's keys need waves "
                                      "from the wind)",
                                      k.key));
        for (const ParameterValue& v : extremes(k)) {
            std::vector<double> components;
            if (const auto* d = std::get_if<double>(&v))
                components = {*d};
            else if (const auto* i = std::get_if<std::int64_t>(&v))
                components = {double(*i)};
            else if (const auto* v3 = std::get_if<glm::dvec3>(&v))
                components = {v3->x, v3->y, v3->z};
            if (p.kind == ParameterKind::Choice || p.kind == ParameterKind::Flag)
                continue;
            for (double c : components)
                if (!std::isfinite(c) || c < p.min || c > p.max || (p.minExclusive && c == p.min))
                    fail(k.place, fmt::format("vary.\"{}\": {} is outside its range {}{} .. {}{}", k.key, c,
                                              p.minExclusive ? "above " : "", p.min, p.max,
                                              p.unit.empty() ? "" : fmt::format(" {}", p.unit)));
            // The one key whose range is the base scene's: an object's index.
            if (&p == findParameter("camera.mount_object") && components[0] >= double(base.objects.size()))
                fail(k.place, fmt::format("vary.\"{}\": {:g} names no object: the base scene has {} object(s), "
                                          "indices from 0 (-1: none)",
                                          k.key, components[0], base.objects.size()));
        }
    }
}

ParameterValue sweptValue(const Scene& scene, std::string_view key)
{
    const std::optional<ResolvedKey> r = resolve(key);
    if (!r)
        throw Error(fmt::format("sweptValue: '{}' is not a sweep key", key));
    return r->parameter->get(scene, r->item);
}

const Parameter* sweptParameter(std::string_view key)
{
    const std::optional<ResolvedKey> r = resolve(key);
    return r ? r->parameter : nullptr;
}

std::optional<fs::path> sweepSceneFile(const Sweep& sweep)
{
    if (sweep.scene.empty() || detail::scenefile::hasControlCharacter(sweep.scene))
        fail(sweep.scenePlace, "scene: name the base scene, a scene file beside the sweep file or a preset's name");
    const fs::path folder = detail::scenefile::baseFolder(sweep.file);
    const fs::path resolved = detail::resolvedFolder(folder);
    std::error_code error;
    if (fs::weakly_canonical(resolved / sweep.scene, error) == resolved)
        fail(sweep.scenePlace, fmt::format("scene: '{}' is the sweep file's folder, not a scene file",
                                           detail::scenefile::shortText(sweep.scene)));
    if (!detail::resolveInside(resolved, sweep.scene))
        fail(sweep.scenePlace,
             fmt::format("scene: '{}' lies outside the sweep file's folder '{}'; a sweep's scene is a file in its "
                         "folder or below it, links included, or a preset's name",
                         detail::scenefile::shortText(sweep.scene), folder.string()));
    const fs::path file = folder / sweep.scene;
    // Anything there (a dangling link, a folder, a FIFO) is the scene file
    // the user meant, for the reader to take or refuse with its reason.
    if (fs::exists(fs::symlink_status(file, error)))
        return file;
    return std::nullopt;
}

SweepSample sweepSample(const Sweep& sweep, const Scene& base, int index)
{
    SweepSample s;
    s.scene = base;
    Stream time(sweep.seed, index, "time_s");
    s.time_s = sweep.timeMin_s + time.next() * (sweep.timeMax_s - sweep.timeMin_s);
    for (const SweepKey& k : sweep.vary) {
        Stream stream(sweep.seed, index, k.key);
        const ParameterValue v = draw(k, stream);
        s.values.push_back(v);
        const ResolvedKey r = *resolve(k.key);
        // A sun angle keeps the other as the base scene has it and gives the
        // sample's sun by its angles, not the base's date and place.
        r.parameter->set(s.scene, r.item, v);
        s.scene.keyPlaces[sceneKeyOf(r)] = k.place;
    }
    return s;
}

} // namespace swell
