#include "ocean/spectral/whitecaps.h"

#include <algorithm>
#include <cmath>

namespace swell::spectral {

double monahanWhitecapCover(double windSpeed10_mps) { return 3.84e-6 * std::pow(windSpeed10_mps, 3.41); }

double foamPersistence(double windSpeed10_mps)
{
    return 3.06 * std::pow(20.0 / windSpeed10_mps, 1.82);
}

double breakingFraction(double windSpeed10_mps)
{
    return monahanWhitecapCover(windSpeed10_mps) / foamPersistence(windSpeed10_mps);
}

std::vector<float> jacobians(const std::vector<float>& dxx, const std::vector<float>& dzz, const std::vector<float>& dxz)
{
    std::vector<float> j(dxx.size());
    for (size_t i = 0; i < j.size(); ++i)
        j[i] = (1.0f + dxx[i]) * (1.0f + dzz[i]) - dxz[i] * dxz[i];
    return j;
}

float quantile(std::vector<float> values, double fraction)
{
    if (values.empty())
        return 0.0f;
    const size_t i = std::min(values.size() - 1, size_t(std::clamp(fraction, 0.0, 1.0) * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(i), values.end());
    return values[i];
}

} // namespace swell::spectral
