// How the scene parameter table (core/parameter_table.cpp) binds a key to
// its place in Scene: a field reached by a small generic lambda (at()), a
// field of the sun's optional place (placing()), the wind and swell that a
// write switches on, and the predicates that say when a key applies.
// Internal to the table.
#pragma once

#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"
#include "swell/scene/sun_position.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace swell::parameter_fields {

// World coordinates beyond this lose too much precision in the GPU's floats
// (1 mm steps at 1e4 m, 10 cm at 1e6 m), so positions stop here, m.
inline constexpr double kWorldLimit_m = 1.0e6;
// Angles may wind round several times (a camera path that turns twice), deg.
inline constexpr double kAngleLimit_deg = 3600.0;

// The wind settings, for reading (defaults when the wind is not set) and for
// writing (setting a wind parameter turns the wind on).
inline const WindSettings& wind(const Scene& s)
{
    static const WindSettings none;
    return s.sea.wind ? *s.sea.wind : none;
}
inline WindSettings& wind(Scene& s)
{
    if (!s.sea.wind)
        s.sea.wind.emplace();
    return *s.sea.wind;
}

// The swell, likewise: setting a swell parameter turns the wind and the swell on.
inline const SwellSettings& swellOf(const Scene& s)
{
    static const SwellSettings none;
    return s.sea.wind && s.sea.wind->swell ? *s.sea.wind->swell : none;
}
inline SwellSettings& swellOf(Scene& s)
{
    WindSettings& w = wind(s);
    if (!w.swell)
        w.swell.emplace();
    return *w.swell;
}

template <class T>
ParameterValue toValue(const T& x)
{
    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, double>)
        return x;
    else if constexpr (std::is_enum_v<T> || std::is_integral_v<T>)
        return static_cast<std::int64_t>(x);
    else
        return x; // glm::dvec2, glm::dvec3
}

template <class T>
T fromValue(const ParameterValue& v)
{
    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, double>)
        return std::get<T>(v);
    else if constexpr (std::is_enum_v<T> || std::is_integral_v<T>)
        return static_cast<T>(std::get<std::int64_t>(v));
    else
        return std::get<T>(v);
}

// Ref is a capture-less generic lambda (auto& scene, size_t item) -> auto&
// naming the field, so one lambda serves both the const get and the set.
template <class Ref>
struct Field {
    static ParameterValue get(const Scene& s, std::size_t i) { return toValue(Ref{}(s, i)); }
    static void set(Scene& s, std::size_t i, const ParameterValue& v)
    {
        auto& ref = Ref{}(s, i);
        ref = fromValue<std::remove_cvref_t<decltype(ref)>>(v);
    }
};

template <class Ref>
Parameter at(Ref, Parameter p)
{
    p.get = &Field<Ref>::get;
    p.set = &Field<Ref>::set;
    return p;
}

// The sun's place and time, for reading (defaults when the sun is given by
// its direction) and for writing (setting one places the sun).
inline const SunPlace& placeOf(const Scene& s)
{
    static const SunPlace none;
    return s.sun.place ? *s.sun.place : none;
}
inline SunPlace& placeOf(Scene& s)
{
    if (!s.sun.place)
        s.sun.place.emplace();
    return *s.sun.place;
}

// A field of the sun's place: setting it moves the sun there and then, so
// sun.direction, which everything downstream reads (and whose change
// bakes the sky again), never disagrees with the place.
template <class Ref>
struct PlaceField {
    static void set(Scene& s, std::size_t i, const ParameterValue& v)
    {
        s.sun.angles.reset(); // one form at a time: the place is now the sun's
        Field<Ref>::set(s, i, v);
        const SunPlace& place = *s.sun.place;
        s.sun.direction = sunDirectionOf(solarPosition(place.time_s, place.latitude_deg, place.longitude_deg));
    }
};

template <class Ref>
Parameter placing(Ref, Parameter p)
{
    p.get = &Field<Ref>::get;
    p.set = &PlaceField<Ref>::set;
    return p;
}

// The sun's angles: those it was given, or else those of its direction
// (the azimuth like a heading, from -z towards +x, in -180..180).
inline SunAngles anglesOf(const Scene& s)
{
    if (s.sun.angles)
        return *s.sun.angles;
    const glm::dvec3 d = glm::normalize(s.sun.direction);
    return {glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0))), glm::degrees(std::atan2(d.x, -d.z))};
}

// sun.elevation_deg or sun.azimuth_deg: setting one places the sun by its
// angles (the other kept as the sun has it) and moves sun.direction there,
// so a sweep may vary one on any base scene, and a saved scene writes back
// the angles it was given.
template <double SunAngles::*Angle>
struct AngleField {
    static ParameterValue get(const Scene& s, std::size_t) { return anglesOf(s).*Angle; }
    static void set(Scene& s, std::size_t, const ParameterValue& v)
    {
        SunAngles angles = anglesOf(s);
        angles.*Angle = std::get<double>(v);
        s.sun.angles = angles;
        s.sun.place.reset();
        SolarPosition seen;
        seen.elevation_deg = angles.elevation_deg;
        seen.azimuth_deg = angles.azimuth_deg;
        s.sun.direction = sunDirectionOf(seen);
    }
};

template <double SunAngles::*Angle>
Parameter angle(Parameter p)
{
    p.get = &AngleField<Angle>::get;
    p.set = &AngleField<Angle>::set;
    return p;
}

// sun.direction: setting it gives the sun by its direction again.
struct DirectionField {
    static ParameterValue get(const Scene& s, std::size_t) { return s.sun.direction; }
    static void set(Scene& s, std::size_t, const ParameterValue& v)
    {
        s.sun.direction = std::get<glm::dvec3>(v);
        s.sun.angles.reset();
        s.sun.place.reset();
    }
};

inline Parameter direction(Parameter p)
{
    p.get = &DirectionField::get;
    p.set = &DirectionField::set;
    return p;
}

inline bool windIsSet(const Scene& s) { return s.sea.wind.has_value(); }
inline bool sunIsPlaced(const Scene& s) { return s.sun.place.has_value(); }
inline bool sunByDirection(const Scene& s) { return !s.sun.place && !s.sun.angles; }
inline bool sunByAngles(const Scene& s) { return s.sun.angles.has_value(); }
inline bool isSpectral(const Scene& s) { return s.waves.model == WaveModelKind::Spectral; }
inline bool swellIsSet(const Scene& s) { return s.sea.wind && s.sea.wind->swell; }
inline bool seabedIsSet(const Scene& s) { return !s.seabed.empty(); }
inline bool heightmapIsSet(const Scene& s) { return !s.seabed.heightmap.path.empty(); }

} // namespace swell::parameter_fields
