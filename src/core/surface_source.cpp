#include "swell/surface_source.h"

namespace swell {

SurfaceSource::~SurfaceSource() = default;

} // namespace swell
