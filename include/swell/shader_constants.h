// Being retired: the constants C++ and GLSL share now live in headers by
// purpose under swell/gpu/ (bindings.h, limits.h, variants.h,
// label_classes.h, ocean.h, sky.h, underwater.h, spray.h, temporal.h), and
// the physical ones in swell/constants.h. This header gathers the former
// for the C++ files not yet moved to the header they need; include that
// header instead. GLSL never includes it.
#ifndef SWELL_SHADER_CONSTANTS_H
#define SWELL_SHADER_CONSTANTS_H

#include "swell/gpu/bindings.h"
#include "swell/gpu/label_classes.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/ocean.h"
#include "swell/gpu/sky.h"
#include "swell/gpu/spray.h"
#include "swell/gpu/temporal.h"
#include "swell/gpu/underwater.h"
#include "swell/gpu/variants.h"

#endif
