// The tunables of the light under and through the water that C++ and GLSL
// share: the waterline mask's values, the caustics map and the shafts of
// light (the water's optical constants are swell/constants.h's). Included
// by C++ and GLSL alike, so it holds only preprocessor lines and comments;
// every value has its reason above it.
#ifndef SWELL_GPU_UNDERWATER_H
#define SWELL_GPU_UNDERWATER_H

// Values of the waterline mask (an R8 texture): the pixel's ray meets no
// water, meets it first from above, or first from below.
#define SWELL_WATERLINE_NO_HIT 0.0
#define SWELL_WATERLINE_ABOVE 0.5
#define SWELL_WATERLINE_BELOW 1.0

// Caustics (shaders/caustics.glsl, src/render/caustics_map.h): the sun's
// light refracted by the drawn surface onto horizontal slices under it,
// splatted with additive blending into a camera-following map.
// The map's side, m, and its texels per side: 48 m around the camera holds
// what a view under or near the water shows in detail; 512 texels of 9.4 cm
// resolve the focusing of the waves the source grid holds.
#define SWELL_CAUSTICS_EXTENT_M 48.0
#define SWELL_CAUSTICS_SIZE 512
// Source grid cells per side (the surface refracted): about 0.24 m cells over
// the map and its margins, so waves down to 0.5 m (SWELL_MIN_CELLS_PER_WAVELENGTH
// cells) focus the light; each is refracted once for every slice. On
// llvmpipe (2 shared cores, swell bench --still of docs/images/caustics.toml
// at 960x540) the pass took a median 655 ms a frame with 384 cells (0.16 m)
// and 459 ms with 256, whose net on the floor still shows every strand.
#define SWELL_CAUSTICS_CELLS 256
// Depth slices of the map: the pattern changes with depth as the waves'
// focal lengths are passed (a refracting surface of radius R focuses at
// n R / (n - 1), about 4 R in water: Hecht, "Optics", eq. 5.8); 3 slices, their depths in
// render/caustics_map.h, and the depths between interpolated.
#define SWELL_CAUSTICS_SLICES 3
// The odd stride of the caustics triangles' draw order (slot = triangle *
// stride modulo the triangles, a permutation while their count,
// 2 * SWELL_CAUSTICS_CELLS^2, is a power of two: about 0.31 of it, so the
// triangles drawn in turn lie far apart in the grid).
#define SWELL_CAUSTICS_ORDER_STRIDE 40503

// Shafts of light (shaders/light_shafts.glsl, src/render/light_shafts.h):
// the sun's beam scattered once towards an eye under the water.
// Samples along each view ray through the caustics map, and how far they
// reach, m: half the map's side (past it the map holds the mean alone, so
// the shafts' pattern ends there; the mean itself is integrated in closed
// form over the whole path). The samples crowd towards the eye (their
// spacing grows linearly), where shafts are nearest and widest on screen.
#define SWELL_SHAFTS_STEPS 16
#define SWELL_SHAFTS_REACH_M 24.0

#endif
