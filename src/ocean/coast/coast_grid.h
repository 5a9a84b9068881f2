// The depth grid a scene's sea floor gives the coast field
// (swell/coast_field.h): the floor's extent with a margin of open sea
// around it, sampled at the floor's own heights.
#pragma once

#include "swell/coast_field.h"

#include <optional>

namespace swell {
class Seabed;
struct WaveSet;
}

namespace swell::coast {

// The most samples along a side the scene's field takes: 320 x 320 samples
// by 16 waves is 26 MB of texels on the GPU and as much on the CPU.
inline constexpr int kSceneGridSide = 320;
// The finest spacing it takes, m: finer resolves no more of a smooth floor.
inline constexpr double kFinestCell_m = 2.0;

// None when the floor is flat everywhere (no extent) or the set has no
// wave. The margin is the longest wave's open-sea length, at least 150 m
// and at most 600 m, so that the grid's edges lie off the floor's shapes
// where the blend into the open sea happens.
std::optional<DepthGrid> depthGridOf(const Seabed& seabed, const WaveSet& waves);

// The field of `waves` over the scene's floor (depthGridOf), none where the
// floor is flat. The field the same waves over the same grid gave last is
// kept and handed out again: a scene's parameters mostly change neither
// (the sun, the camera, the grid), and a field over the built-in island
// takes about half a second to solve. The last few are kept, process-wide.
std::shared_ptr<const CoastField> coastFieldOf(const Seabed& seabed, const WaveSet& waves);

} // namespace swell::coast
