// The scene parameter table (swell/scene/parameters.h): every parameter, where its
// value lives in Scene (a small generic lambda that Field<> turns into the
// get/set pair), its unit, range, default and what a change to it costs.
// The checks and formatting built on it are parameters.cpp.
#include "swell/scene/parameters.h"

#include "core/parameter_fields.h"
#include "core/parameter_table_camera.h"
#include "core/parameter_table_seabed.h"

#include "swell/gpu/limits.h"
#include "swell/gpu/variants.h"
#include "swell/scene/sun_position.h"

#include <fmt/format.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace swell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Direction components are normalised on use; this only keeps them finite.
constexpr double kDirectionLimit = 1.0e3;

// The TOML names of the enums, indexed by the enum's value.
constexpr std::array<std::string_view, 2> kReflectionModes{"fixed", "raymarch"};
static_assert(static_cast<int>(ReflectionMode::FixedDistance) == 0 && static_cast<int>(ReflectionMode::RayMarch) == 1);

constexpr std::array<std::string_view, 2> kGridLayouts{"geometric", "paper"};
constexpr std::array<std::string_view, 2> kWaveModels{"gerstner", "spectral"};
static_assert(static_cast<int>(GridLayout::Geometric) == 0 && static_cast<int>(GridLayout::Paper) == 1);

constexpr std::array<std::string_view, 7> kDebugViews{"shaded", "normals", "reflection", "refraction", "lod", "wireframe", "foam"};
static_assert(static_cast<int>(DebugView::Shaded) == SWELL_VIEW_SHADED && static_cast<int>(DebugView::Normals) == SWELL_VIEW_NORMALS
              && static_cast<int>(DebugView::Reflection) == SWELL_VIEW_REFLECTION
              && static_cast<int>(DebugView::Refraction) == SWELL_VIEW_REFRACTION
              && static_cast<int>(DebugView::Lod) == SWELL_VIEW_LOD && static_cast<int>(DebugView::Wireframe) == SWELL_VIEW_WIREFRAME);

constexpr std::array<std::string_view, 3> kLabelWorldFrames{"swell", "enu", "ned"};
static_assert(static_cast<int>(LabelWorldFrame::Swell) == 0 && static_cast<int>(LabelWorldFrame::Enu) == 1
              && static_cast<int>(LabelWorldFrame::Ned) == 2);


constexpr std::array<std::string_view, 3> kAntialiasing{"off", "msaa4", "fxaa"};
static_assert(static_cast<int>(Antialiasing::Off) == 0 && static_cast<int>(Antialiasing::Msaa4) == 1
              && static_cast<int>(Antialiasing::Fxaa) == 2);

constexpr std::array<std::string_view, 2> kSkyModels{"gradient", "physical"};
constexpr std::array<std::string_view, 2> kFogModels{"linear", "atmosphere"};
static_assert(static_cast<int>(FogModel::Linear) == 0 && static_cast<int>(FogModel::Atmosphere) == 1);
static_assert(static_cast<int>(SkyModel::Gradient) == 0 && static_cast<int>(SkyModel::Physical) == 1);

constexpr std::array<std::string_view, 2> kSpreadings{"mitsuyasu", "donelan-banner"};
static_assert(static_cast<int>(SpreadingModel::Mitsuyasu) == 0 && static_cast<int>(SpreadingModel::DonelanBanner) == 1);

// Where each parameter lives in Scene: core/parameter_fields.h.
using namespace parameter_fields;

using K = ParameterKind;
using L = ParameterList;
using E = ParameterEffect;

