// Scene files (swell/scene_file.h). Loading runs in four steps, each of which
// throws InputError at the first problem it finds:
//   1. size, text and structure: the text is small enough, is UTF-8 without
//      NUL bytes, and its keys and nesting are shallow enough for the TOML
//      parser's recursion;
//   2. TOML syntax (toml++);
//   3. reading: every key is known, every value has the right type and range
//      (keys and ranges come from the parameter table, swell/parameters.h),
//      and the place of each key is remembered;
//   4. checking the scene as a whole: cross-field rules, referenced files,
//      the wave set. validateScene() runs this step alone.
// Saving writes TOML by hand, section by section, so the file reads like the
// docs: one key per line with its range in a comment.
#include "swell/scene_file.h"

#include "swell/error.h"
#include "swell/parameters.h"
#include "swell/shader_constants.h"

#include <fmt/format.h>

#include <toml++/toml.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swell {
namespace fs = std::filesystem;
namespace {

// ---------------------------------------------------------------------------
// Places: where each key of the file was, so that later checks can point at it.
// Keys are written as the user sees them: "fog.end_m", "objects[2].scale",
// "sky.faces[3]"; "" is the file itself.

std::string parentKey(std::string_view key)
{
    if (!key.empty() && key.back() == ']') {
        auto open = key.rfind('[');
        return std::string(key.substr(0, open == std::string_view::npos ? 0 : open));
    }
    auto dot = key.rfind('.');
    return dot == std::string_view::npos ? std::string() : std::string(key.substr(0, dot));
}

class Places {
public:
    explicit Places(std::string path) : path_(std::move(path)) {}

    const std::string& path() const { return path_; }

    SourcePlace of(const toml::source_region& region) const
    {
        return {path_, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
    }

    void add(std::string key, const toml::source_region& region) { places_[std::move(key)] = of(region); }

    bool has(std::string_view key) const { return places_.find(key) != places_.end(); }

    // The place of `key`, else of the nearest enclosing key that has one, else the file.
    SourcePlace at(std::string_view key) const
    {
        std::string k(key);
        while (true) {
            if (auto it = places_.find(k); it != places_.end())
                return it->second;
            if (k.empty())
                return {path_, 0, 0};
            k = parentKey(k);
        }
    }

    // The place of the first of `keys` the file has, else at(first key).
    SourcePlace first(std::initializer_list<std::string_view> keys) const
    {
        for (std::string_view k : keys)
            if (has(k))
                return at(k);
        return at(*keys.begin());
    }

private:
    std::string path_;
    std::map<std::string, SourcePlace, std::less<>> places_;
};

[[noreturn]] void fail(SourcePlace place, const std::string& message) { throw InputError(std::move(place), message); }

// ---------------------------------------------------------------------------
// Step 1a: text. The parser would also find these, but only after the
// structure scan has run over them; checking first reports binary data as
// such, at its first bad byte.

// Length of the UTF-8 sequence at s[i], or 0 when it is not valid UTF-8.
std::size_t utf8Length(std::string_view s, std::size_t i)
{
    auto byte = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    auto continuation = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
        return byte(k) >= lo && byte(k) <= hi;
    };
    unsigned b = byte(i);
    if (b < 0x80)
        return 1;
    if (b >= 0xC2 && b <= 0xDF)
        return continuation(i + 1) ? 2 : 0;
    if (b >= 0xE0 && b <= 0xEF) {
        // No overlong forms (E0 80..9F) and no UTF-16 surrogates (ED A0..BF).
        unsigned lo = b == 0xE0 ? 0xA0 : 0x80;
        unsigned hi = b == 0xED ? 0x9F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) ? 3 : 0;
    }
    if (b >= 0xF0 && b <= 0xF4) {
        // No overlong forms (F0 80..8F) and nothing past U+10FFFF (F4 90..).
        unsigned lo = b == 0xF0 ? 0x90 : 0x80;
        unsigned hi = b == 0xF4 ? 0x8F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
    }
    return 0;
}

void checkText(std::string_view text, const std::string& path)
{
    int line = 1;
    int column = 1;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '\0')
            fail({path, line, column}, "the file contains a NUL byte; a scene file is UTF-8 TOML text, not binary data");
        std::size_t n = utf8Length(text, i);
        if (n == 0)
            fail({path, line, column},
                 fmt::format("byte 0x{:02X} is not UTF-8; a scene file is UTF-8 TOML text, not binary data",
                             static_cast<unsigned>(static_cast<unsigned char>(text[i]))));
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        i += n;
    }
}

// ---------------------------------------------------------------------------
// Step 1b: structure. toml++ recurses once per dotted key part and once per
// nested [ ] or { }, so a 4 MiB line of "a.a.a..." overflows the stack; and it
// builds a node for every array entry before the reader can count them, so
// "list = [{},{},...]" would allocate a million tables. This scan skips
// strings and comments and counts just those things (parts, nesting, array
// entries, [[ ]] headers); anything else, including broken syntax, is left
// for the parser to report.

