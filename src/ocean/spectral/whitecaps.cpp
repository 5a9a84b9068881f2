#include "ocean/spectral/whitecaps.h"

#include <cmath>

namespace swell::spectral {

double monahanWhitecapCover(double windSpeed10_mps) { return 3.84e-6 * std::pow(windSpeed10_mps, 3.41); }

} // namespace swell::spectral
