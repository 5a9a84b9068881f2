// The label pass's classes (swell/dataset/labels.h, shaders/labels.glsl), shared
// by C++ and GLSL alike, so this file holds only preprocessor lines and
// comments.
#ifndef SWELL_GPU_LABEL_CLASSES_H
#define SWELL_GPU_LABEL_CLASSES_H

// The label pass (swell/dataset/labels.h, shaders/labels.glsl; prepended as
// SWELL_LABEL_PASS 1 in its programs): each pixel's semantic class. The
// classes of scene objects follow from SWELL_LABEL_FIRST_OBJECT_CLASS on,
// one per distinct class name in the scene (FrameLabels::classes).
#define SWELL_LABEL_NONE 0
#define SWELL_LABEL_SKY 1
#define SWELL_LABEL_WATER 2
#define SWELL_LABEL_WHITECAP_FOAM 3
#define SWELL_LABEL_WAKE_FOAM 4
#define SWELL_LABEL_TERRAIN 5
// The coast's breaking waves' whitewater (shaders/surf.glsl) and the waves'
// wash against what stands in them (shaders/contact.glsl): water whose
// point is under the surf's foam, where that is more than the whitecaps'.
#define SWELL_LABEL_SURF 6
// The beach the swash wets (shaders/swash.glsl): terrain the sea runs up,
// at least SWELL_LABEL_WET_SAND_WETNESS wet.
#define SWELL_LABEL_WET_SAND 7
#define SWELL_LABEL_WET_SAND_WETNESS 0.5
#define SWELL_LABEL_FIRST_OBJECT_CLASS 16
// A water pixel is labelled foam where foam covers the point its centre ray
// meets (the foam's texture at full detail there, 1 or 0): at least this.
#define SWELL_LABEL_FOAM_COVER 0.5

#endif
