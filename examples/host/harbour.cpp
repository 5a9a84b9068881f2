#include "harbour.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace host {

namespace {

// Where the ship lies (world x, z, m) and the camera on it (ship frame, m):
// a person's eye on the port bridge wing, 6 m above the waterline, looking
// ahead and to port at the pier, down the ship's side.
constexpr glm::dvec2 kAnchorage_m{0.0, 0.0};
constexpr glm::dvec3 kBridgeWing_m{-4.3, 6.0, 3.5};
constexpr double kLookToPort_deg = 12.0;
constexpr double kLookDown_deg = 10.0;
// The ship's own roll on top of the water's slope under it: the swell from
// abeam (harbourScene()) rocks it 5 degrees every 9 s (a small coaster's
// natural roll period is 6..12 s; the water's slope alone is under a degree).
constexpr double kRollAmplitude_deg = 5.0;
constexpr double kRollPeriod_s = 9.0;
// The loose crate: where it drifts (world x, z, m) and its size, m.
constexpr glm::dvec2 kLooseCrate_m{-8.5, -21.0};
constexpr double kCrateSide_m = 1.2;

// The floor: the basin's depth, the quay (world x, z rectangle, m, as
// addPier() draws it) and the mole, its crest above the highest swell.
constexpr double kBasinDepth_m = 10.0;
constexpr glm::dvec2 kQuayMin_m{-120.0, -190.0}, kQuayMax_m{10.0, -130.0};
constexpr double kQuayHeight_m = 1.2;
constexpr glm::dvec2 kMoleMin_m{-96.0, -190.0}, kMoleMax_m{-80.0, 70.0};
constexpr double kMoleCrest_m = 3.0;
// The heights' extent and spacing: 4 m samples over 800 m around the anchorage.
constexpr double kFloorHalfSide_m = 400.0;
constexpr int kFloorSamples = 201;

// Linear albedos.
const glm::vec3 kHullAbove{0.05f, 0.09f, 0.16f};  // dark blue topsides
const glm::vec3 kHullBelow{0.32f, 0.05f, 0.03f};  // red antifouling
const glm::vec3 kWhite{0.75f, 0.74f, 0.70f};      // superstructure paint
const glm::vec3 kDeck{0.24f, 0.18f, 0.12f};
const glm::vec3 kHatch{0.16f, 0.13f, 0.10f};
const glm::vec3 kFunnel{0.85f, 0.55f, 0.05f};
const glm::vec3 kMast{0.20f, 0.20f, 0.20f};
const glm::vec3 kPlanks{0.33f, 0.24f, 0.16f};     // weathered pier deck
const glm::vec3 kPiles{0.10f, 0.08f, 0.06f};      // tarred piles
const glm::vec3 kCrate{0.55f, 0.36f, 0.16f};
const glm::vec3 kCrateGreen{0.12f, 0.30f, 0.14f};
const glm::vec3 kShed{0.45f, 0.12f, 0.08f};       // a red harbour shed
const glm::vec3 kRoof{0.20f, 0.22f, 0.24f};

double surfaceY(const swell::DrawnSurface& water, glm::dvec2 xz, double fallback)
{
    const auto p = water.at(xz);
    return p ? p->position_m.y : fallback;
}

void addShip(const glm::dmat4& ship, std::vector<Box>& boxes)
{
    // The hull, its red bottom below the waterline and the blue topsides above.
    boxes.push_back(boxBetween({-3.0, -2.2, -11.0}, {3.0, -0.3, 12.0}, kHullBelow, ship));
    boxes.push_back(boxBetween({-3.0, -0.3, -11.0}, {3.0, 1.6, 12.0}, kHullAbove, ship));
    // The bow: narrower steps towards the stem, decked over.
    boxes.push_back(boxBetween({-2.2, -1.8, -14.0}, {2.2, -0.3, -11.0}, kHullBelow, ship));
    boxes.push_back(boxBetween({-2.2, -0.3, -14.0}, {2.2, 1.6, -11.0}, kHullAbove, ship));
    boxes.push_back(boxBetween({-1.2, -1.2, -16.5}, {1.2, -0.3, -14.0}, kHullBelow, ship));
    boxes.push_back(boxBetween({-1.2, -0.3, -16.5}, {1.2, 1.6, -14.0}, kHullAbove, ship));
    boxes.push_back(boxBetween({-2.9, 1.6, -14.0}, {2.9, 1.7, 12.0}, kDeck, ship));
    boxes.push_back(boxBetween({-1.1, 1.6, -16.4}, {1.1, 1.7, -14.0}, kDeck, ship));
    // The white rail along both sides and round the bow.
    for (double side : {-1.0, 1.0}) {
        boxes.push_back(boxBetween({side * 3.0 - 0.06, 1.6, -11.0}, {side * 3.0 + 0.06, 2.5, 12.0}, kWhite, ship));
        boxes.push_back(boxBetween({side * 2.2 - 0.06, 1.6, -14.0}, {side * 2.2 + 0.06, 2.5, -11.0}, kWhite, ship));
        boxes.push_back(boxBetween({side * 1.2 - 0.06, 1.6, -16.5}, {side * 1.2 + 0.06, 2.5, -14.0}, kWhite, ship));
    }
    // The deckhouse aft, the bridge on it with its wings, the funnel.
    boxes.push_back(boxBetween({-2.4, 1.7, 3.0}, {2.4, 4.4, 10.5}, kWhite, ship));
    boxes.push_back(boxBetween({-4.4, 4.4, 3.4}, {4.4, 5.3, 6.0}, kWhite, ship));
    boxes.push_back(boxBetween({-1.7, 5.3, 3.6}, {1.7, 7.4, 6.0}, kWhite, ship));
    boxes.push_back(boxBetween({-0.6, 4.4, 7.5}, {0.6, 8.0, 9.0}, kFunnel, ship));
    // The foremast and a hatch with cargo on the foredeck.
    boxes.push_back(boxBetween({-0.15, 1.7, -8.2}, {0.15, 13.0, -7.9}, kMast, ship));
    boxes.push_back(boxBetween({-1.8, 1.7, -6.0}, {1.8, 2.3, -1.0}, kHatch, ship));
    boxes.push_back(boxBetween({-1.2, 2.3, -5.4}, {-0.2, 3.3, -4.4}, kCrate, ship));
    boxes.push_back(boxBetween({0.3, 2.3, -3.2}, {1.3, 3.3, -2.2}, kCrateGreen, ship));
}

void addPier(double level_m, std::vector<Box>& boxes)
{
    // A timber pier running out from the shore along the ship's port side.
    const double deck_m = level_m + 2.2;
    boxes.push_back(boxBetween({-24.0, deck_m - 0.35, -130.0}, {-17.0, deck_m, -24.0}, kPlanks));
    for (double z = -26.0; z > -130.0; z -= 6.0)
        for (double x : {-23.4, -17.6})
            boxes.push_back(boxBetween({x - 0.25, level_m - 6.0, z - 0.25}, {x + 0.25, deck_m - 0.35, z + 0.25}, kPiles));
    // Bollards along its edge, crates stacked on it.
    for (double z = -30.0; z > -120.0; z -= 15.0)
        boxes.push_back(boxBetween({-17.8, deck_m, z - 0.2}, {-17.4, deck_m + 0.5, z + 0.2}, kPiles));
    const glm::dvec3 stacks[] = {{-20.5, 0.0, -40.0}, {-21.8, 0.0, -40.3}, {-21.1, 1.0, -40.1},
                                 {-19.5, 0.0, -52.0}, {-21.0, 0.0, -58.0}, {-21.0, 1.0, -58.2},
                                 {-19.7, 0.0, -58.4}};
    int n = 0;
    for (const glm::dvec3& s : stacks) {
        const double side = 1.0 + 0.1 * (n % 3);
        const glm::dvec3 lo{s.x, deck_m + s.y * side, s.z};
        boxes.push_back(boxBetween(lo, lo + glm::dvec3(side), n++ % 4 == 2 ? kCrateGreen : kCrate));
    }
    // The shed at the landward end.
    boxes.push_back(boxBetween({-36.0, level_m - 1.0, -150.0}, {-12.0, level_m + 8.0, -132.0}, kShed));
    boxes.push_back(boxBetween({-36.5, level_m + 8.0, -150.5}, {-11.5, level_m + 8.6, -131.5}, kRoof));
    // The quay it stands on.
    boxes.push_back(boxBetween({-120.0, level_m - 4.0, -190.0}, {10.0, level_m + 1.2, -130.0}, {0.25f, 0.24f, 0.22f}));
    boxes.push_back(boxBetween({-70.0, level_m + 1.2, -175.0}, {-45.0, level_m + 12.0, -150.0}, {0.55f, 0.52f, 0.45f}));
    boxes.push_back(boxBetween({-100.0, level_m + 1.2, -180.0}, {-76.0, level_m + 7.0, -160.0}, kShed));
    // The mole west of the pier, as seabed() gives it to Swell.
    boxes.push_back(boxBetween({kMoleMin_m.x, level_m - kBasinDepth_m, kMoleMin_m.y},
                               {kMoleMax_m.x, level_m + kMoleCrest_m, kMoleMax_m.y}, {0.40f, 0.39f, 0.36f}));
}

bool inside(glm::dvec2 p, glm::dvec2 lo, glm::dvec2 hi) { return p.x >= lo.x && p.y >= lo.y && p.x <= hi.x && p.y <= hi.y; }

} // namespace

