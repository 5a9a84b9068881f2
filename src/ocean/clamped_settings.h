// The wind and swell settings with every field inside its documented range,
// shared by the spectrum, the sea spectrum and the wave generator so that all
// three see the same sea. Non-finite input throws std::invalid_argument
// naming `function` ("swell::generateWaves()") and the field.
#pragma once

#include "swell/scene/spectrum.h"

namespace swell::detail {

WindSettings clampedWind(const WindSettings& wind, const char* function);
SwellSettings clampedSwell(const SwellSettings& swell, const char* function);

} // namespace swell::detail
