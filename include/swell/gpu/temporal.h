// The temporal resolve's tunables that C++ and GLSL share
// (shaders/temporal_resolve.frag, render/temporal_resolve.h,
// docs/RENDERING.md "Temporal resolve"). Included by C++ and GLSL alike, so
// it holds only preprocessor lines and comments; every value has its
// reason above it.
#ifndef SWELL_GPU_TEMPORAL_H
#define SWELL_GPU_TEMPORAL_H

// The most weight the history holds, in frames of a sample at the pixel's
// centre: a still view ends up averaging about the last this many frames
// (each new one weighs 1/this), which is what hides the jitter's steps and
// the low resolution's, while a change takes about this many frames to
// settle where the neighbourhood clip below does not catch it.
#define SWELL_TEMPORAL_MAX_WEIGHT 10.0
// ...and on the water while the waves move (the simulated time changed since
// the last frame): its pattern travels with the waves' phase, each
// wavelength at its own speed, which no one motion per pixel follows, so
// the water keeps a short history: each new frame weighs at least two
// thirds, which keeps some of the jitter's smoothing without dragging the
// crests (measured in tests/gl/test_temporal_resolve.cpp: at 3 frames the
// moving water strayed further from a full-quality frame than frames with
// no history did). It converges fully while the time stands.
#define SWELL_TEMPORAL_WATER_MAX_WEIGHT 1.5
// The box the reprojected history is clipped to: the mean of the frame's
// 3x3 neighbourhood (YCoCg) plus or minus this many standard deviations
// (Salvi 2016, "An excursion in temporal supersampling", GDC: variance
// clipping). Smaller rejects more (less ghosting, more flicker).
#define SWELL_TEMPORAL_CLIP_SIGMAS 1.25
// The number of frames in the jitter's cycle (Halton 2, 3: points 1..this).
#define SWELL_TEMPORAL_JITTER_PHASES 16

#endif
