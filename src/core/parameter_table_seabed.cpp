// The [seabed] rows of the scene parameter table (parameter_table_seabed.h).
// Every change to one builds the sea floor again (ParameterEffect::Seabed)
// and nothing else.
#include "core/parameter_table_seabed.h"

#include "core/parameter_fields.h"

#include <limits>

namespace swell::detail {

namespace {

using namespace parameter_fields;
using K = ParameterKind;
using L = ParameterList;
using E = ParameterEffect;

// The deepest sea on Earth, m: no floor lies deeper or stands higher.
constexpr double kDeepest_m = 11000.0;
// The steepest slope a shape may have (rise over run): 1000, a cliff.
constexpr double kSteepest = 1000.0;


} // namespace

std::vector<Parameter> seabedParameters()
{
    return {
        // [seabed]
        at([](auto& s, std::size_t) -> auto& { return s.seabed.toeDepth_m; },
           {.key = "seabed.toe_depth_m", .effect = E::Seabed, .unit = "m", .min = 0.0, .max = kDeepest_m,
            .minExclusive = true, .sliderMin = 5.0, .sliderMax = 1000.0, .logarithmic = true,
            .description = "where beaches' and shelves' slopes end when the sea is deeper (waves.depth_m = inf: "
                           "deep water beyond them)",
            .present = &seabedIsSet}),
        // [[seabed.beaches]]
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].shorePoint_m; },
           {.key = "seabed.beaches.shore_point_m", .kind = K::Vector2, .list = L::SeabedBeaches, .effect = E::Seabed,
            .unit = "m", .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -5000.0, .sliderMax = 5000.0,
            .description = "world [x, z] of a point where the floor crosses the sea's mean level"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].seawardAzimuth_deg; },
           {.key = "seabed.beaches.seaward_azimuth_deg", .list = L::SeabedBeaches, .effect = E::Seabed, .unit = "deg",
            .min = -kAngleLimit_deg, .max = kAngleLimit_deg, .sliderMin = -180.0, .sliderMax = 180.0,
            .description = "the way the beach faces the sea (down its slope), like a heading: from -z (north) towards "
                           "+x (east)"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].slope; },
           {.key = "seabed.beaches.slope", .list = L::SeabedBeaches, .effect = E::Seabed, .min = 0.0, .max = kSteepest,
            .minExclusive = true, .sliderMin = 0.005, .sliderMax = 0.5, .logarithmic = true,
            .description = "rise over run (0.02: 1:50)"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].length_m; },
           {.key = "seabed.beaches.length_m", .list = L::SeabedBeaches, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kWorldLimit_m, .minExclusive = true, .sliderMin = 10.0, .sliderMax = 10000.0, .logarithmic = true,
            .description = "how far the beach reaches along the shore, centred on shore_point_m"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].top_m; },
           {.key = "seabed.beaches.top_m", .list = L::SeabedBeaches, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kDeepest_m, .minExclusive = true, .sliderMin = 0.5, .sliderMax = 50.0, .logarithmic = true,
            .description = "how far up the land the beach reaches: its top's height above the sea's mean level"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.beaches[i].landWidth_m; },
           {.key = "seabed.beaches.land_width_m", .list = L::SeabedBeaches, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kWorldLimit_m, .sliderMin = 0.0, .sliderMax = 1000.0,
            .description = "the flat land behind the beach's top"}),
        // [[seabed.shelves]]
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].edgePoint_m; },
           {.key = "seabed.shelves.edge_point_m", .kind = K::Vector2, .list = L::SeabedShelves, .effect = E::Seabed,
            .unit = "m", .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -5000.0, .sliderMax = 5000.0,
            .description = "world [x, z] of a point on the top line of the shelf's sloping edge"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].seawardAzimuth_deg; },
           {.key = "seabed.shelves.seaward_azimuth_deg", .list = L::SeabedShelves, .effect = E::Seabed, .unit = "deg",
            .min = -kAngleLimit_deg, .max = kAngleLimit_deg, .sliderMin = -180.0, .sliderMax = 180.0,
            .description = "the way the edge slopes down, like a heading: from -z (north) towards +x (east)"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].depth_m; },
           {.key = "seabed.shelves.depth_m", .list = L::SeabedShelves, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kDeepest_m, .sliderMin = 0.0, .sliderMax = 100.0,
            .description = "the flat top's depth below the sea's mean level"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].slope; },
           {.key = "seabed.shelves.slope", .list = L::SeabedShelves, .effect = E::Seabed, .min = 0.0, .max = kSteepest,
            .minExclusive = true, .sliderMin = 0.005, .sliderMax = 1.0, .logarithmic = true,
            .description = "the edge's rise over run"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].width_m; },
           {.key = "seabed.shelves.width_m", .list = L::SeabedShelves, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kWorldLimit_m, .minExclusive = true, .sliderMin = 10.0, .sliderMax = 10000.0, .logarithmic = true,
            .description = "how far the flat top reaches landward from the edge"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.shelves[i].length_m; },
           {.key = "seabed.shelves.length_m", .list = L::SeabedShelves, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kWorldLimit_m, .minExclusive = true, .sliderMin = 10.0, .sliderMax = 10000.0, .logarithmic = true,
            .description = "how far the shelf reaches along its edge, centred on edge_point_m"}),
        // [[seabed.breakwaters]]
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.breakwaters[i].start_m; },
           {.key = "seabed.breakwaters.start_m", .kind = K::Vector2, .list = L::SeabedBreakwaters, .effect = E::Seabed,
            .unit = "m", .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -5000.0, .sliderMax = 5000.0,
            .description = "world [x, z] of one end of the crest's axis"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.breakwaters[i].end_m; },
           {.key = "seabed.breakwaters.end_m", .kind = K::Vector2, .list = L::SeabedBreakwaters, .effect = E::Seabed,
            .unit = "m", .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -5000.0, .sliderMax = 5000.0,
            .description = "world [x, z] of the other end; not start_m"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.breakwaters[i].crest_m; },
           {.key = "seabed.breakwaters.crest_m", .list = L::SeabedBreakwaters, .effect = E::Seabed, .unit = "m",
            .min = -kDeepest_m, .max = kDeepest_m, .sliderMin = -5.0, .sliderMax = 15.0,
            .description = "the crest's height above the sea's mean level (< 0: a submerged breakwater)"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.breakwaters[i].crestWidth_m; },
           {.key = "seabed.breakwaters.crest_width_m", .list = L::SeabedBreakwaters, .effect = E::Seabed, .unit = "m",
            .min = 0.0, .max = 1000.0, .minExclusive = true, .sliderMin = 1.0, .sliderMax = 50.0, .logarithmic = true,
            .description = "the crest's width"}),
        at([](auto& s, std::size_t i) -> auto& { return s.seabed.breakwaters[i].sideSlope; },
           {.key = "seabed.breakwaters.side_slope", .list = L::SeabedBreakwaters, .effect = E::Seabed, .min = 0.0,
            .max = kSteepest, .minExclusive = true, .sliderMin = 0.1, .sliderMax = 10.0, .logarithmic = true,
            .description = "the sides' rise over run down to the floor (0.67: 1:1.5, a rubble mound's)"}),
        // [seabed.heightmap]
        at([](auto& s, std::size_t) -> auto& { return s.seabed.heightmap.center_m; },
           {.key = "seabed.heightmap.center_m", .kind = K::Vector2, .effect = E::Seabed, .unit = "m",
            .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -5000.0, .sliderMax = 5000.0,
            .description = "world [x, z] of the image's centre", .present = &heightmapIsSet}),
        at([](auto& s, std::size_t) -> auto& { return s.seabed.heightmap.size_m; },
           {.key = "seabed.heightmap.size_m", .kind = K::Vector2, .effect = E::Seabed, .unit = "m", .min = 0.0,
            .max = kWorldLimit_m, .minExclusive = true, .sliderMin = 10.0, .sliderMax = 10000.0,
            .description = "the image's size along x and z; its first and last pixels lie on the edges", .present = &heightmapIsSet}),
        at([](auto& s, std::size_t) -> auto& { return s.seabed.heightmap.blackHeight_m; },
           {.key = "seabed.heightmap.black_height_m", .effect = E::Seabed, .unit = "m", .min = -kDeepest_m,
            .max = kDeepest_m, .sliderMin = -100.0, .sliderMax = 100.0,
            .description = "the height black means, above the sea's mean level", .present = &heightmapIsSet}),
        at([](auto& s, std::size_t) -> auto& { return s.seabed.heightmap.whiteHeight_m; },
           {.key = "seabed.heightmap.white_height_m", .effect = E::Seabed, .unit = "m", .min = -kDeepest_m,
            .max = kDeepest_m, .sliderMin = -100.0, .sliderMax = 100.0,
            .description = "the height white means, above the sea's mean level", .present = &heightmapIsSet}),
    };
}

} // namespace swell::detail
