// The sky's tunables that C++ and GLSL share: the physical sky's bake and
// tables, the cloud layer, and its shadows' map (the physical constants of
// the air and the clouds are swell/constants.h's). Included by C++ and
// GLSL alike, so it holds only preprocessor lines and comments; every value
// has its reason above it.
#ifndef SWELL_GPU_SKY_H
#define SWELL_GPU_SKY_H

// The physical sky (swell/scene/atmosphere.h, src/core/atmosphere.cpp and
// shaders/atmosphere.glsl share these; docs/RENDERING.md).
// The eye's altitude for the baked sky, m: a deck's height (the sky hardly
// changes over the first hundred metres).
#define SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M 10.0
// Steps of the sky's ray march, spaced quadratically (dense near the eye,
// where the air is densest along a low ray): 40 keep the horizon's radiance
// within 1% of a 4000-step march (tests/cpu/test_atmosphere.cpp).
#define SWELL_SKY_MARCH_STEPS 40
// The transmittance table: (view zenith, altitude) texels, in Bruneton
// 2017's parametrisation (dense towards the horizon).
#define SWELL_TRANSMITTANCE_MU_SIZE 256
#define SWELL_TRANSMITTANCE_R_SIZE 64
// Hillaire 2020's multiple-scattering table (sec. 5.5): (sun zenith
// cosine, altitude), 32 x 32 as in the paper, in layers: Psi_ms, then the
// three order-2 harmonics of the air's share (swell/scene/atmosphere.h).
#define SWELL_MULTISCATTER_SIZE 32
#define SWELL_MULTISCATTER_LAYERS 4

// The cloud layer (swell/scene/clouds.h, src/core/clouds.cpp and shaders/clouds.glsl
// share these; docs/RENDERING.md, "Clouds"). A thin layer at an altitude,
// baked into the physical sky's cubemap with it.
// Octaves of gradient noise in its fractal sum: the coarsest cell is the
// scene's clouds.scale_m, the finest 1/32 of it (about 90 m for 3 km: finer
// than a texel of the bake straight up at 1.5 km is wide, 9 m, is lost anyway
// at the usual views, which look at the layer kilometres away).
#define SWELL_CLOUD_OCTAVES 6
// Standard deviation of the unfiltered fractal sum (measured over 10^6
// points by tests/cpu/test_clouds.cpp): a threshold at its quantile makes
// the clouded share of the layer the scene's cover.
#define SWELL_CLOUD_FBM_SIGMA 0.2491
// Softness of a cloud's edge, in units of that standard deviation: wide
// enough that a bake texel never steps from clear to opaque, narrow enough
// that edges read as edges.
#define SWELL_CLOUD_EDGE_SIGMA 0.12
// How far the domain warp moves a point, in coarsest cells (Quilez's domain
// warping): bends the lattice's straight runs into the swirls of real decks.
#define SWELL_CLOUD_WARP_CELLS 0.7
// The layer's shapes are drawn out along x this much (rolls and bands of a
// wind-driven deck).
#define SWELL_CLOUD_STRETCH 1.6
// Angular width of the sky bake's texel, rad (90 degrees over 256): the
// footprint below which the layer's octaves are averaged away.
#define SWELL_CLOUD_TEXEL_RAD 0.00614
// The layer's shadows on the sea and the world (shaders/cloud_shadow.glsl,
// src/render/cloud_shadow_map.h): its transmittance along the sun's ray,
// baked per point of the sea's mean level into a camera-following map
// (R32F, mipmapped: the mip chain averages the transmittance itself, as a
// pixel's footprint does) when the sky or the sun changes or the camera
// has moved SWELL_CLOUD_SHADOW_REBAKE of the map's side from its centre.
// 16 km across: the sea to the haze from a boat, the horizon's first
// kilometres from a mast; 512 texels of 31 m, under the finest octave of
// a 3 km layer (94 m) and about the penumbra of a cloud 3 km up (the
// sun's 0.53 degrees: 28 m). Beyond it, the map's mean.
#define SWELL_CLOUD_SHADOW_EXTENT_M 16000.0
#define SWELL_CLOUD_SHADOW_SIZE 512
#define SWELL_CLOUD_SHADOW_REBAKE 0.125
// The lowest sun the shadows are cast for (sin of 2.9 degrees): a lower
// one's ray crosses the layer tens of kilometres away, and the air has
// dimmed its light to little anyway.
#define SWELL_CLOUD_SHADOW_MIN_SUN_Y 0.05

#endif