class StructureScan {
public:
    StructureScan(std::string_view text, const std::string& path) : text_(text), path_(path) {}

    void run()
    {
        while (i_ < text_.size()) {
            char c = text_[i_];
            switch (mode_) {
            case Mode::LineStart: lineStart(c); break;
            case Mode::Key: key(c); break;
            case Mode::Value: value(c); break;
            }
        }
    }

private:
    enum class Mode { LineStart, Key, Value };

    SourcePlace here() const { return {path_, line_, column_}; }

    // Moves past one byte; columns count code points, as the parser's do.
    void step()
    {
        char c = text_[i_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else if (i_ < text_.size() && (static_cast<unsigned char>(text_[i_]) & 0xC0) != 0x80) {
            ++column_;
        }
    }

    bool startsWith(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

    void skipComment()
    {
        while (i_ < text_.size() && text_[i_] != '\n' && text_[i_] != '\0')
            step();
    }

    // A string starting at i_ (on its opening quote): basic or literal, one
    // line or multi-line. Single-line strings also end at a newline, so that
    // a stray quote cannot hide the rest of the file from the scan.
    void skipString()
    {
        char q = text_[i_];
        const std::string triple(3, q);
        if (startsWith(triple)) {
            for (int k = 0; k < 3; ++k)
                step();
            while (i_ < text_.size() && !startsWith(triple)) {
                if (text_[i_] == '\0')
                    return;
                if (q == '"' && text_[i_] == '\\' && i_ + 1 < text_.size())
                    step();
                step();
            }
            // The closing delimiter may be preceded by up to two more quotes.
            for (int k = 0; k < 5 && i_ < text_.size() && text_[i_] == q; ++k)
                step();
            return;
        }
        step();
        while (i_ < text_.size() && text_[i_] != q && text_[i_] != '\n') {
            if (text_[i_] == '\0')
                return;
            if (q == '"' && text_[i_] == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n')
                step();
            step();
        }
        if (i_ < text_.size() && text_[i_] == q)
            step();
    }

    void pop()
    {
        nest_.pop_back();
        items_.pop_back();
    }

    void startKey()
    {
        mode_ = Mode::Key;
        keyParts_ = 1;
    }

    void lineStart(char c)
    {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            step();
        } else if (c == '#') {
            skipComment();
        } else if (c == '[') { // table header, [name] or [[name]]
            step();
            if (i_ < text_.size() && text_[i_] == '[') {
                if (++tableArrayHeaders_ > kMaxSceneTableArrayHeaders)
                    fail(here(), fmt::format("more than {} [[...]] headers; a scene holds at most {} camera keys, {} "
                                             "objects and {} waves",
                                             kMaxSceneTableArrayHeaders, kMaxCameraKeys, kMaxSceneObjects, SWELL_MAX_WAVES));
                step();
            }
            startKey();
        } else {
            startKey();
        }
    }

    void key(char c)
    {
        switch (c) {
        case '"':
        case '\'': skipString(); return;
        case '#': skipComment(); return;
        case '.':
            if (++keyParts_ > kMaxSceneKeyParts)
                fail(here(), fmt::format("a key with more than {} dotted parts; scene keys have at most 3",
                                         kMaxSceneKeyParts));
            step();
            return;
        case '=':
        case ']': // end of a table header; the rest of its line reads like a value's
            mode_ = Mode::Value;
            step();
            return;
        case '}': // an empty inline table
            if (!nest_.empty() && nest_.back() == '{')
                pop();
            mode_ = Mode::Value;
            step();
            return;
        case '\n':
            mode_ = nest_.empty() ? Mode::LineStart : Mode::Value;
            step();
            return;
        default: step(); return;
        }
    }

    void value(char c)
    {
        switch (c) {
        case '"':
        case '\'': skipString(); return;
        case '#': skipComment(); return;
        case '[':
        case '{':
            nest_.push_back(c);
            items_.push_back(1);
            if (static_cast<int>(nest_.size()) > kMaxSceneNesting)
                fail(here(), fmt::format("values nested more than {} deep in [ ] and {{ }}; scene values nest at most 3 deep",
                                         kMaxSceneNesting));
            step();
            if (c == '{')
                startKey();
            return;
        case ']':
        case '}':
            if (!nest_.empty() && nest_.back() == (c == ']' ? '[' : '{'))
                pop();
            step();
            return;
        case ',':
            // TOML allows a comma after the last entry: n commas hold at least n entries.
            if (!nest_.empty() && nest_.back() == '[' && ++items_.back() > kMaxSceneArrayItems + 1)
                fail(here(), fmt::format("an array with more than {} entries; the longest list in a scene "
                                         "(camera.path) has at most {}",
                                         kMaxSceneArrayItems, kMaxCameraKeys));
            step();
            if (!nest_.empty() && nest_.back() == '{')
                startKey();
            return;
        case '\n':
            if (nest_.empty())
                mode_ = Mode::LineStart;
            step();
            return;
        default: step(); return;
        }
    }

    std::string_view text_;
    const std::string& path_;
    std::size_t i_ = 0;
    int line_ = 1;
    int column_ = 1;
    Mode mode_ = Mode::LineStart;
    int keyParts_ = 1;
    std::vector<char> nest_;
    // 1 + the commas so far of each open [ ] or { } in nest_ (counted for [ ] only).
    std::vector<std::size_t> items_;
    int tableArrayHeaders_ = 0;
};

// ---------------------------------------------------------------------------
// Step 3: reading the TOML tree into a Scene.

// Keys that are not parameters: tables, arrays of tables and strings.
enum class Shape { Table, TableList, Faces, ObjectPath };

struct StructuralKey {
    std::string_view key;
    Shape shape;
    ParameterList list; // the array of tables the key sits in (None: not in one)
};

constexpr StructuralKey kStructure[] = {
    {"waves", Shape::Table, ParameterList::None},
    {"waves.wind", Shape::Table, ParameterList::None},
    {"waves.swell", Shape::Table, ParameterList::None},
    {"waves.list", Shape::TableList, ParameterList::None},
    {"grid", Shape::Table, ParameterList::None},
    {"sun", Shape::Table, ParameterList::None},
    {"sky", Shape::Table, ParameterList::None},
    {"sky.faces", Shape::Faces, ParameterList::None},
    {"fog", Shape::Table, ParameterList::None},
    {"water", Shape::Table, ParameterList::None},
    {"reflection", Shape::Table, ParameterList::None},
    {"objects", Shape::TableList, ParameterList::None},
    {"objects.path", Shape::ObjectPath, ParameterList::Objects},
    {"camera", Shape::Table, ParameterList::None},
    {"camera.path", Shape::TableList, ParameterList::None},
};

const StructuralKey* findStructural(std::string_view key, ParameterList list)
{
    for (const StructuralKey& s : kStructure)
        if (s.key == key && s.list == list)
            return &s;
    return nullptr;
}

const Parameter* findParameterIn(std::string_view key, ParameterList list)
{
    const Parameter* p = findParameter(key);
    return (p != nullptr && p->list == list) ? p : nullptr;
}

ParameterList listOf(std::string_view tableListKey)
{
    for (ParameterList l : {ParameterList::Waves, ParameterList::Objects, ParameterList::CameraPath})
        if (listKey(l) == tableListKey)
            return l;
    return ParameterList::None;
}

std::size_t listLimit(ParameterList list)
{
    switch (list) {
    case ParameterList::Waves: return SWELL_MAX_WAVES;
    case ParameterList::Objects: return kMaxSceneObjects;
    case ParameterList::CameraPath: return kMaxCameraKeys;
    case ParameterList::None: break;
    }
    return 0;
}

std::string join(std::string_view prefix, std::string_view key)
{
    return prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
}

// Edit distance with adjacent transpositions, so "strat" is one step from "start".
std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The candidate closest to `word`, if it is close enough to be a typo.
std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates)
{
    std::optional<std::string> best;
    std::size_t bestDistance = word.size() >= 5 ? 3 : 2; // must beat this
    for (const std::string& c : candidates) {
        std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

std::string typeName(const toml::node& node)
{
    switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
    }
}

std::optional<double> number(const toml::node& node)
{
    if (const auto* i = node.as_integer())
        return static_cast<double>(i->get());
    if (const auto* f = node.as_floating_point())
        return f->get();
    return std::nullopt;
}

bool hasControlCharacter(std::string_view s)
{
    return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

class SceneReader {
public:
    explicit SceneReader(Places& places) : places_(places) {}

    Scene read(const toml::table& root)
    {
        readTable(root, "", "", ParameterList::None, 0);
        if (places_.has("waves.wind") && places_.has("waves.list"))
            fail(places_.at("waves.list"),
                 "waves.list and waves.wind exclude each other: list the waves, or let the wind generate them");
        if (places_.has("waves.swell") && !places_.has("waves.wind"))
            fail(places_.at("waves.swell"),
                 "waves.swell adds a swell to the waves generated from waves.wind; add a [waves.wind] table");
        if (scene_.waves.wind && scene_.waves.wind->swell) {
            const int total = scene_.waves.wind->waveCount + scene_.waves.wind->swell->waveCount;
            if (total > SWELL_MAX_WAVES)
                fail(places_.at("waves.swell"),
                     fmt::format("waves.wind.count + waves.swell.count = {}; at most {} waves in all (SWELL_MAX_WAVES)",
                                 total, SWELL_MAX_WAVES));
        }
        // One depth for both wave sources (see WaveSource).
        if (scene_.waves.wind)
            scene_.waves.wind->depth_m = scene_.waves.listed.depth_m;
        return std::move(scene_);
    }

private:
    // Entries of a table in the order they appear in the file (toml++ keeps
    // them sorted by name), so the first problem reported is the first one written.
    static std::vector<std::pair<const toml::key*, const toml::node*>> inFileOrder(const toml::table& table)
    {
        std::vector<std::pair<const toml::key*, const toml::node*>> entries;
        for (auto&& [k, v] : table)
            entries.emplace_back(&k, &v);
        std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
            const auto& pa = a.first->source().begin;
            const auto& pb = b.first->source().begin;
            return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
        });
        return entries;
    }

    // schema: the key without item numbers ("objects"); shown: as the user
    // sees it ("objects[2]"); list/item: the array of tables we are inside.
    void readTable(const toml::table& table, const std::string& schema, const std::string& shown, ParameterList list,
                   std::size_t item)
    {
        for (auto [k, node] : inFileOrder(table)) {
            std::string childSchema = join(schema, k->str());
            std::string childShown = join(shown, k->str());
            if (const Parameter* p = findParameterIn(childSchema, list)) {
                readParameter(*p, *node, childShown, item);
                continue;
            }
            const StructuralKey* s = findStructural(childSchema, list);
            if (s == nullptr)
                unknownKey(*k, childSchema, shown, list);
            switch (s->shape) {
            case Shape::Table:
                if (!node->is_table())
                    fail(places_.of(node->source()), fmt::format("{} must be a table, not {}", childShown, typeName(*node)));
                places_.add(childShown, node->source());
                // Present, even when empty, means "generate from the wind" (or
                // "add a swell"); a swell read first has already set the wind up.
                if (childSchema == "waves.wind" && !scene_.waves.wind)
                    scene_.waves.wind.emplace();
                if (childSchema == "waves.swell") {
                    if (!scene_.waves.wind)
                        scene_.waves.wind.emplace();
                    if (!scene_.waves.wind->swell)
                        scene_.waves.wind->swell.emplace();
                }
                readTable(*node->as_table(), childSchema, childShown, list, item);
                break;
            case Shape::TableList: readTableList(*node, childSchema, childShown); break;
            case Shape::Faces: readFaces(*node, childShown); break;
            case Shape::ObjectPath:
                scene_.objects[item].path = readPath(*node, childShown);
                places_.add(childShown, node->source());
                break;
            }
        }
    }

    static bool isTopLevelKey(std::string_view name)
    {
        for (const Parameter& p : parameters())
            if (p.list == ParameterList::None && p.key == name)
                return true;
        return false;
    }

    [[noreturn]] void unknownKey(const toml::key& key, const std::string& schema, const std::string& shownPrefix,
                                 ParameterList list)
    {
        // Candidates in the same array of tables, written as the user would.
        std::string_view itemKey = listKey(list);
        std::vector<std::string> schemaNames;
        std::vector<std::string> shownNames;
        auto consider = [&](std::string_view name) {
            schemaNames.emplace_back(name);
            shownNames.push_back(list == ParameterList::None ? std::string(name)
                                                             : std::string(shownPrefix) + std::string(name.substr(itemKey.size())));
        };
        for (const Parameter& p : parameters())
            if (p.list == list)
                consider(p.key);
        for (const StructuralKey& s : kStructure)
            if (s.list == list)
                consider(s.key);

        std::string shown = join(shownPrefix, key.str());
        std::string message = fmt::format("unknown key '{}'", shown);
        std::optional<std::string> guess = closest(schema, schemaNames);
        if (!guess) {
            // A known key in the wrong table: the same last part, exactly one owner.
            std::string_view last = key.str();
            std::vector<std::string> owners;
            for (const std::string& n : schemaNames)
                if (n.size() > last.size() && n.ends_with(last) && n[n.size() - last.size() - 1] == '.')
                    owners.push_back(n);
            if (owners.size() == 1)
                guess = owners.front();
        }
        if (guess) {
            auto at = std::find(schemaNames.begin(), schemaNames.end(), *guess) - schemaNames.begin();
            message += fmt::format("; did you mean '{}'?", shownNames[static_cast<std::size_t>(at)]);
        } else if (const std::size_t dot = shown.rfind('.'); dot != std::string::npos && isTopLevelKey(key.str())) {
            // In TOML a key belongs to the last [table] above it, so a
            // top-level key written after one lands in that table.
            message += fmt::format("; '{}' is a top-level key: write it above the first [table] header, "
                                   "since every key after [{}] belongs to that table",
                                   key.str(), shown.substr(0, dot));
        }
        fail(places_.of(key.source()), message);
    }

    void readTableList(const toml::node& node, const std::string& schema, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr)
            fail(places_.of(node.source()),
                 fmt::format("{} must be an array of tables, written [[{}]], not {}", shown, schema, typeName(node)));
        places_.add(shown, node.source());
        ParameterList list = listOf(schema);
        std::size_t limit = listLimit(list);
        if (array->size() > limit)
            fail(places_.of((*array)[limit].source()),
                 fmt::format("{} has {} entries; at most {} are allowed", shown, array->size(), limit));
        for (std::size_t i = 0; i < array->size(); ++i) {
            const toml::node& element = (*array)[i];
            std::string itemShown = fmt::format("{}[{}]", shown, i);
            if (!element.is_table())
                fail(places_.of(element.source()), fmt::format("{} must be a table, not {}", itemShown, typeName(element)));
            places_.add(itemShown, element.source());
            switch (list) {
            case ParameterList::Waves: scene_.waves.listed.waves.emplace_back(); break;
            case ParameterList::Objects: scene_.objects.emplace_back(); break;
            case ParameterList::CameraPath: scene_.camera.path.emplace_back(); break;
            case ParameterList::None: break;
            }
            readTable(*element.as_table(), schema, itemShown, list, i);
            if (list == ParameterList::Objects && !places_.has(itemShown + ".path"))
                fail(places_.of(element.source()),
                     fmt::format("{} needs a path: a .gltf or .glb file, or \"builtin:NAME\"", itemShown));
        }
    }

