// Told when each pass of a frame begins and ends (for timing and counters).
#pragma once

#include "swell/export.h"

namespace swell {

// Passes: "ocean" (the wave model's simulation for the frame), "bodies" (the
// floating bodies and their wake stepped on the CPU to the frame's time),
// "wake" (the wake's frame blended and uploaded), "caustics" (the
// caustics map, when Swell's own world reaches under the water near the
// camera, or the eye is below the waves' crests with water.shafts on), "reflection",
// "refraction", "waterline" (the mask, when the near plane meets the
// waves), "main"; within "main", "underwater host" (draw(): the host's
// geometry seen from under the water) and "water" for the water draw,
// within which, when it is drawn in two passes (docs/RENDERING.md "The
// water in two passes"), "water visibility" and "water shading"; then
// "present" when the main pass's image is resolved, filtered or scaled. The
// first three come from advanceTo(), the others from each view drawn.
// Within "ocean", a wave model may name the stages of its GPU work
// (WaveModelGpu::beginStage); the spectral model's are "fft rows", "fft
// columns", "foam", and "mipmaps" (the slopes' and the foam's mip chains
// after the frame's last step; "slope mipmaps" or "foam mipmaps" when only
// one changed). A stage may run more than once in a frame (a replay of the
// foam's history steps the foam many times).
class SWELL_API PassObserver {
public:
    virtual ~PassObserver() = default;
    virtual void beginPass(const char* name) = 0;
    virtual void endPass(const char* name) = 0;
};

} // namespace swell
