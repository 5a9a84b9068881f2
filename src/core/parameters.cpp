// Checks and formatting built on the scene parameter table
// (swell/scene/parameters.h; the table itself is parameter_table.cpp).
#include "swell/scene/parameters.h"


#include <fmt/format.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace swell {
namespace {

using K = ParameterKind;
using L = ParameterList;

// Shortest direction accepted. Directions are normalised on use, some of them
// in the shaders' 32-bit floats, where the squared length of anything far
// shorter underflows to zero (1e-300 does so even in doubles) and the
// normalised result is NaN. At this length the squared length, 1e-24, is far
// above float's smallest normal number (1.2e-38).
constexpr double kMinDirectionLength = 1.0e-12;

// Length of v without underflow or overflow: scaled by its largest component first.
template <class V>
double robustLength(const V& v)
{
    double largest = 0.0;
    for (int c = 0; c < V::length(); ++c)
        largest = std::max(largest, std::abs(v[c]));
    return largest == 0.0 ? 0.0 : largest * glm::length(v / largest);
}

// The problem with direction v (written as `name`), or "" when it is long enough.
template <class V>
std::string directionProblem(const V& v, std::string_view name)
{
    const double length = robustLength(v);
    if (length >= kMinDirectionLength)
        return "";
    std::string written;
    for (int c = 0; c < V::length(); ++c)
        written += fmt::format("{}{}", c > 0 ? ", " : "", v[c]);
    if (length == 0.0)
        return fmt::format("{} is [{}]; a direction must not be zero", name, written);
    return fmt::format("{} is [{}], of length {}; a direction must be at least {} long (it is normalised on use)", name,
                       written, length, kMinDirectionLength);
}

std::string withUnit(std::string text, std::string_view unit)
{
    if (!unit.empty())
        text += fmt::format(" {}", unit);
    return text;
}

std::string formatReal(double x)
{
    if (std::isnan(x))
        return "nan";
    if (std::isinf(x))
        return x > 0 ? "inf" : "-inf";
    std::string s = fmt::format("{}", x);
    // A TOML float needs a '.' or an exponent, or it reads back as an integer.
    if (s.find_first_of(".e") == std::string::npos)
        s += ".0";
    return s;
}

// Numbers in messages and docs: shortest form, "inf" for infinity.
std::string formatNumber(double x)
{
    if (std::isinf(x))
        return x > 0 ? "inf" : "-inf";
    return fmt::format("{}", x);
}

bool holdsKind(const Parameter& p, const ParameterValue& v)
{
    switch (p.kind) {
    case K::Real:
    case K::DateTime: return std::holds_alternative<double>(v);
    case K::Integer:
    case K::Choice: return std::holds_alternative<std::int64_t>(v);
    case K::Flag: return std::holds_alternative<bool>(v);
    case K::Colour:
    case K::Direction3:
    case K::Vector3: return std::holds_alternative<glm::dvec3>(v);
    case K::Direction2:
    case K::Vector2: return std::holds_alternative<glm::dvec2>(v);
    }
    return false;
}

} // namespace


std::string_view listKey(ParameterList list)
{
    switch (list) {
    case L::None: return "";
    case L::Waves: return "waves.list";
    case L::Objects: return "objects";
    case L::CameraPath: return "camera.path";
    case L::CameraRig: return "camera.rig";
    case L::SeabedBeaches: return "seabed.beaches";
    case L::SeabedShelves: return "seabed.shelves";
    case L::SeabedBreakwaters: return "seabed.breakwaters";
    }
    return "";
}

