// The built-in island's terrain (Scene::showTerrain): its size, peak and
// place, and the one height function that both its drawn mesh
// (makeIsland, assets/mesh_data.h) and the sea floor (swell/scene/seabed.h)
// take it from. Also the smooth value noise its relief, and the built-in
// rock's, are made of.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell::detail {

// The island: size, peak and where it stands (ahead-left of the default
// camera; in the sea frame, y = 0 at the sea's mean level, as the renderer
// places it).
inline constexpr double kIslandSize_m = 1400.0;
inline constexpr double kIslandPeak_m = 70.0;
inline constexpr glm::dvec3 kIslandPosition_m{-700.0, 0.0, -1700.0};

// The terrain's height at a point of a square island of side size_m
// centred on the origin (local [x, z], m), peak_m above y = 0 at most: a
// dome that dips below y = 0 at about 0.45 of its half-size, shallows to
// about 0.75, then deep (-45 m at most). Defined over the whole plane; the
// island is its square.
double islandHeight_m(glm::dvec2 local_xz_m, double size_m, double peak_m);

// Smooth value noise, deterministic, in -0.5..0.5 summed over `octaves`
// octaves of 2.03 times the frequency and half the amplitude each.
double fractalNoise(double x, double y, int octaves = 5);

} // namespace swell::detail
