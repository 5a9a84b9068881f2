// Contact foam: the whitewater where the waves wash against what stands in
// the water (rocks, breakwaters, piles, walls, hulls; Swell's and the
// host's), for every wave model. The contact pass (src/render/contact_map.h)
// draws that geometry from straight above in a window around the camera,
// where it stands at or above the sea level within the waves' reach, and
// its distance passes (contact_distance.comp) give every texel its distance
// to the nearest such texel. Here a water point takes foam in a band round
// the contact, e-folding over the significant wave's amplitude (the water
// churned at the face runs to and fro that far on its orbits: Frame's
// contactBand_m), denser and wider while a crest stands against it, thinning
// to lace in the troughs. The foam is the surf's (surf.glsl: its amount,
// look and bubbles), so it takes the whitecaps' lace and relief, anchored to
// the water's rest points so that it rides the waves' orbits.
// Called by water.frag's shading and its labels alike.
#ifndef SWELL_CONTACT_GLSL
#define SWELL_CONTACT_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/contact.h"

layout(binding = SWELL_UNIT_CONTACT) uniform sampler2D contactDistance;

// The share of the window's side over which the foam fades out at its
// edges, so that the window's edge draws no line in the sea.
const float kContactEdgeFade = 0.05;
// The foam's amount at the contact: with a crest against the face (the
// water at the significant wave's amplitude above the mean level or more),
// whole, a breaking's own (above the surf's kSurfFreshAmount, 0.61); in a
// trough (as far below) this share of it, lace. Chosen by eye: a trough's
// contact keeps a ring of older foam, as photographs of piles in a swell show.
const float kContactTroughShare = 0.45;
// The band widens by this share of itself while a crest stands at the point
// (and narrows by as much in a trough): the uprush spreads the fresh foam
// outwards, the backwash draws it in.
const float kContactCrestWidening = 0.35;
// Seas whose significant height (4 sigma, m) is below this wash less: the
// foam's amount grows from none in a glassy calm to whole at this height
// (chosen by eye: ripples of a few centimetres leave no ring on a hull).
const float kContactWholeHeight_m = 0.25;

// The contact foam's amount at the drawn point `position` (relative to the
// render origin) standing `elevation_m` above the mean level: 0 away from
// any contact and wherever the pass drew nothing this view (contactOn 0).
float contactAmount(vec3 position, float elevation_m)
{
    if (contactOn == 0)
        return 0.0;
    vec2 uv = (position.xz - contactCorner_m) / contactSize_m;
    vec2 edge = min(uv, vec2(1.0) - uv);
    float inside = smoothstep(0.0, kContactEdgeFade, min(edge.x, edge.y));
    float distance_m = textureLod(contactDistance, uv, 0.0).r * (contactSize_m / float(SWELL_CONTACT_SIZE));
    if (inside <= 0.0 || distance_m >= contactReach_m)
        return 0.0;
    float height_m = 4.0 * waveHeightDeviation_m;
    float crest = clamp(elevation_m / max(0.5 * height_m, 0.01), -1.0, 1.0);
    float band_m = contactBand_m * (1.0 + kContactCrestWidening * crest);
    float atFace = mix(kContactTroughShare, 1.0, smoothstep(-1.0, 1.0, crest));
    float strength = smoothstep(0.0, kContactWholeHeight_m, height_m);
    // Faded out before the searched reach, so the reach draws no edge.
    float fade = 1.0 - smoothstep(0.6 * contactReach_m, contactReach_m, distance_m);
    return strength * inside * fade * atFace * exp(-distance_m / band_m);
}
#endif
