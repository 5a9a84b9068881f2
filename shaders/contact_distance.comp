// The contact map's distance (src/render/contact_map.h): from every texel
// to the nearest texel the contact pass covered (solid geometry at or above
// the sea level within the waves' reach), Euclidean, in texels, searched
// within SWELL_CONTACT_REACH_TEXELS (farther: that reach plus one). Two
// passes of the separable scheme of Meijster, Roerdink & Hesselink (2000):
// the rows' pass finds each texel's distance to the nearest covered texel
// in its row; the columns' pass takes, over the texels of its column within
// the reach, the least of dy^2 + (that texel's row distance)^2, which is
// the exact Euclidean distance wherever it is within the reach (their
// lower envelope replaced by the bounded search: 17 reads a texel a pass).
#include "swell/gpu/bindings.h"
#include "swell/gpu/contact.h"

layout(local_size_x = SWELL_CONTACT_GROUP, local_size_y = SWELL_CONTACT_GROUP) in;

#ifndef SWELL_CONTACT_ROWS
#error "SWELL_CONTACT_ROWS is given by the pass (src/render/contact_map.cpp)"
#endif

// The rows' pass: the contact pass's depth (1: nothing drawn). The
// columns' pass: the rows' distances.
layout(binding = SWELL_UNIT_CONTACT_SOURCE) uniform sampler2D source;
layout(binding = SWELL_IMAGE_CONTACT_OUT, r32f) writeonly uniform image2D result;

const int kReach = SWELL_CONTACT_REACH_TEXELS;
const float kNone = float(kReach + 1);

void main()
{
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(SWELL_CONTACT_SIZE))))
        return;
    float best = kNone;
#if SWELL_CONTACT_ROWS
    for (int dx = -kReach; dx <= kReach; ++dx) {
        int x = texel.x + dx;
        if (x < 0 || x >= SWELL_CONTACT_SIZE)
            continue;
        if (texelFetch(source, ivec2(x, texel.y), 0).r < 1.0)
            best = min(best, float(abs(dx)));
    }
#else
    float bestSquared = kNone * kNone;
    for (int dy = -kReach; dy <= kReach; ++dy) {
        int y = texel.y + dy;
        if (y < 0 || y >= SWELL_CONTACT_SIZE)
            continue;
        float across = texelFetch(source, ivec2(texel.x, y), 0).r;
        if (across < kNone)
            bestSquared = min(bestSquared, across * across + float(dy * dy));
    }
    best = min(sqrt(bestSquared), kNone);
#endif
    imageStore(result, texel, vec4(best, 0.0, 0.0, 0.0));
}