    void readFaces(const toml::node& node, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr)
            fail(places_.of(node.source()),
                 fmt::format("{} must be an array of 6 image paths (+x, -x, +y, -y, +z, -z), not {}", shown, typeName(node)));
        places_.add(shown, node.source());
        if (array->size() != 0 && array->size() != 6)
            fail(places_.of(node.source()),
                 fmt::format("{} must list 6 image paths (+x, -x, +y, -y, +z, -z), or none for the procedural sky; "
                             "it lists {}",
                             shown, array->size()));
        scene_.sky.cubemapFaces.clear();
        for (std::size_t i = 0; i < array->size(); ++i) {
            std::string faceShown = fmt::format("{}[{}]", shown, i);
            scene_.sky.cubemapFaces.push_back(readPath((*array)[i], faceShown));
            places_.add(faceShown, (*array)[i].source());
        }
    }

    std::string readPath(const toml::node& node, const std::string& shown)
    {
        const auto* s = node.as_string();
        if (s == nullptr)
            fail(places_.of(node.source()), fmt::format("{} must be a string (a file path), not {}", shown, typeName(node)));
        if (s->get().empty())
            fail(places_.of(node.source()), fmt::format("{} is empty; it must name a file", shown));
        if (hasControlCharacter(s->get()))
            fail(places_.of(node.source()), fmt::format("{} contains a control character", shown));
        return s->get();
    }

    [[noreturn]] void wrongType(const Parameter& p, const toml::node& node, const std::string& shown)
    {
        std::string expected;
        std::string unit = p.unit.empty() ? std::string() : fmt::format(" ({})", p.unit);
        switch (p.kind) {
        case ParameterKind::Real: expected = "a number" + unit; break;
        case ParameterKind::Integer: expected = "a whole number"; break;
        case ParameterKind::Flag: expected = "true or false"; break;
        case ParameterKind::Choice: expected = "one of " + rangeText(p); break;
        case ParameterKind::Colour: expected = "an array of 3 numbers [r, g, b]"; break;
        case ParameterKind::Direction3:
        case ParameterKind::Vector3: expected = "an array of 3 numbers [x, y, z]" + unit; break;
        case ParameterKind::Direction2: expected = "an array of 2 numbers [x, z]" + unit; break;
        }
        fail(places_.of(node.source()), fmt::format("{} must be {}, not {}", shown, expected, typeName(node)));
    }

    // A scalar, or one component of a vector (then `shown` is "sun.color[1]").
    double readNumber(const Parameter& p, const toml::node& node, const std::string& shown, bool component)
    {
        std::optional<double> x = number(node);
        if (!x && component)
            fail(places_.of(node.source()), fmt::format("{} must be a number, not {}", shown, typeName(node)));
        if (!x)
            wrongType(p, node, shown);
        if (!inRange(p, *x))
            fail(places_.of(node.source()), rangeMessage(p, shown, *x));
        return *x;
    }

    template <int N>
    glm::vec<N, double> readVector(const Parameter& p, const toml::node& node, const std::string& shown)
    {
        const toml::array* array = node.as_array();
        if (array == nullptr || array->size() != N) {
            if (array != nullptr)
                fail(places_.of(node.source()),
                     fmt::format("{} must have {} components, not {}", shown, N, array->size()));
            wrongType(p, node, shown);
        }
        glm::vec<N, double> v(0.0);
        for (int c = 0; c < N; ++c)
            v[c] = readNumber(p, (*array)[static_cast<std::size_t>(c)], fmt::format("{}[{}]", shown, c), true);
        return v;
    }

    void readParameter(const Parameter& p, const toml::node& node, const std::string& shown, std::size_t item)
    {
        ParameterValue value;
        switch (p.kind) {
        case ParameterKind::Real: value = readNumber(p, node, shown, false); break;
        case ParameterKind::Integer: {
            const auto* i = node.as_integer();
            if (i == nullptr)
                wrongType(p, node, shown);
            if (!inRange(p, static_cast<double>(i->get())))
                fail(places_.of(node.source()), rangeMessage(p, shown, static_cast<double>(i->get())));
            value = i->get();
            break;
        }
        case ParameterKind::Flag: {
            const auto* b = node.as_boolean();
            if (b == nullptr)
                wrongType(p, node, shown);
            value = b->get();
            break;
        }
        case ParameterKind::Choice: {
            const auto* s = node.as_string();
            if (s == nullptr)
                wrongType(p, node, shown);
            auto it = std::find(p.choices.begin(), p.choices.end(), s->get());
            if (it == p.choices.end()) {
                std::vector<std::string> names(p.choices.begin(), p.choices.end());
                std::optional<std::string> guess = closest(s->get(), names);
                fail(places_.of(node.source()),
                     fmt::format("{} = \"{}\" is not a choice; allowed {}{}", shown, s->get(), rangeText(p),
                                 guess ? fmt::format("; did you mean \"{}\"?", *guess) : std::string()));
            }
            value = static_cast<std::int64_t>(it - p.choices.begin());
            break;
        }
        case ParameterKind::Colour:
        case ParameterKind::Direction3:
        case ParameterKind::Vector3: value = readVector<3>(p, node, shown); break;
        case ParameterKind::Direction2: value = readVector<2>(p, node, shown); break;
        }
        places_.add(shown, node.source());
        // What is left: zero-length directions.
        if (std::string problem = valueProblem(p, value, shown); !problem.empty())
            fail(places_.of(node.source()), problem);
        p.set(scene_, item, value);
    }

    Places& places_;
    Scene scene_;
};

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