std::vector<std::string> parameterTables(ParameterList list)
{
    std::vector<std::string> tables;
    const std::string_view item = listKey(list);
    const std::size_t from = item.empty() ? 0 : item.size() + 1; // past "objects."
    for (const Parameter& p : parameters()) {
        if (p.list != list)
            continue;
        // Every proper prefix that ends before a dot: "waves" and "waves.wind"
        // for "waves.wind.speed_mps".
        for (std::size_t dot = p.key.find('.', from); dot != std::string_view::npos; dot = p.key.find('.', dot + 1)) {
            std::string table(p.key.substr(0, dot));
            if (std::find(tables.begin(), tables.end(), table) == tables.end())
                tables.push_back(std::move(table));
        }
    }
    return tables;
}

std::size_t listSize(const Scene& scene, ParameterList list)
{
    switch (list) {
    case L::None: return 1;
    case L::Waves: return scene.waves.listed.size();
    case L::Objects: return scene.objects.size();
    case L::CameraPath: return scene.camera.path.size();
    case L::CameraRig: return scene.camera.rig.size();
    case L::SeabedBeaches: return scene.seabed.beaches.size();
    case L::SeabedShelves: return scene.seabed.shelves.size();
    case L::SeabedBreakwaters: return scene.seabed.breakwaters.size();
    }
    return 0;
}

bool isPresent(const Parameter& p, const Scene& scene) { return p.present == nullptr || p.present(scene); }

int componentCount(ParameterKind kind)
{
    switch (kind) {
    case K::Colour:
    case K::Direction3:
    case K::Vector3: return 3;
    case K::Direction2:
    case K::Vector2: return 2;
    default: return 1;
    }
}

bool inRange(const Parameter& p, double x)
{
    if (std::isnan(x))
        return false;
    if (p.minExclusive ? !(x > p.min) : !(x >= p.min))
        return false;
    return x <= p.max; // +inf passes only when max is +inf
}

std::string rangeText(const Parameter& p)
{
    if (p.kind == K::Flag)
        return "true or false";
    if (p.kind == K::DateTime)
        return fmt::format("a date and time with its UTC offset, {} to {}", formatDateTime(p.min), formatDateTime(p.max));
    if (p.kind == K::Choice) {
        std::string s;
        for (std::size_t i = 0; i < p.choices.size(); ++i) {
            if (i > 0)
                s += (i + 1 == p.choices.size()) ? " or " : ", ";
            s += fmt::format("\"{}\"", p.choices[i]);
        }
        return s;
    }
    std::string span;
    if (std::isinf(p.min) && !std::isinf(p.max))
        span = fmt::format("<= {}", formatNumber(p.max));
    else if (std::isinf(p.max))
        span = fmt::format("{} {}", p.minExclusive ? ">" : ">=", formatNumber(p.min));
    else if (p.minExclusive)
        span = fmt::format("> {} and <= {}", formatNumber(p.min), formatNumber(p.max));
    else
        span = fmt::format("{}..{}", formatNumber(p.min), formatNumber(p.max));
    span = withUnit(span, p.unit);
    if (std::isinf(p.max))
        span += ", inf allowed";
    else if (std::isinf(p.min))
        span += ", -inf allowed";
    switch (p.kind) {
    case K::Colour: return "each channel " + span;
    case K::Vector3: return "each component " + span;
    case K::Direction3:
    case K::Direction2: return fmt::format("length >= {}, each component {}", kMinDirectionLength, span);
    default: return span;
    }
}

std::string rangeMessage(const Parameter& p, std::string_view name, double x)
{
    bool finiteExpected = !(std::isinf(x) && (x > 0 ? std::isinf(p.max) : std::isinf(p.min)));
    const char* what = (std::isfinite(x) || !finiteExpected) ? "is out of range" : "is not a finite number";
    const std::string shown = p.kind == K::DateTime && std::isfinite(x) ? formatDateTime(x) : formatNumber(x);
    return fmt::format("{} = {} {}; allowed {}", name, shown, what, rangeText(p));
}