std::vector<Parameter> buildTable()
{
    // Keep in the order of scene.h; scene files and docs list them so.
    std::vector<Parameter> t{
        // [waves]
        at([](auto& s, std::size_t) -> auto& { return s.waves.model; },
           {.key = "waves.model", .kind = K::Choice, .effect = E::Waves, .min = 0.0, .max = kWaveModels.size() - 1.0,
            .sliderMin = 0.0, .sliderMax = kWaveModels.size() - 1.0,
            .description = "gerstner: a sum of waves, listed or from the wind; spectral: the wind's spectrum on FFT cascades",
            .choices = kWaveModels}),
        at([](auto& s, std::size_t) -> auto& { return s.waves.choppiness; },
           {.key = "waves.choppiness", .effect = E::Waves, .min = 0.0, .max = 2.0, .sliderMin = 0.0, .sliderMax = 2.0,
            .description = "spectral model: how far crests lean and troughs widen (0: linear sea)", .present = isSpectral}),
        at([](auto& s, std::size_t) -> auto& { return s.waves.foamLifetime_s; },
           {.key = "waves.foam_lifetime_s", .effect = E::Waves, .unit = "s", .min = 0.0, .max = 60.0, .sliderMin = 0.0,
            .sliderMax = 20.0, .description = "spectral model: e-folding time of whitecap foam (salt water: 3.85); 0: no foam",
            .present = isSpectral}),
        at([](auto& s, std::size_t) -> auto& { return s.sea.depth_m; },
           {.key = "waves.depth_m", .effect = E::Waves | E::Bodies | E::Seabed, .unit = "m", .min = 0.0, .max = kInf, .minExclusive = true,
            .sliderMin = 1.0, .sliderMax = 500.0, .logarithmic = true,
            .description = "water depth for listed and wind waves; inf is deep water"}),
        // [waves.wind]
        at([](auto& s, std::size_t) -> auto& { return wind(s).windSpeed_mps; },
           {.key = "waves.wind.speed_mps", .effect = E::Waves, .unit = "m/s", .min = 0.5, .max = 40.0,
            .sliderMin = 0.5, .sliderMax = 40.0, .description = "wind speed 10 m above the sea", .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).windDirection_deg; },
           {.key = "waves.wind.direction_deg", .effect = E::Waves, .unit = "deg", .min = -360.0, .max = 360.0,
            .sliderMin = 0.0, .sliderMax = 360.0, .description = "direction the wind blows towards, from +x towards +z",
            .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).spread_deg; },
           {.key = "waves.wind.spread_deg", .effect = E::Waves, .unit = "deg", .min = 0.0, .max = 180.0,
            .sliderMin = 0.0, .sliderMax = 180.0, .description = "half-width of the spread of wave directions around the wind",
            .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).fetch_km; },
           {.key = "waves.wind.fetch_km", .effect = E::Waves, .unit = "km", .min = 1.0, .max = 10000.0,
            .sliderMin = 1.0, .sliderMax = 10000.0, .logarithmic = true,
            .description = "distance over which the wind has blown; short fetch, young short waves", .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).waveCount; },
           {.key = "waves.wind.count", .kind = K::Integer, .effect = E::Waves, .min = 1.0, .max = SWELL_MAX_WAVES,
            .sliderMin = 1.0, .sliderMax = SWELL_MAX_WAVES, .description = "how many waves to generate",
            .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).minWavelength_m; },
           {.key = "waves.wind.min_wavelength_m", .effect = E::Waves, .unit = "m", .min = 0.01, .max = 1000.0,
            .sliderMin = 0.1, .sliderMax = 50.0, .logarithmic = true, .description = "shortest wave generated",
            .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).seed; },
           {.key = "waves.wind.seed", .kind = K::Integer, .effect = E::Waves, .min = 0.0, .max = 4294967295.0,
            .sliderMin = 0.0, .sliderMax = 1000.0, .description = "random seed; the same seed gives the same waves",
            .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).steepness; },
           {.key = "waves.wind.steepness", .effect = E::Waves, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "overall choppiness, scaled down to stay fold-free", .present = windIsSet}),
        at([](auto& s, std::size_t) -> auto& { return wind(s).spreading; },
           {.key = "waves.wind.spreading", .kind = K::Choice, .effect = E::Waves, .min = 0.0,
            .max = kSpreadings.size() - 1.0, .sliderMin = 0.0, .sliderMax = kSpreadings.size() - 1.0,
            .description = "how wave energy spreads over directions: cos^2s (Mitsuyasu/Hasselmann) or sech^2 (Donelan-Banner)",
            .choices = kSpreadings, .present = windIsSet}),
        // [waves.swell]
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).height_m; },
           {.key = "waves.swell.height_m", .effect = E::Waves, .unit = "m", .min = 0.0, .max = 15.0, .sliderMin = 0.0,
            .sliderMax = 8.0, .description = "significant wave height of the swell alone", .present = swellIsSet}),
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).period_s; },
           {.key = "waves.swell.period_s", .effect = E::Waves, .unit = "s", .min = 3.0, .max = 25.0, .sliderMin = 3.0,
            .sliderMax = 25.0, .description = "peak period; long swell from afar is 10-20 s", .present = swellIsSet}),
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).direction_deg; },
           {.key = "waves.swell.direction_deg", .effect = E::Waves, .unit = "deg", .min = -360.0, .max = 360.0,
            .sliderMin = 0.0, .sliderMax = 360.0, .description = "direction the swell travels towards, from +x towards +z",
            .present = swellIsSet}),
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).gamma; },
           {.key = "waves.swell.gamma", .effect = E::Waves, .min = 1.0, .max = 10.0, .sliderMin = 1.0, .sliderMax = 10.0,
            .description = "JONSWAP peak enhancement: higher is a narrower band of periods", .present = swellIsSet}),
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).sMax; },
           {.key = "waves.swell.spreading_s", .effect = E::Waves, .min = 1.0, .max = 200.0, .sliderMin = 1.0,
            .sliderMax = 200.0, .logarithmic = true,
            .description = "cos^2s spreading exponent at the peak: 25 young swell, 75 from afar (Goda 1985)",
            .present = swellIsSet}),
        at([](auto& s, std::size_t) -> auto& { return swellOf(s).waveCount; },
           {.key = "waves.swell.count", .kind = K::Integer, .effect = E::Waves, .min = 1.0, .max = SWELL_MAX_WAVES - 1.0,
            .sliderMin = 1.0, .sliderMax = SWELL_MAX_WAVES - 1.0,
            .description = "how many swell waves, on top of waves.wind.count (together at most 64)", .present = swellIsSet}),
        // [[waves.list]]
        at([](auto& s, std::size_t i) -> auto& { return s.waves.listed[i].direction; },
           {.key = "waves.list.direction", .kind = K::Direction2, .list = L::Waves, .effect = E::Waves,
            .min = -kDirectionLimit, .max = kDirectionLimit, .sliderMin = -1.0, .sliderMax = 1.0,
            .description = "direction of travel [x, z]"}),
        at([](auto& s, std::size_t i) -> auto& { return s.waves.listed[i].wavelength_m; },
           {.key = "waves.list.wavelength_m", .list = L::Waves, .effect = E::Waves, .unit = "m", .min = 0.0,
            .max = 10000.0, .minExclusive = true, .sliderMin = 0.1, .sliderMax = 500.0, .logarithmic = true,
            .description = "crest to crest"}),
        at([](auto& s, std::size_t i) -> auto& { return s.waves.listed[i].amplitude_m; },
           {.key = "waves.list.amplitude_m", .list = L::Waves, .effect = E::Waves, .unit = "m", .min = 0.0,
            .max = 100.0, .sliderMin = 0.0, .sliderMax = 5.0, .description = "crest height above rest"}),
        at([](auto& s, std::size_t i) -> auto& { return s.waves.listed[i].steepness; },
           {.key = "waves.list.steepness", .list = L::Waves, .effect = E::Waves, .min = 0.0, .max = 1.0,
            .sliderMin = 0.0, .sliderMax = 1.0, .description = "Gerstner Q: 0 is a sine wave, 1 the sharpest crest"}),
        at([](auto& s, std::size_t i) -> auto& { return s.waves.listed[i].phase_rad; },
           {.key = "waves.list.phase_rad", .list = L::Waves, .effect = E::Waves, .unit = "rad", .min = -1000.0,
            .max = 1000.0, .sliderMin = -kPi, .sliderMax = kPi, .description = "phase offset"}),
        // [grid]
        at([](auto& s, std::size_t) -> auto& { return s.grid.layout; },
           {.key = "grid.layout", .kind = K::Choice, .effect = E::Grid | E::Programs | E::Bodies, .min = 0.0, .max = kGridLayouts.size() - 1.0,
            .sliderMin = 0.0, .sliderMax = kGridLayouts.size() - 1.0,
            .description = "geometric: spacing in proportion to distance, scaled with camera height; paper: the "
                           "paper's quadratic division points",
            .choices = kGridLayouts}),
        at([](auto& s, std::size_t) -> auto& { return s.grid.resolution; },
           {.key = "grid.resolution", .kind = K::Integer, .effect = E::Grid | E::Bodies, .min = 16.0, .max = 2048.0,
            .sliderMin = 16.0, .sliderMax = 2048.0, .logarithmic = true, .description = "grid vertices along each side"}),
        at([](auto& s, std::size_t) -> auto& { return s.grid.radius_m; },
           {.key = "grid.radius_m", .effect = E::Grid | E::Bodies, .unit = "m", .min = 10.0, .max = 100000.0, .sliderMin = 100.0,
            .sliderMax = 20000.0, .logarithmic = true, .description = "half-size of the detailed grid around the camera"}),
        at([](auto& s, std::size_t) -> auto& { return s.grid.fadeStart_m; },
           {.key = "grid.fade_start_m", .unit = "m", .min = 0.0, .max = 100000.0, .sliderMin = 0.0,
            .sliderMax = 20000.0, .description = "distance from the camera where wave height starts to fade"}),
        at([](auto& s, std::size_t) -> auto& { return s.grid.fadeEnd_m; },
           {.key = "grid.fade_end_m", .unit = "m", .min = 0.0, .max = 100000.0, .sliderMin = 0.0,
            .sliderMax = 20000.0,
            .description = "distance where the water is flat; > fade_start_m, <= radius_m"}),
        // [sun]
        direction({.key = "sun.direction", .kind = K::Direction3, .min = -kDirectionLimit, .max = kDirectionLimit,
                   .sliderMin = -1.0, .sliderMax = 1.0,
                   .description = "towards the sun [x, y, z], world space (north -z, east +x); not with sun.time or "
                                  "sun.elevation_deg",
                   .present = sunByDirection}),
        // The sun placed by its angles instead (a sweep's keys too): both set sun.direction.
        angle<&SunAngles::elevation_deg>(
            {.key = "sun.elevation_deg", .unit = "deg", .min = -90.0, .max = 90.0, .sliderMin = -10.0,
             .sliderMax = 90.0,
             .description = "with sun.azimuth_deg: the sun's height above the horizon; sets sun.direction, so the "
                            "sky is baked again",
             .present = sunByAngles}),
        angle<&SunAngles::azimuth_deg>(
            {.key = "sun.azimuth_deg", .unit = "deg", .min = -360.0, .max = 360.0, .sliderMin = 0.0,
             .sliderMax = 360.0,
             .description = "with sun.elevation_deg: the sun's bearing, like a heading from -z (north) towards +x "
                            "(east)",
             .present = sunByAngles}),
        // The sun placed by the date, the time and the place instead
        // (swell/scene/sun_position.h, Michalsky 1988): each sets sun.direction.
        placing([](auto& s, std::size_t) -> auto& { return placeOf(s).time_s; },
                {.key = "sun.time", .kind = K::DateTime, .min = kSolarPositionFirst_s, .max = kSolarPositionLast_s,
                 .sliderMin = 946684800.0, .sliderMax = 1893456000.0,
                 .description = "places the sun by the date and time (with its UTC offset) at sun.latitude_deg and "
                                "sun.longitude_deg (Michalsky 1988); sets sun.direction, so the sky is baked again",
                 .present = sunIsPlaced}),
        placing([](auto& s, std::size_t) -> auto& { return placeOf(s).latitude_deg; },
                {.key = "sun.latitude_deg", .unit = "deg", .min = -90.0, .max = 90.0, .sliderMin = -90.0,
                 .sliderMax = 90.0, .description = "with sun.time: where the sea is, north +", .present = sunIsPlaced}),
        placing([](auto& s, std::size_t) -> auto& { return placeOf(s).longitude_deg; },
                {.key = "sun.longitude_deg", .unit = "deg", .min = -180.0, .max = 180.0, .sliderMin = -180.0,
                 .sliderMax = 180.0, .description = "with sun.time: where the sea is, east +", .present = sunIsPlaced}),
        at([](auto& s, std::size_t) -> auto& { return s.sun.color; },
           {.key = "sun.color", .kind = K::Colour, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "sunlight colour, linear RGB"}),
        at([](auto& s, std::size_t) -> auto& { return s.sun.intensity; },
           {.key = "sun.intensity", .min = 0.0, .max = 20.0, .sliderMin = 0.0, .sliderMax = 20.0,
            .description = "sunlight multiplier"}),
        // [sky]
        at([](auto& s, std::size_t) -> auto& { return s.sky.model; },
           {.key = "sky.model", .kind = K::Choice, .min = 0.0, .max = kSkyModels.size() - 1.0, .sliderMin = 0.0,
            .sliderMax = kSkyModels.size() - 1.0,
            .description = "gradient: the colours below and a glow round the sun; physical: the atmosphere's scattering "
                           "of sunlight, which also sets the sun's colour and intensity and objects' ambient light "
                           "(sun.color and sun.intensity unused); the sky is baked again",
            .choices = kSkyModels}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.zenithColor; },
           {.key = "sky.zenith_color", .kind = K::Colour, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "gradient sky straight up, linear RGB"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.horizonColor; },
           {.key = "sky.horizon_color", .kind = K::Colour, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "gradient sky at the horizon, linear RGB"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.exposure; },
           {.key = "sky.exposure", .min = 0.01, .max = 1000.0, .sliderMin = 1.0, .sliderMax = 100.0, .logarithmic = true,
            .description = "physical sky: displayed linear colour per unit radiance over the sun's irradiance at the "
                           "top of the atmosphere (1/sr); the sky is baked again"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.atmosphere.mieScale; },
           {.key = "sky.mie_scale", .min = 0.0, .max = 20.0, .sliderMin = 0.0, .sliderMax = 10.0,
            .description = "physical sky: aerosol (haze) density over Bruneton 2017's clear air; the atmosphere's "
                           "tables are built again (0.35 s on one core)"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.atmosphere.rayleighScale; },
           {.key = "sky.rayleigh_scale", .min = 0.0, .max = 10.0, .sliderMin = 0.0, .sliderMax = 3.0,
            .description = "physical sky: air density over Bruneton 2017's Earth's at every altitude (its Rayleigh "
                           "scattering: a deeper or paler blue); the atmosphere's tables are built again (0.35 s on "
                           "one core)"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.atmosphere.groundAlbedo; },
           {.key = "sky.ground_albedo", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "physical sky: Lambertian albedo of the surface below (the sea: about 0.06); the "
                           "atmosphere's tables are built again (0.35 s on one core)"}),
        // [sky.clouds]
        at([](auto& s, std::size_t) -> auto& { return s.sky.clouds.cover; },
           {.key = "sky.clouds.cover", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "physical sky: share of the cloud layer that is cloud (0: no layer; 1: an overcast deck "
                           "that hides the sun); the sky is baked again"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.clouds.altitude_m; },
           {.key = "sky.clouds.altitude_m", .unit = "m", .min = 100.0, .max = 12000.0, .sliderMin = 200.0,
            .sliderMax = 8000.0, .logarithmic = true,
            .description = "physical sky: the cloud layer's height over the sea; the sky is baked again"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.clouds.opticalDepth; },
           {.key = "sky.clouds.optical_depth", .min = 0.0, .max = 200.0, .sliderMin = 0.0, .sliderMax = 80.0,
            .description = "physical sky: a cloud's mean vertical optical depth (fair-weather cumulus a few to 20, "
                           "a storm's deck 30 and more); the sky is baked again"}),
        at([](auto& s, std::size_t) -> auto& { return s.sky.clouds.scale_m; },
           {.key = "sky.clouds.scale_m", .unit = "m", .min = 200.0, .max = 50000.0, .sliderMin = 500.0,
            .sliderMax = 20000.0, .logarithmic = true,
            .description = "physical sky: the size of the cloud layer's largest shapes; the sky is baked again"}),
        // [fog]
        at([](auto& s, std::size_t) -> auto& { return s.fog.model; },
           {.key = "fog.model", .kind = K::Choice, .min = 0.0, .max = kFogModels.size() - 1.0, .sliderMin = 0.0,
            .sliderMax = kFogModels.size() - 1.0,
            .description = "linear: the paper's ramp towards fog.color; atmosphere: aerial perspective, the veil "
                           "coloured by the sky at the horizon in each view's azimuth (fog.color unused) and, with "
                           "the physical sky, the clear air's extinction added to the ramp",
            .choices = kFogModels}),
        at([](auto& s, std::size_t) -> auto& { return s.fog.start_m; },
           {.key = "fog.start_m", .unit = "m", .min = 0.0, .max = kWorldLimit_m, .sliderMin = 0.0, .sliderMax = 20000.0,
            .description = "distance from the camera where fog begins"}),
        at([](auto& s, std::size_t) -> auto& { return s.fog.end_m; },
           {.key = "fog.end_m", .unit = "m", .min = 0.0, .max = kWorldLimit_m, .sliderMin = 0.0, .sliderMax = 20000.0,
            .description = "distance where fog is complete; > start_m"}),
        at([](auto& s, std::size_t) -> auto& { return s.fog.color; },
           {.key = "fog.color", .kind = K::Colour, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "fog colour, linear RGB (fog.model = \"linear\")"}),
        // [water]
        at([](auto& s, std::size_t) -> auto& { return s.water.deepColor; },
           {.key = "water.deep_color", .kind = K::Colour, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "light scattered back from deep water, linear RGB"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.absorption_per_m; },
           {.key = "water.absorption_per_m", .kind = K::Vector3, .unit = "1/m", .min = 0.0, .max = 100.0,
            .sliderMin = 0.0, .sliderMax = 2.0, .description = "Beer-Lambert absorption per channel [r, g, b]"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.fresnelF0; },
           {.key = "water.fresnel_f0", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 0.2,
            .description = "reflectance looking straight down (water: 0.02)"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.shininess; },
           {.key = "water.shininess", .min = 1.0, .max = 10000.0, .sliderMin = 1.0, .sliderMax = 10000.0,
            .logarithmic = true, .description = "Phong specular exponent of the sun glint"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.specularStrength; },
           {.key = "water.specular_strength", .min = 0.0, .max = 10.0, .sliderMin = 0.0, .sliderMax = 10.0,
            .description = "sun glint multiplier"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.refractionDistortion; },
           {.key = "water.refraction_distortion", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 0.3,
            .description = "how far the normal bends the refraction lookup"}),
        at([](auto& s, std::size_t) -> auto& { return s.sea.level_m; },
           {.key = "water.level_m", .effect = E::Bodies | E::Seabed, .unit = "m", .min = -1.0e4, .max = 1.0e4, .sliderMin = -10.0, .sliderMax = 500.0,
            .description = "the water's mean level: the height of the surface at rest (a lake at 300 m)"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.caustics; },
           {.key = "water.caustics", .kind = K::Flag, .effect = E::Programs, .min = 0.0, .max = 1.0, .sliderMin = 0.0,
            .sliderMax = 1.0,
            .description = "the sun's light focused by the waves on what lies under the water (a map drawn each "
                           "frame); off: the light under a level surface"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.shafts; },
           {.key = "water.shafts", .kind = K::Flag, .effect = E::Programs, .min = 0.0, .max = 1.0, .sliderMin = 0.0,
            .sliderMax = 1.0,
            .description = "shafts of light seen from under the water: the sun's light the water scatters towards the "
                           "eye, focused by the waves (the caustics map read along each ray); off: none of it"}),
        at([](auto& s, std::size_t) -> auto& { return s.water.spray; },
           {.key = "water.spray", .kind = K::Flag, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "spray torn from the breaking crests and carried downwind, from Beaufort 7 (13.9 m/s) "
                           "up, growing with the wind to Beaufort 10 (spectral model only), and thrown from the "
                           "bows of rigid bodies under way (any model); off: none"}),
        // [reflection]
        at([](auto& s, std::size_t) -> auto& { return s.reflection.mode; },
           {.key = "reflection.mode", .kind = K::Choice, .effect = E::Programs, .min = 0.0, .max = kReflectionModes.size() - 1.0,
            .sliderMin = 0.0, .sliderMax = kReflectionModes.size() - 1.0,
            .description = "raymarch: what the reflected ray really meets, else the sky; fixed: step a fixed distance along it",
            .choices = kReflectionModes}),
        at([](auto& s, std::size_t) -> auto& { return s.reflection.fixedDistance_m; },
           {.key = "reflection.fixed_distance_m", .unit = "m", .min = 0.0, .max = 1000.0, .minExclusive = true,
            .sliderMin = 0.5, .sliderMax = 50.0, .logarithmic = true,
            .description = "step along the reflected ray in fixed mode"}),
        at([](auto& s, std::size_t) -> auto& { return s.reflection.resolutionScale; },
           {.key = "reflection.resolution_scale", .min = 0.1, .max = 1.0, .sliderMin = 0.1,
            .sliderMax = 1.0, .description = "reflection and refraction target size relative to the output"}),
        at([](auto& s, std::size_t) -> auto& { return s.reflection.clipOffset_m; },
           {.key = "reflection.clip_offset_m", .unit = "m", .min = 0.0, .max = 10.0, .sliderMin = 0.0, .sliderMax = 2.0,
            .description = "the mirrored world is clipped this far below the water plane"}),
        // [[objects]]
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].position_m; },
           {.key = "objects.position_m", .kind = K::Vector3, .list = L::Objects, .effect = E::Bodies, .unit = "m", .min = -kWorldLimit_m,
            .max = kWorldLimit_m, .sliderMin = -1000.0, .sliderMax = 1000.0, .description = "world position [x, y, z]"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].yaw_deg; },
           {.key = "objects.yaw_deg", .list = L::Objects, .effect = E::Bodies, .unit = "deg", .min = -kAngleLimit_deg, .max = kAngleLimit_deg,
            .sliderMin = -180.0, .sliderMax = 180.0, .description = "rotation about +y"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].scale; },
           {.key = "objects.scale", .list = L::Objects, .effect = E::Bodies, .min = 0.0, .max = 10000.0, .minExclusive = true,
            .sliderMin = 0.01, .sliderMax = 100.0, .logarithmic = true, .description = "uniform scale"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].floats; },
           {.key = "objects.floats", .kind = K::Flag, .list = L::Objects, .effect = E::Bodies, .min = 0.0, .max = 1.0, .sliderMin = 0.0,
            .sliderMax = 1.0, .description = "ride the waves: height and tilt follow the surface"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].mass_kg; },
           {.key = "objects.mass_kg", .list = L::Objects, .effect = E::Bodies, .unit = "kg", .min = 0.0, .max = 1.0e9, .sliderMin = 0.0,
            .sliderMax = 1.0e4, .description = "floating rigid body's mass; 0: from density_kg_per_m3 (give one)"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].density_kg_per_m3; },
           {.key = "objects.density_kg_per_m3", .list = L::Objects, .effect = E::Bodies, .unit = "kg/m^3", .min = 0.0, .max = 1.0e5,
            .sliderMin = 0.0, .sliderMax = 1000.0,
            .description = "floating rigid body's mean density over its closed volume; 0: from mass_kg"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].centerOfMassOffset_m; },
           {.key = "objects.center_of_mass_offset_m", .kind = K::Vector3, .list = L::Objects, .effect = E::Bodies, .unit = "m", .min = -1.0e3,
            .max = 1.0e3, .sliderMin = -5.0, .sliderMax = 5.0,
            .description = "rigid body: centre of mass from the volume's centroid, model axes [x, y, z]"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].inertia_kg_m2; },
           {.key = "objects.inertia_kg_m2", .kind = K::Vector3, .list = L::Objects, .effect = E::Bodies, .unit = "kg*m^2", .min = 0.0,
            .max = 1.0e15, .sliderMin = 0.0, .sliderMax = 1.0e6,
            .description = "rigid body: principal moments about the centre of mass, model axes: all three > 0, or "
                           "[0, 0, 0]: from the mesh"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].velocity_m_per_s; },
           {.key = "objects.velocity_m_per_s", .kind = K::Vector3, .list = L::Objects, .effect = E::Bodies, .unit = "m/s", .min = -100.0,
            .max = 100.0, .sliderMin = -20.0, .sliderMax = 20.0,
            .description = "rigid body: carried at [x, z] (a boat under way); y: its heave velocity at its start"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].dampingRatio; },
           {.key = "objects.damping_ratio", .list = L::Objects, .effect = E::Bodies, .min = 0.0, .max = 2.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "rigid body: fraction of critical damping in heave, roll and pitch"}),
        // [[objects]] of the fleet (isFleetPath; docs/SCENE.md, "The fleet")
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].length_m; },
           {.key = "objects.length_m", .list = L::Objects, .effect = E::World | E::Bodies, .unit = "m", .min = 0.0,
            .max = 1000.0, .sliderMin = 0.0, .sliderMax = 400.0,
            .description = "the fleet's: overall length, 0.5 to 2 times the design's, draft kept; 0: the design's"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].beam_m; },
           {.key = "objects.beam_m", .list = L::Objects, .effect = E::World | E::Bodies, .unit = "m", .min = 0.0,
            .max = 200.0, .sliderMin = 0.0, .sliderMax = 60.0,
            .description = "the fleet's: greatest beam, 0.75 to 1.5 times the design's, draft kept; 0: the design's"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].hullColor; },
           {.key = "objects.hull_color", .kind = K::Colour, .list = L::Objects, .effect = E::World, .min = -1.0,
            .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "the fleet's: the hull's paint, linear RGB, each 0..1; [-1, -1, -1]: the model's own"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].superstructureColor; },
           {.key = "objects.superstructure_color", .kind = K::Colour, .list = L::Objects, .effect = E::World,
            .min = -1.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "the fleet's: the superstructure's paint, linear RGB, each 0..1; [-1, -1, -1]: the "
                           "model's own"}),
        at([](auto& s, std::size_t i) -> auto& { return s.objects[i].superstructure; },
           {.key = "objects.superstructure", .kind = K::Flag, .list = L::Objects, .effect = E::World, .min = 0.0,
            .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "the fleet's: draw its superstructure (wheelhouse, coachroof, a kayak's paddler, a "
                           "buoy's topmark)"}),
        // [wake]
        at([](auto& s, std::size_t) -> auto& { return s.wake.enabled; },
           {.key = "wake.enabled", .kind = K::Flag, .effect = E::Programs | E::Bodies, .min = 0.0, .max = 1.0, .sliderMin = 0.0,
            .sliderMax = 1.0, .description = "moving floating rigid bodies leave wakes (waves and foam)"}),
        at([](auto& s, std::size_t) -> auto& { return s.wake.cells; },
           {.key = "wake.cells", .kind = K::Integer, .effect = E::Bodies, .min = 32.0, .max = 1024.0, .sliderMin = 32.0, .sliderMax = 1024.0,
            .logarithmic = true, .description = "wake field cells along each side, rounded up to a product of 2, 3 and 5 (CPU cost grows as cells^2 log cells)"}),
        at([](auto& s, std::size_t) -> auto& { return s.wake.cellSize_m; },
           {.key = "wake.cell_size_m", .effect = E::Bodies, .unit = "m", .min = 0.1, .max = 10.0, .sliderMin = 0.25, .sliderMax = 4.0,
            .logarithmic = true, .description = "wake field cell size: waves shorter than 2 cells are not carried"}),
        // [seabed] follows (parameter_table_seabed.cpp)
        // [camera], [[camera.path]] and [[camera.rig]] follow (parameter_table_camera.cpp)
        // [labels]
        at([](auto& s, std::size_t) -> auto& { return s.labels.worldFrame; },
           {.key = "labels.world_frame", .kind = K::Choice, .min = 0.0, .max = kLabelWorldFrames.size() - 1.0,
            .sliderMin = 0.0, .sliderMax = kLabelWorldFrames.size() - 1.0,
            .description = "the axes of the labels' world quantities: swell (x east, y up, -z north), enu (east, "
                           "north, up) or ned (north, east, down)",
            .choices = kLabelWorldFrames}),
        // top level
        at([](auto& s, std::size_t) -> auto& { return s.debugView; },
           {.key = "debug_view", .kind = K::Choice, .effect = E::Programs, .min = 0.0, .max = kDebugViews.size() - 1.0, .sliderMin = 0.0,
            .sliderMax = kDebugViews.size() - 1.0, .description = "what the water shows: the shaded ocean or one ingredient",
            .choices = kDebugViews}),
        at([](auto& s, std::size_t) -> auto& { return s.showTerrain; },
           {.key = "terrain", .kind = K::Flag, .effect = E::World | E::Seabed, .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 1.0,
            .description = "draw the built-in island (part of the sea floor too)"}),
        at([](auto& s, std::size_t) -> auto& { return s.antialiasing; },
           {.key = "antialiasing", .kind = K::Choice, .min = 0.0, .max = kAntialiasing.size() - 1.0, .sliderMin = 0.0,
            .sliderMax = kAntialiasing.size() - 1.0,
            .description = "edge smoothing of the main pass: fxaa (a post-process), msaa4 (4 samples a pixel) or off",
            .choices = kAntialiasing}),
        at([](auto& s, std::size_t) -> auto& { return s.historyStart_s; },
           {.key = "history_start_s", .effect = E::Waves | E::Bodies, .unit = "s", .min = -kInf, .max = 1.0e9,
            .sliderMin = -120.0, .sliderMax = 120.0,
            .description = "when the foam, floating bodies and their wake start; -inf: the sea has always been going "
                           "(foam developed, bodies started 60 s before t = 0)"}),
    };

    // [seabed] and then [camera] in their places of scene.h, after [wake]
    const auto labels = std::find_if(t.begin(), t.end(), [](const Parameter& p) { return p.key == "labels.world_frame"; });
    std::vector<Parameter> inserted = detail::seabedParameters();
    std::vector<Parameter> camera = detail::cameraParameters();
    inserted.insert(inserted.end(), camera.begin(), camera.end());
    t.insert(labels, inserted.begin(), inserted.end());

    // Defaults come from the member initialisers: a default Scene with one
    // item in every list and the wind switched on.
    Scene prototype;
    prototype.sea.wind.emplace();
    prototype.waves.listed.emplace_back();
    prototype.objects.emplace_back();
    prototype.camera.path.emplace_back();
    prototype.camera.rig.emplace_back();
    prototype.seabed.beaches.emplace_back();
    prototype.seabed.shelves.emplace_back();
    prototype.seabed.breakwaters.emplace_back();
    for (Parameter& p : t)
        p.defaultValue = p.get(prototype, 0);
    return t;
}

} // namespace

std::span<const Parameter> parameters()
{
    static const std::vector<Parameter> table = buildTable();
    return table;
}

const Parameter* findParameter(std::string_view key)
{
    for (const Parameter& p : parameters())
        if (p.key == key)
            return &p;
    return nullptr;
}

} // namespace swell
