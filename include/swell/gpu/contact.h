// The contact foam's map (src/render/contact_map.h, shaders/contact.glsl,
// shaders/contact_distance.comp): where solid geometry stands at or above
// the sea level within the band the waves reach, seen from straight above in
// a window around the camera, and the distance from each texel to the
// nearest such texel. Included by C++ and GLSL alike, so it holds only
// preprocessor lines and comments; every value has its reason above it.
#ifndef SWELL_GPU_CONTACT_H
#define SWELL_GPU_CONTACT_H

// Texels per side of the map. 256 texels over the smallest window (128 m)
// are 50 cm: the distance is read bilinearly, so a band half a metre wide
// (a hull at rest in a light sea) has a smooth edge, its place within a
// quarter of a metre. 512 texels cost the distance passes 80 ms a view on
// llvmpipe (2 shared cores, the harbour preset at 320x180, reach 16), 256
// texels with a reach of 8 an eighth of the reads.
#define SWELL_CONTACT_SIZE 256
// The window's side, m: the smallest, around an eye near the water, and the
// largest, from high up (it grows with the eye's height above the sea,
// SWELL_CONTACT_EXTENT_PER_HEIGHT times it, so a view from 300 m up sees the
// foam round the structures below it, at 2 m texels then, where a pixel of
// a 640 x 360 frame spans about 0.8 m).
#define SWELL_CONTACT_MIN_EXTENT_M 128.0
#define SWELL_CONTACT_MAX_EXTENT_M 512.0
#define SWELL_CONTACT_EXTENT_PER_HEIGHT 1.5
// How far from the contact the distance is searched, texels: the foam's
// band fades out by this distance (4 m over the smallest window, three
// e-foldings of a 1.3 m band). The search costs two passes of 2 x 8 + 1
// reads a texel (an exact Euclidean distance bounded by it: a row pass,
// then a column pass over the rows' answers; Meijster et al. 2000's
// separable scheme, its lower envelope replaced by the bounded search).
#define SWELL_CONTACT_REACH_TEXELS 8
// The distance passes' workgroup side (8 x 8 invocations, a texel each).
#define SWELL_CONTACT_GROUP 8

#endif