// A file the scene refers to must exist and be readable now, so that the
// renderer does not find out halfway through loading.
void checkFile(const fs::path& base, const std::string& relative, const std::string& name, const SourcePlace& place)
{
    fs::path file(relative);
    if (file.is_relative())
        file = base / file;
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status))
        fail(place, fmt::format("{}: file '{}' not found (relative paths start at the scene file's folder)", name,
                                file.string()));
    if (fs::is_directory(status))
        fail(place, fmt::format("{}: '{}' is a folder, not a file", name, file.string()));
    std::ifstream in(file, std::ios::binary);
    if (!in)
        fail(place, fmt::format("{}: cannot read '{}': {}", name, file.string(), std::strerror(errno)));
}

void checkObjectPath(const fs::path& base, const std::string& path, const std::string& name, const SourcePlace& place)
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
        fail(place, fmt::format("{} = \"{}\" is not a built-in object; the built-ins are {}", name, path, known));
    }
    std::string extension = lowercase(fs::path(path).extension().string());
    if (extension != ".gltf" && extension != ".glb")
        fail(place, fmt::format("{} = \"{}\" is not a glTF model; use a .gltf or .glb file, or \"builtin:NAME\"", name, path));
    checkFile(base, path, name, place);
}

void checkWaves(const Scene& scene, const Places& places)
{
    if (scene.waves.listed.waves.size() > SWELL_MAX_WAVES)
        fail(places.first({"waves.list", "waves"}),
             fmt::format("waves.list has {} waves; at most {} are allowed", scene.waves.listed.waves.size(), SWELL_MAX_WAVES));
    SourcePlace place = scene.waves.wind ? places.first({"waves.wind", "waves"}) : places.first({"waves.list", "waves"});
    const char* source = scene.waves.wind ? "the waves generated from waves.wind" : "waves.list";
    WaveSet waves;
    try {
        waves = resolveWaves(scene.waves);
    } catch (const InputError& e) {
        fail(place, fmt::format("{}: {}", source, e.message()));
    } catch (const std::invalid_argument& e) {
        fail(place, fmt::format("{}: {}", source, e.what()));
    }
    if (std::string problem = validate(waves); !problem.empty())
        fail(place, fmt::format("{} are not usable: {}", source, problem));
}

