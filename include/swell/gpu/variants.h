// The values the programs' variant #defines take (render/programs.h builds
// each program with the defines its own flags give). Included by C++ and
// GLSL alike, so it holds only preprocessor lines and comments.
#ifndef SWELL_GPU_VARIANTS_H
#define SWELL_GPU_VARIANTS_H

// Debug views, selected by the scene or viewer (prepended as SWELL_DEBUG_VIEW).
#define SWELL_VIEW_SHADED 0
#define SWELL_VIEW_NORMALS 1
#define SWELL_VIEW_REFLECTION 2
#define SWELL_VIEW_REFRACTION 3
#define SWELL_VIEW_LOD 4
#define SWELL_VIEW_WIREFRAME 5
#define SWELL_VIEW_FOAM 6

// Reflection lookups (prepended as SWELL_REFLECTION_MODE).
#define SWELL_REFLECTION_FIXED 0
#define SWELL_REFLECTION_RAYMARCH 1

// Terms of the water shading (bit flags). The benchmark leaves one out at a
// time to measure what each costs (prepended as SWELL_OMITTED_TERMS, 0 in
// every normal build). Left out, a term becomes its cheapest stand-in:
// wave normals -> the interpolated vertex normal (and no foam, which the same
// per-pixel evaluation returns); reflection -> the sky's horizon colour;
// refraction -> the deep water colour; lighting -> no sun diffuse or
// specular; foam -> none; fog -> none; subsurface (light through the
// crests) -> none; filtering (normals filtered by the pixel's footprint,
// the highlight spread by what they leave out) -> every wave in the normal,
// unspread, as shading without horizon filtering would do.
#define SWELL_TERM_WAVE_NORMALS 1
#define SWELL_TERM_REFLECTION 2
#define SWELL_TERM_REFRACTION 4
#define SWELL_TERM_LIGHTING 8
#define SWELL_TERM_FOAM 16
#define SWELL_TERM_FOG 32
#define SWELL_TERM_SUBSURFACE 64
#define SWELL_TERM_FILTERING 128
#define SWELL_TERM_ALL 255

// Grid layouts (prepended as SWELL_GRID_LAYOUT; see shaders/grid.glsl).
#define SWELL_GRID_GEOMETRIC 0
#define SWELL_GRID_PAPER 1

#endif
