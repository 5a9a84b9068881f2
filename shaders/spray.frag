// The spray's streaks (spray.vert): their colour, lit and fogged per
// vertex there, under a Gaussian profile across and a tail fading in along
// them; blended over the frame. Built with SWELL_BOW_SPRAY, the bow's
// pieces of sheet too: opaque where the sheet holds, torn into streamers
// along its flight as its holes open.
#ifdef SWELL_BOW_SPRAY
#include "spray.glsl"
#endif

in vec2 vRibbon;
in vec3 vColor;
in float vOpacity;
#ifdef SWELL_BOW_SPRAY
in flat vec2 vSheet; // x: the piece's own number (0..1), y: the share torn open; < 0: a drop's streak
#endif

layout(location = 0) out vec4 fravColor;

#ifdef SWELL_BOW_SPRAY
// Value noise over the lattice of whole numbers, 0..1 (spray.glsl's hash:
// exact, so a still reproduces to the bit).
float sheetNoise(vec2 p)
{
    vec2 i = floor(p), f = p - i;
    uvec2 c = uvec2(ivec2(i) + 4096);
    float a = sprayUnit(sprayHash(c.x ^ sprayHash(c.y)), 0u);
    float b = sprayUnit(sprayHash((c.x + 1u) ^ sprayHash(c.y)), 0u);
    float d = sprayUnit(sprayHash(c.x ^ sprayHash(c.y + 1u)), 0u);
    float e = sprayUnit(sprayHash((c.x + 1u) ^ sprayHash(c.y + 1u)), 0u);
    vec2 s = f * f * (3.0 - 2.0 * f);
    return mix(mix(a, b, s.x), mix(d, e, s.x), s.y);
}
#endif

void main()
{
#ifdef SWELL_BOW_SPRAY
    if (vSheet.y >= 0.0) {
        // The piece of sheet: streamers along its flight (the noise drawn
        // out along it, six across), its edges ragged; a hole where the
        // noise lies under the share torn, so as the holes open the sheet
        // falls apart into the streamers that last (chosen by eye).
        vec2 seed = vec2(vSheet.x * 977.0, vSheet.x * 613.0);
        float n = 0.65 * sheetNoise(vec2(vRibbon.y * 3.0, vRibbon.x * 0.8) + seed) +
                  0.35 * sheetNoise(vec2(vRibbon.y * 7.0, vRibbon.x * 2.0) + seed.yx);
        float edge = 1.0 - smoothstep(0.5, 1.0, abs(vRibbon.y) + 0.4 * (n - 0.5));
        float held = smoothstep(vSheet.y - 0.12, vSheet.y + 0.12, n);
        float along = smoothstep(0.0, 0.35, vRibbon.x) * (1.0 - 0.5 * smoothstep(0.85, 1.0, vRibbon.x));
        fravColor = vec4(vColor, vOpacity * edge * held * along);
        return;
    }
#endif
    // Across: a Gaussian profile, no edge. Along: the tail fades in (the
    // streak's oldest part has spread into the air), the head ends softly.
    float across = (exp(-3.0 * vRibbon.y * vRibbon.y) - exp(-3.0)) / (1.0 - exp(-3.0));
    float along = smoothstep(0.0, 0.7, vRibbon.x) * (1.0 - 0.6 * smoothstep(0.8, 1.0, vRibbon.x));
    fravColor = vec4(vColor, vOpacity * across * along);
}