void checkScene(const Scene& scene, const Places& places, const fs::path& base)
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
    if (!(scene.camera.far_m > scene.camera.near_m))
        fail(places.first({"camera.far_m", "camera.near_m", "camera"}),
             fmt::format("camera.far_m ({} m) must be greater than camera.near_m ({} m)", scene.camera.far_m,
                         scene.camera.near_m));
    for (std::size_t i = 1; i < scene.camera.path.size(); ++i)
        if (!(scene.camera.path[i].time_s > scene.camera.path[i - 1].time_s)) {
            std::string name = fmt::format("camera.path[{}].time_s", i);
            fail(places.at(name), fmt::format("{} ({} s) must be later than camera.path[{}].time_s ({} s): keys are "
                                              "sorted by time",
                                              name, scene.camera.path[i].time_s, i - 1, scene.camera.path[i - 1].time_s));
        }

    // Referenced files.
    const auto& faces = scene.sky.cubemapFaces;
    if (!faces.empty() && faces.size() != 6)
        fail(places.at("sky.faces"), fmt::format("sky.faces must list 6 image paths, or none; it lists {}", faces.size()));
    for (std::size_t i = 0; i < faces.size(); ++i) {
        std::string name = fmt::format("sky.faces[{}]", i);
        if (faces[i].empty() || hasControlCharacter(faces[i]))
            fail(places.at(name), fmt::format("{} must name a file", name));
        checkFile(base, faces[i], name, places.at(name));
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        std::string name = fmt::format("objects[{}].path", i);
        if (hasControlCharacter(scene.objects[i].path))
            fail(places.at(name), fmt::format("{} contains a control character", name));
        checkObjectPath(base, scene.objects[i].path, name, places.at(name));
    }

    checkWaves(scene, places);
}