Harbour::Harbour(double level_m) : level_m_(level_m) {}

swell::SeabedHeights Harbour::seabed() const
{
    swell::SeabedHeights floor;
    floor.columns = floor.rows = kFloorSamples;
    floor.min_m = kAnchorage_m - kFloorHalfSide_m;
    floor.max_m = kAnchorage_m + kFloorHalfSide_m;
    floor.heights_m.resize(std::size_t(kFloorSamples) * std::size_t(kFloorSamples));
    const double step_m = 2.0 * kFloorHalfSide_m / (kFloorSamples - 1);
    for (int j = 0; j < kFloorSamples; ++j)
        for (int i = 0; i < kFloorSamples; ++i) {
            const glm::dvec2 p = floor.min_m + step_m * glm::dvec2(i, j);
            double height = -kBasinDepth_m;
            if (inside(p, kQuayMin_m, kQuayMax_m))
                height = kQuayHeight_m;
            if (inside(p, kMoleMin_m, kMoleMax_m))
                height = kMoleCrest_m;
            floor.heights_m[std::size_t(j) * std::size_t(kFloorSamples) + std::size_t(i)] = float(height);
        }
    return floor;
}

glm::dvec3 Harbour::viewpoint_m() const { return {kAnchorage_m.x, level_m_ + kBridgeWing_m.y, kAnchorage_m.y}; }

