// Where the spectral ocean's whitecaps break (src/ocean/spectral/breaking.h,
// shaders/ocean/spectral_foam.comp), shared by C++ and GLSL alike, so this
// file holds only preprocessor lines and comments.
//
// A whitecap breaks where the surface folds: where the fold Jacobian J of
// the breaking-scale cascades is low (Tessendorf 2001, sec. 4.4). Measured
// against the whole sea, J's lowest share follows the longest waves: a
// 300 m swell's compressed phase lowers J over a whole wave face, so the
// sea a camera 10 m up sees (half of it within 22 m) ran from none to half
// white as the big waves passed, at a constant share of the whole sea.
// Measured against its own neighbourhood, J's lowest share is the same
// everywhere: a texel's breaking score is (J - mean) / deviation over the
// box of texels SWELL_FOAM_BREAKING_RADIUS each way around it, and foam is
// made in full where the score is below a level found for each sea so that
// its foam covers Monahan & O'Muircheartaigh's (1980) share of it
// (swell::spectral::calibratedBreakingRamps), so every stretch of sea a few
// metres across has its share of breaking crests.
#ifndef SWELL_GPU_BREAKING_H
#define SWELL_GPU_BREAKING_H

// The box: 5 x 5 texels, 9 m at 20 m/s (1.9 m texels at level 0), 2 m at
// 8 m/s: tried on the CPU twin against the share of the sea a camera 10 m
// up sees breaking, each second of a minute at 20 m/s: radius 1 held
// 0.44 to 2.1 times the mean, 2 held 0.38 to 2.0, 3 held 0.35 to 2.0,
// against 0.03 to 10.5 for J against the whole sea; 2 gives the lowest
// texel of a box room to be a crest's line rather than a point.
#define SWELL_FOAM_BREAKING_RADIUS 2
// A breaking whitens the water around its folding line: the foam a level-0
// texel makes is the most any texel within this many texels each way makes
// (a 3 x 3 box: 5.6 m at 20 m/s, 2.2 m at 8 m/s). Without it a breaking is
// often a single texel, which the shading's B-spline reads as 0.44 of full
// foam at its centre, so breaking crests never showed their dense sheet
// (FoamTexture.ABreakingCrestsFoamIsDenseAndOlderFoamThins: no pixel 0.85
// covered). Level 1's texels are SWELL_FOAM_LEVEL_RATIO times wider, as
// wide as level 0's spread patch, so it spreads none.
#define SWELL_FOAM_BREAKING_SPREAD 1
#define SWELL_FOAM_BREAKING_SPREAD_AT(level) ((level) == 0 ? SWELL_FOAM_BREAKING_SPREAD : 0)
// The least deviation a box's J is divided by: a glassy box, where J hardly
// varies (below a hundredth), scores near 0 rather than amplifying the
// float noise of its J (about 1e-5) into breaking.
#define SWELL_FOAM_LEAST_DEVIATION 0.01

#endif