fs::path baseFolder(const fs::path& sceneFile)
{
    fs::path base = sceneFile.parent_path();
    return base.empty() ? fs::path(".") : base;
}

// ---------------------------------------------------------------------------
// Saving.

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

} // namespace

// ---------------------------------------------------------------------------

// A missing ']' at the end of an array's line is found by the TOML parser
// only on the next line, which it reads as more of the array. When the error
// lies on a later line than the innermost array still open there, this is
// the place to report instead: the end of the line that opened that array.
// Strings and comments are skipped; nullopt when no array is open.
std::optional<SourcePlace> unclosedArrayBefore(std::string_view text, const toml::source_position& error,
                                               const std::string& path)
{
    std::vector<std::pair<int, std::size_t>> open; // line and offset of each '[' still open
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (line > int(error.line) || (line == int(error.line) && i - lineStart + 1 >= error.column))
            break;
        const char c = text[i];
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (c == '#') {
            while (i + 1 < text.size() && text[i + 1] != '\n')
                ++i;
        } else if (c == '"' || c == '\'') {
            // A basic or literal string on one line; multi-line strings are not
            // looked into (an error inside one is reported where the parser says).
            while (i + 1 < text.size() && text[i + 1] != c && text[i + 1] != '\n')
                i += text[i + 1] == '\\' && c == '"' ? 2 : 1;
            ++i;
        } else if (c == '[') {
            open.emplace_back(line, i);
        } else if (c == ']' && !open.empty()) {
            open.pop_back();
        }
    }
    if (open.empty() || open.back().first >= int(error.line))
        return std::nullopt;
    // Only where the parser stopped at the first thing on its line, and the
    // array's line goes on after its '[' (an array written one element a line
    // has its '[' last: there the missing piece is more likely a comma).
    const std::size_t errorLineStart = lineStart;
    const std::size_t firstToken = text.find_first_not_of(" \t", errorLineStart);
    if (firstToken == std::string_view::npos || firstToken - errorLineStart + 1 != error.column)
        return std::nullopt;
    // The end of the opening line, comments and trailing blanks left out.
    const std::size_t from = open.back().second;
    std::size_t end = text.find('\n', from);
    if (end == std::string_view::npos)
        end = text.size();
    std::string_view rest = text.substr(from, end - from);
    if (const std::size_t hash = rest.find('#'); hash != std::string_view::npos)
        rest = rest.substr(0, hash);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r'))
        rest.remove_suffix(1);
    if (rest.size() <= 1)
        return std::nullopt;
    const std::size_t start = text.rfind('\n', from) == std::string_view::npos ? 0 : text.rfind('\n', from) + 1;
    return SourcePlace{path, open.back().first, int(from - start + rest.size()) + 1};
}