void Harbour::update(double time_s, const swell::DrawnSurface& water, std::vector<Box>& boxes)
{
    // The ship on the water under it: heave from the mean of four points
    // (bow, stern, both sides), pitch and roll from their differences, and
    // its own roll on top.
    const double halfLength_m = 12.0, halfBeam_m = 3.0;
    const auto y = [&](double x, double z) { return surfaceY(water, kAnchorage_m + glm::dvec2(x, z), level_m_); };
    const double bow = y(0.0, -halfLength_m), stern = y(0.0, halfLength_m);
    const double port = y(-halfBeam_m, 0.0), starboard = y(halfBeam_m, 0.0);
    const double heave_m = 0.25 * (bow + stern + port + starboard);
    const double pitch_rad = std::atan2(bow - stern, 2.0 * halfLength_m);
    roll_deg_ = glm::degrees(std::atan2(port - starboard, 2.0 * halfBeam_m)) +
                kRollAmplitude_deg * std::sin(2.0 * std::numbers::pi * time_s / kRollPeriod_s);
    ship_ = glm::translate(glm::dmat4(1.0), glm::dvec3(kAnchorage_m.x, heave_m, kAnchorage_m.y)) *
            glm::rotate(glm::dmat4(1.0), pitch_rad, glm::dvec3(1.0, 0.0, 0.0)) *
            glm::rotate(glm::dmat4(1.0), glm::radians(-roll_deg_), glm::dvec3(0.0, 0.0, 1.0));

    boxes.clear();
    addShip(ship_, boxes);
    addPier(level_m_, boxes);

    // The loose crate, a third under water, tilted with the facet it sits on.
    if (const auto p = water.at(kLooseCrate_m)) {
        const glm::dvec3 up = p->normal;
        const glm::dvec3 side = glm::normalize(glm::cross(up, glm::dvec3(0.0, 0.0, 1.0)));
        const glm::dmat4 frame(glm::dvec4(side, 0.0), glm::dvec4(up, 0.0), glm::dvec4(glm::cross(side, up), 0.0),
                               glm::dvec4(p->position_m, 1.0));
        const double h = kCrateSide_m * 0.5;
        boxes.push_back(boxBetween({-h, -0.35 * kCrateSide_m, -h}, {h, 0.65 * kCrateSide_m, h}, kCrate,
                                   frame * glm::rotate(glm::dmat4(1.0), 0.6, glm::dvec3(0.0, 1.0, 0.0))));
    }
}

glm::dmat4 Harbour::eyeView() const
{
    const glm::dmat4 eyeOnShip = glm::translate(glm::dmat4(1.0), kBridgeWing_m) *
                                 glm::rotate(glm::dmat4(1.0), glm::radians(kLookToPort_deg), glm::dvec3(0.0, 1.0, 0.0)) *
                                 glm::rotate(glm::dmat4(1.0), glm::radians(-kLookDown_deg), glm::dvec3(1.0, 0.0, 0.0));
    return glm::inverse(ship_ * eyeOnShip);
}

} // namespace host
