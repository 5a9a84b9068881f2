// The most of each thing the GPU interfaces hold: the sizes of the uniform
// blocks' arrays, which C++ and GLSL must agree on. Included by C++ and
// GLSL alike, so it holds only preprocessor lines and comments; every value
// has its reason above it.
#ifndef SWELL_GPU_LIMITS_H
#define SWELL_GPU_LIMITS_H

// Most Gerstner waves summed per vertex. 64 keeps the wave UBO at 2 KiB
// (32 bytes per wave) and the vertex shader affordable on software GL.
#define SWELL_MAX_WAVES 64

// Snap levels of the LOD grid: level l snaps vertices to multiples of
// (finest step * 2^l). 24 levels span 0.1 m to over 800 km.
#define SWELL_GRID_LEVELS 24
// Boxes that bound the world's geometry for the reflection ray march; a
// scene with more objects marches every ray.
#define SWELL_MAX_WORLD_BOXES 16

// Surface sources drawn at once (swell/surface_source.h), the wake's
// included: four vec4 parameters a source in the SurfaceSources block.
#define SWELL_MAX_SURFACE_SOURCES 8

#endif