Scene parseScene(std::string_view text, const fs::path& virtualPath)
{
    Places places(virtualPath.string());
    if (text.size() > kMaxSceneFileBytes)
        fail({places.path(), 0, 0}, fmt::format("the scene is {} bytes; scene files are at most {} bytes (4 MiB)",
                                                text.size(), kMaxSceneFileBytes));
    checkText(text, places.path());
    StructureScan(text, places.path()).run();

    toml::table root;
    try {
        root = toml::parse(text, std::string_view(places.path()));
    } catch (const toml::parse_error& e) {
        const bool arrayOpen = e.description().find("closing ']'") != std::string_view::npos;
        if (const std::optional<SourcePlace> open =
                arrayOpen ? unclosedArrayBefore(text, e.source().begin, places.path()) : std::nullopt)
            fail(*open, fmt::format("TOML syntax: this array has no closing ']' (the parser read on into line {} "
                                    "and stopped there: {})",
                                    e.source().begin.line, e.description()));
        fail(places.of(e.source()), fmt::format("TOML syntax: {}", e.description()));
    }

    Scene scene = SceneReader(places).read(root);
    checkScene(scene, places, baseFolder(virtualPath));
    scene.assetFolder = baseFolder(virtualPath).string();
    return scene;
}

Scene loadScene(const fs::path& path)
{
    const SourcePlace file{path.string(), 0, 0};
    std::error_code ec;
    fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status))
        fail(file, "scene file not found");
    if (fs::is_directory(status))
        fail(file, "is a folder, not a scene file");
    if (fs::is_regular_file(status)) {
        std::uintmax_t size = fs::file_size(path, ec);
        if (!ec && size > kMaxSceneFileBytes)
            fail(file, fmt::format("the scene file is {} bytes; scene files are at most {} bytes (4 MiB)", size,
                                   kMaxSceneFileBytes));
    }

    std::ifstream in(path, std::ios::binary);
    if (!in)
        fail(file, fmt::format("cannot read the scene file: {}", std::strerror(errno)));
    // Read at most one byte past the limit, whatever the size claimed (pipes, /dev files).
    std::string text;
    char buffer[64 * 1024];
    while (text.size() <= kMaxSceneFileBytes) {
        in.read(buffer, sizeof buffer);
        if (in.gcount() <= 0)
            break;
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad())
        fail(file, fmt::format("cannot read the scene file: {}", std::strerror(errno)));
    if (text.size() > kMaxSceneFileBytes)
        fail(file, fmt::format("the scene file is over {} bytes; scene files are at most 4 MiB", kMaxSceneFileBytes));
    return parseScene(text, path);
}

