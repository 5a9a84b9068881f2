// The ocean's tunables that C++ and GLSL share: how a wave is faded by the
// grid's sampling, the spectral model's cascades and warp, and the
// whitecaps' foam and its texture. Included by C++ and GLSL alike, so it
// holds only preprocessor lines and comments; every value has its reason
// above it.
#ifndef SWELL_GPU_OCEAN_H
#define SWELL_GPU_OCEAN_H

// A wave is faded out where the grid samples it with fewer than this many
// cells per wavelength (Nyquist is 2; a little more keeps shading stable).
#define SWELL_MIN_CELLS_PER_WAVELENGTH 2.0
// ...and is at full strength from this many cells per wavelength on.
#define SWELL_FULL_CELLS_PER_WAVELENGTH 4.0

// The spectral model (src/ocean/spectral/): cascades of SWELL_FFT_SIZE^2
// samples, each a periodic patch of its own size. 256 resolves a patch's
// waves down to 4 texels per wavelength with one 64-thread workgroup per
// line of the FFT (spectral_fft.comp takes its stages two at a time, so the
// size is a power of 4); 4 cascades span 1 km down to about 5 cm.
#define SWELL_FFT_SIZE 256
#define SWELL_FFT_LOG2_SIZE 8
#define SWELL_FFT_CASCADES 4
// The cascades whose displacement far vertices read filtered (a mip chain)
// where their exact field fades: the first, which holds the swell
// (src/ocean/spectral/spectral_cpu.h, filteredCascadeWeight). Only their
// layers of the displacement's chain are built.
#define SWELL_FFT_FILTERED_CASCADES 1
// Sinusoids in each cascade's anti-tiling warp (src/ocean/spectral/
// spectral_warp.h): enough directions that every wave direction and every
// shift is decorrelated, few enough to cost little per vertex and pixel.
#define SWELL_FFT_WARP_WAVES 6
// The water's pixels take each cascade's warp (its lookup point and
// Jacobian) interpolated from the grid's vertices where a grid cell is at
// most 1/SWELL_FFT_WARP_CELLS_PER_WAVELENGTH of the warp's shortest
// sinusoid, and evaluate it themselves elsewhere: a sinusoid sampled 20
// times a wavelength is off its linear interpolation by at most
// (pi/20)^2/2 = 1.2% of its amplitude, a fraction of a texel of the
// lookup (docs/RENDERING.md, "The spectral ocean").
#define SWELL_FFT_WARP_CELLS_PER_WAVELENGTH 20
// The spectral model's whitecap foam lives in the world, not in the periodic
// cascades (whose foam would repeat with their patches): SWELL_FOAM_LEVELS
// camera-following windows of SWELL_FOAM_SIZE^2 texels, each level's texels
// SWELL_FOAM_LEVEL_RATIO times the last's (src/ocean/spectral/world_foam.h).
#define SWELL_FOAM_SIZE 256
#define SWELL_FOAM_LOG2_SIZE 8
#define SWELL_FOAM_LEVELS 2
#define SWELL_FOAM_LEVEL_RATIO 4.0
// The whitecaps' texture (src/ocean/spectral/foam_texture.h): octaves of
// gradient noise on lattices turned from each other, plus one that warps
// them; each lattice repeats after SWELL_FOAM_NOISE_PERIOD cells (14 km for
// the coarsest octave, 140 m for the finest: more than a picture holds
// where the octave is not faded into its mean; a float still holds a cell
// index that large to a two-thousandth of a cell).
#define SWELL_FOAM_OCTAVES 6
#define SWELL_FOAM_NOISE_MAPS 7
#define SWELL_FOAM_NOISE_PERIOD 4096
// The share of the water foam covers (foamLook() in shaders/whitecap_foam.glsl,
// swell::foam::foamShare in C++, which calibrates the whitecaps' breaking
// against Monahan's cover with it): a breaking's own foam (younger than a
// second) SWELL_FOAM_BREAKING_SHARE, older foam SWELL_FOAM_LACE_SHARE of
// its amount, and none below SWELL_FOAM_LEAST_AMOUNT.
#define SWELL_FOAM_BREAKING_SHARE 0.9
#define SWELL_FOAM_LACE_SHARE 0.75
#define SWELL_FOAM_LEAST_AMOUNT 0.0005
// The surface sources' foam (the bodies' wake's) fades as exp(-age / this),
// s: the spectral whitecaps' default lifetime (salt water, Monahan &
// O'Muircheartaigh 1980). The shading draws source foam above
// exp(-1 s / this) as a breaking's own (the whitecaps' dense layer).
#define SWELL_SOURCE_FOAM_LIFETIME_S 3.85

#endif