std::string valueProblem(const Parameter& p, const ParameterValue& value, std::string_view name)
{
    if (name.empty())
        name = p.key;
    if (!holdsKind(p, value))
        return fmt::format("{} holds the wrong type of value", name);
    switch (p.kind) {
    case K::Real:
    case K::DateTime: {
        double x = std::get<double>(value);
        return inRange(p, x) ? "" : rangeMessage(p, name, x);
    }
    case K::Integer: {
        double x = static_cast<double>(std::get<std::int64_t>(value));
        return inRange(p, x) ? "" : rangeMessage(p, name, x);
    }
    case K::Choice: {
        std::int64_t i = std::get<std::int64_t>(value);
        if (i >= 0 && static_cast<std::size_t>(i) < p.choices.size())
            return "";
        return fmt::format("{} has no choice number {}; allowed {}", name, i, rangeText(p));
    }
    case K::Flag: return "";
    case K::Colour:
    case K::Direction3:
    case K::Vector3: {
        glm::dvec3 v = std::get<glm::dvec3>(value);
        for (int c = 0; c < 3; ++c)
            if (!inRange(p, v[c]))
                return rangeMessage(p, fmt::format("{}[{}]", name, c), v[c]);
        return p.kind == K::Direction3 ? directionProblem(v, name) : "";
    }
    case K::Direction2:
    case K::Vector2: {
        glm::dvec2 v = std::get<glm::dvec2>(value);
        for (int c = 0; c < 2; ++c)
            if (!inRange(p, v[c]))
                return rangeMessage(p, fmt::format("{}[{}]", name, c), v[c]);
        return p.kind == K::Direction2 ? directionProblem(v, name) : "";
    }
    }
    return "";
}

std::string formatValue(const Parameter& p, const ParameterValue& value)
{
    if (!holdsKind(p, value))
        return "?";
    switch (p.kind) {
    case K::Real: return formatReal(std::get<double>(value));
    case K::DateTime: return formatDateTime(std::get<double>(value));
    case K::Integer: return fmt::format("{}", std::get<std::int64_t>(value));
    case K::Flag: return std::get<bool>(value) ? "true" : "false";
    case K::Choice: {
        std::int64_t i = std::get<std::int64_t>(value);
        if (i >= 0 && static_cast<std::size_t>(i) < p.choices.size())
            return fmt::format("\"{}\"", p.choices[static_cast<std::size_t>(i)]);
        return fmt::format("{}", i);
    }
    case K::Colour:
    case K::Direction3:
    case K::Vector3: {
        glm::dvec3 v = std::get<glm::dvec3>(value);
        return fmt::format("[{}, {}, {}]", formatReal(v.x), formatReal(v.y), formatReal(v.z));
    }
    case K::Direction2:
    case K::Vector2: {
        glm::dvec2 v = std::get<glm::dvec2>(value);
        return fmt::format("[{}, {}]", formatReal(v.x), formatReal(v.y));
    }
    }
    return "?";
}

std::string formatDateTime(double time_s)
{
    if (!std::isfinite(time_s))
        return formatNumber(time_s);
    using namespace std::chrono;
    // Whole seconds and milliseconds (a TOML date-time's fraction; finer
    // than a millisecond moves the sun by less than 1e-5 degree).
    auto seconds = static_cast<std::int64_t>(std::floor(time_s));
    auto milliseconds = static_cast<std::int64_t>(std::llround((time_s - double(seconds)) * 1000.0));
    if (milliseconds == 1000) {
        ++seconds;
        milliseconds = 0;
    }
    const std::int64_t dayNumber = seconds >= 0 ? seconds / 86400 : -((-seconds + 86399) / 86400);
    const year_month_day date{sys_days{days{dayNumber}}};
    const std::int64_t second = seconds - dayNumber * 86400;
    std::string text = fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}", int(date.year()), unsigned(date.month()),
                                   unsigned(date.day()), second / 3600, second / 60 % 60, second % 60);
    if (milliseconds != 0)
        text += fmt::format(".{:03}", milliseconds);
    return text + "Z";
}

} // namespace swell
