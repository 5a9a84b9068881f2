// The foam look's share (foamShare() in shaders/whitecap_foam.glsl) against
// its C++ twin (swell::foam::foamShare, src/ocean/foam/foam_texture.h),
// which the whitecaps' calibration counts the cover with: a calibration
// that counted another share than the look draws would miss Monahan's
// cover by the difference.
#include "ocean/foam/foam_texture.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

class FoamShare : public swell::test::GlTest {};

const char* const kFoamShareProbe = R"(
#include "whitecap_foam.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Amounts { vec2 amounts[]; }; // amount, breakingFoamAmount
layout(std430, binding = 1) buffer Shares { float shares[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    shares[i] = foamShare(amounts[i].x, amounts[i].y);
}
)";

// Every amount from none to full in steps of 1/1000, at the breaking
// amounts of lifetimes from 1 s to 60 s; the share in float against the
// twin's in double (measured within a few float roundings).
TEST_F(FoamShare, TheLooksShareIsItsCppTwins)
{
    std::vector<float> pairs;
    for (const double lifetime_s : {1.0, 3.85, 10.0, 60.0})
        for (int a = 0; a < 1024; ++a) {
            pairs.push_back(std::min(float(a) / 1000.0f, 1.0f));
            pairs.push_back(float(std::exp(-swell::foam::kBreakingFoamAge_s / lifetime_s)));
        }
    const size_t n = pairs.size() / 2;
    const swell::gl::Program program = swell::test::buildShaderProbe(kFoamShareProbe);
    const std::vector<float> got = swell::test::runShaderProbe<float, float>(program, pairs, n, GLuint(n / 64));
    double worst = 0.0, total = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double expected = swell::foam::foamShare(pairs[2 * i], pairs[2 * i + 1]);
        worst = std::max(worst, std::abs(double(got[i]) - expected));
        total += expected;
    }
    std::printf("%zu amounts: worst difference %.2e\n", n, worst);
    ASSERT_GT(total, 0.0);
    EXPECT_LT(worst, 1e-5);
}

} // namespace
