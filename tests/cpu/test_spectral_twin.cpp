// The CPU twin transforms the derivative fields only when a query needs
// them: the displacement it gives without them, and the fields it ends up
// with, are exactly those of a twin that transforms everything at once.
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/spectrum.h"

#include <gtest/gtest.h>

#include <memory>

namespace {

using namespace swell::spectral;

std::shared_ptr<const SpectralField> testField()
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 11.0;
    return std::make_shared<const SpectralField>(makeSpectralField(swell::SeaSpectrum(wind), 0.8, 3));
}

TEST(SpectralTwin, DisplacementWithoutDerivativesEqualsTheFullQuery)
{
    const auto field = testField();
    CpuSurface lazy(field), eager(field);
    const swell::SurfaceFilter exact{}, filtered{0.5, 0.9};
    for (double time_s : {0.0, 12.5, 1.0e6}) {
        eager.fieldsAt(time_s);
        for (glm::dvec2 p : {glm::dvec2(0.0, 0.0), glm::dvec2(13.7, -250.2), glm::dvec2(1.0e4, 3.3e3)}) {
            // lazy has only the displacement fields here (its first query at this time).
            const glm::dvec3 d = lazy.displacementAt(p, time_s, exact);
            EXPECT_FALSE(lazy.displacementFieldsAt(time_s).hasDerivatives);
            EXPECT_EQ(d, eager.surfaceAt(p, time_s, exact).displacement_m);
            EXPECT_EQ(lazy.displacementAt(p, time_s, filtered), eager.surfaceAt(p, time_s, filtered).displacement_m);
        }
        // A normal asked for later in the frame transforms the rest.
        const glm::dvec2 p(-40.0, 77.0);
        const swell::SurfacePoint a = lazy.surfaceAt(p, time_s, exact), b = eager.surfaceAt(p, time_s, exact);
        EXPECT_EQ(a.displacement_m, b.displacement_m);
        EXPECT_EQ(a.normal, b.normal);
        for (int c = 0; c < kCascades; ++c)
            for (int v = 0; v < 8; ++v)
                EXPECT_EQ(lazy.fieldsAt(time_s).values[size_t(c)][size_t(v)], eager.fieldsAt(time_s).values[size_t(c)][size_t(v)]);
    }
}

} // namespace
