// A coast field solved once per build and kept on disk (core/derived_cache.h):
// the same waves over the same depth grid read back the texels the solve
// found, bit for bit, in every later process.
#pragma once

#include "swell/coast_field.h"

#include <memory>

namespace swell {
struct WaveSet;
}

namespace swell::coast {

// The field of `waves` over `grid` at the breaker index kBreakerIndex: from
// the cache when it holds this build's, else solved (and kept there when
// the cache is on).
std::shared_ptr<const CoastField> solvedOrCachedField(const WaveSet& waves, DepthGrid grid);

} // namespace swell::coast