void validateScene(const Scene& scene, const fs::path& sceneFile)
{
    checkScene(scene, Places(sceneFile.string()), baseFolder(sceneFile));
}

std::string saveScene(const Scene& scene)
{
    std::string out = "# Swell scene. Every key is described in docs/SCENE.md; the comments give each range.\n\n";
    writeParameters(out, scene, "", ParameterList::None, 0);

    out += "\n[waves]\n";
    writeParameters(out, scene, "waves", ParameterList::None, 0);
    if (scene.waves.wind) {
        out += "\n[waves.wind]\n";
        writeParameters(out, scene, "waves.wind", ParameterList::None, 0);
        if (scene.waves.wind->swell) {
            out += "\n[waves.swell]\n";
            writeParameters(out, scene, "waves.swell", ParameterList::None, 0);
        }
    } else {
        for (std::size_t i = 0; i < scene.waves.listed.waves.size(); ++i) {
            out += "\n[[waves.list]]\n";
            writeParameters(out, scene, "waves.list", ParameterList::Waves, i);
        }
    }

    for (std::string_view table : {"grid", "sun", "sky", "fog", "water", "reflection"}) {
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
        writeParameters(out, scene, "objects", ParameterList::Objects, i);
    }

    out += "\n[camera]\n";
    writeParameters(out, scene, "camera", ParameterList::None, 0);
    for (std::size_t i = 0; i < scene.camera.path.size(); ++i) {
        out += "\n[[camera.path]]\n";
        writeParameters(out, scene, "camera.path", ParameterList::CameraPath, i);
    }
    return out;
}

void saveSceneFile(const Scene& scene, const fs::path& path)
{
    const std::string text = saveScene(scene);

    // Write next to the file a symbolic link points at, not over the link.
    std::error_code ec;
    fs::path target = path;
    if (fs::is_symlink(path, ec)) {
        fs::path resolved = fs::canonical(path, ec);
        if (!ec)
            target = resolved;
    }
    fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    static std::atomic<unsigned> counter{0};
    fs::path temp = folder / fmt::format(".{}.{}-{}.tmp", target.filename().string(), ::getpid(), counter++);

    auto failWith = [&](int error, int fd) {
        if (fd >= 0)
            ::close(fd);
        ::unlink(temp.c_str());
        fail({path.string(), 0, 0}, fmt::format("cannot save the scene: {}", std::strerror(error)));
    };

    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        fail({path.string(), 0, 0}, fmt::format("cannot save the scene: {} ({})", std::strerror(errno), temp.string()));
    // Keep the permissions of the file being replaced.
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0)
        ::fchmod(fd, existing.st_mode & 07777);

    for (std::size_t written = 0; written < text.size();) {
        ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            failWith(n < 0 ? errno : EIO, fd);
        written += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0)
        failWith(errno, fd);
    if (::close(fd) != 0)
        failWith(errno, -1);
    if (::rename(temp.c_str(), target.c_str()) != 0)
        failWith(errno, -1);
    // Make the rename itself durable; a failure here loses nothing already written.
    int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

} // namespace swell
