// The spray's clumps (spray.vert) as SWELL_SPRAY_DROPS drops (the bow's:
// SWELL_BOW_SPRAY_DROPS and a piece of its sheet, sheetPiece), each drawn as
// a streak of its own path (spray.glsl's closed form) over the last
// fraction of a second: a ribbon facing the eye through four points of
// that path, so the fine mist the wind takes up at once shows as thin
// sheets drawn out downwind, densest where the clump left the crest and
// thinning as they spread, and the larger drops as short streaks along
// their arcs. A streak narrower or shorter than a pixel is drawn out to
// one, made fainter by as much (its coverage kept), so distant spray thins
// into a haze instead of sparkling.
#include "frame.glsl"
#include "fog.glsl"
#include "lighting.glsl"
#include "spray.glsl"
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif

layout(points) in;
#ifdef SWELL_BOW_SPRAY
// SWELL_BOW_SPRAY_DROPS ribbons of 4 point pairs, and the piece of sheet's.
layout(triangle_strip, max_vertices = 72) out;
#define SPRAY_DROPS SWELL_BOW_SPRAY_DROPS
#else
layout(triangle_strip, max_vertices = 40) out; // SWELL_SPRAY_DROPS ribbons of 4 point pairs
#define SPRAY_DROPS SWELL_SPRAY_DROPS
#endif

in vec3 vBirth[];
in vec3 vWind[];
in float vAge_s[];
in flat uint vKey[];
in float vOpacity[];
#ifdef SWELL_BOW_SPRAY
// The bow's sheets (spray.vert built with SWELL_BOW_SPRAY): their launch
// and drops are the bow's, their flight the same closed form.
in vec4 vBow[];
in vec3 vForward[];
#endif

out vec2 gRibbon;     // x: 0 at the streak's tail to 1 at its head; y: -1..1 across
out vec3 gColor;      // lit and fogged, in the pass's output encoding
out float gOpacity;
#ifdef SWELL_BOW_SPRAY
// x: the piece of sheet's own number (0..1), y: the share of it torn open
// (bowSheetTorn); y < 0: a drop's streak.
out flat vec2 gSheet;
#endif

// A streak's colour at p: fine water drops, lit by the sky and the sun
// (drops scatter nearly all the light they meet, most of it forward),
// fogged with the distance as the world is. Lit as the whitecaps are
// (water.frag), the sun's share brighter looking towards it, with an albedo
// of 1 (drops absorb next to nothing; the foam's 0.55 to 0.65 is a layer
// the water shows through): chosen by eye. The sky lights a drop from
// every side: the mean of its irradiance from above and from below
// (skyAmbient, the sky's and the ground's light), so under an overcast
// deck, the sun hidden, the spray is still whiter than the sea. Per vertex,
// not per fragment: it hardly changes along a streak, and the fragments
// are many.
vec3 sprayColor(vec3 p)
{
    vec3 toEye = normalize(eyePosition - p);
    float forward = max(dot(-toEye, sunDirection), 0.0);
#if SWELL_CLOUD_SHADOWS
    // In the cloud layer's shadow or not (cloud_shadow.glsl): a pixel's
    // footprint at its distance.
    float cloudSun = cloudShadowAt(p, 2.0 * distance(p, eyePosition) / (viewportSize.y * projectionFocalY));
    vec3 sunLight = sunColor * (sunIntensity * cloudSun) * max(sunDirection.y, 0.0);
#else
    vec3 sunLight = sunColor * sunIntensity * max(sunDirection.y, 0.0);
#endif
    vec3 skyLight = 0.5 * (skyAmbient(vec3(0.0, 1.0, 0.0)) + skyAmbient(vec3(0.0, -1.0, 0.0)));
    vec3 light = sunLight * (0.6 + 0.4 * forward * forward) + max(skyLight, vec3(0.0));
    return passOutput(applyFog(light, distance(p, eyePosition), p - eyePosition)).rgb;
}

#ifdef SWELL_BOW_SPRAY
// The clump's piece of the water sheet (spray.glsl: bowSheetLaunch, its
// flight as its largest drops', bowSheetTorn): a wide streak of its path
// over the last SWELL_BOW_SPRAY_PIECE_TRAIL_S, facing the eye, opaque where
// the sheet holds and torn into streamers along its flight (spray.frag) as
// its holes open, gone when they have met. It widens as it flies (the fan
// spreads and thins; 0.1 m + 0.3 m/s half width, chosen by eye).
void sheetPiece(float flareCot, float pixelSpread)
{
    float age_s = vAge_s[0];
    float torn = bowSheetTorn(vKey[0], age_s);
    if (torn >= 1.0)
        return;
    vec3 launch_mps = bowSheetLaunch(vKey[0], vForward[0].xy, vBow[0].xy, vBow[0].z, vBow[0].w, flareCot);
    // The piece is water, not mist: the air it meets is the crest
    // spray's, a drop's own eddy (its first sheet drop's).
    vec3 air_mps = sprayAir(vKey[0], uint(SWELL_SPRAY_MIST_DROPS), vWind[0].xy, vWind[0].z);
    float tau_s = bowSheetTau_s();
    float tail_s = max(age_s - float(SWELL_BOW_SPRAY_PIECE_TRAIL_S), 0.0);
    vec3 points[4];
    for (int k = 0; k < 4; ++k)
        points[k] = vBirth[0] + sprayDropOffset(launch_mps, air_mps, tau_s, mix(tail_s, age_s, float(k) / 3.0));
    vec3 path = points[3] - points[0];
    float length_m = length(path);
    if (length_m < 1e-4)
        return;
    // Nearly opaque while whole (an aerated sheet scatters most of the
    // light it meets; chosen by eye), fading as it falls back to the
    // height it left at, where the foam takes it.
    float opacity = 0.85 * vOpacity[0] * smoothstep(-0.3, 0.3, points[3].y - vBirth[0].y);
    float halfWidth_m = 0.1 + 0.3 * age_s;
    float pixel_m = distance(eyePosition, points[3]) * pixelSpread;
    float drawn_m = max(halfWidth_m, 0.6 * pixel_m);
    opacity *= halfWidth_m / drawn_m;
    if (opacity <= 0.002)
        return;
    float piece = sprayUnit(vKey[0], 111u);
    for (int k = 0; k < 4; ++k) {
        vec3 color = sprayColor(points[k]);
        vec3 toEye = normalize(eyePosition - points[k]);
        vec3 side = cross(toEye, path);
        side = dot(side, side) > 1e-12 ? normalize(side) : normalize(cross(toEye, vec3(1.0, 0.0, 0.0)));
        for (int s = -1; s <= 1; s += 2) {
            gRibbon = vec2(float(k) / 3.0, float(s));
            gColor = color;
            gOpacity = opacity;
            gSheet = vec2(piece, torn);
            gl_Position = passViewProj * vec4(points[k] + float(s) * drawn_m * side, 1.0);
            EmitVertex();
        }
    }
    EndPrimitive();
}
#endif

void main()
{
    if (vOpacity[0] <= 0.0)
        return;
    float age_s = vAge_s[0];
    // A pixel's width per metre of distance.
    float pixelSpread = 2.0 / (projectionFocalY * viewportSize.y);
#ifdef SWELL_BOW_SPRAY
    float flareCot = vForward[0].z;
    sheetPiece(flareCot, pixelSpread);
#endif
    for (uint drop = 0u; drop < uint(SPRAY_DROPS); ++drop) {
        bool mist = drop < uint(SWELL_SPRAY_MIST_DROPS);
#ifdef SWELL_BOW_SPRAY
        float tau_s = bowSprayTau_s(vKey[0], drop);
        vec3 launch_mps = bowSprayLaunch(vKey[0], drop, vForward[0].xy, vBow[0].xy, vBow[0].z, vBow[0].w, flareCot);
        float trail_s = mist ? float(SWELL_SPRAY_MIST_TRAIL_S) : float(SWELL_BOW_SPRAY_SHEET_TRAIL_S);
#else
        float tau_s = sprayTau_s(vKey[0], drop);
        vec3 launch_mps = sprayLaunch(vKey[0], drop, vWind[0].xy, vWind[0].z);
        float trail_s = mist ? float(SWELL_SPRAY_MIST_TRAIL_S) : float(SWELL_SPRAY_DROP_TRAIL_S);
#endif
        vec3 air_mps = sprayAir(vKey[0], drop, vWind[0].xy, vWind[0].z);
        float tail_s = max(age_s - trail_s, 0.0);
        vec3 points[4];
        for (int k = 0; k < 4; ++k)
            points[k] = vBirth[0] + sprayDropOffset(launch_mps, air_mps, tau_s, mix(tail_s, age_s, float(k) / 3.0));
        // It fades as it falls back to the crest's height, where the foam takes it.
        float opacity = vOpacity[0] * smoothstep(-0.3, 0.3, points[3].y - vBirth[0].y);
        // Mist spreads as it flies (turbulent diffusion, chosen by eye),
        // fainter as it spreads; a drop stays a drop.
#ifdef SWELL_BOW_SPRAY
        // A sheet's drop stands for a ligament of the torn sheet, wider
        // than the crest's drops (6 cm: chosen by eye; at 16 cm their
        // streaks, a few metres long in a head wind, veiled the hull).
        float halfWidth_m = mist ? 0.03 + 0.08 * age_s : 0.03;
#else
        float halfWidth_m = mist ? 0.03 + 0.08 * age_s : 0.012;
#endif
#ifdef SWELL_BOW_SPRAY
        // The bow's mist is the torn sheet's fine spindrift, fainter than
        // a crest's spume beside its pieces and drops (chosen by eye: at
        // the crest's opacity it veils the hull aft of the bow).
        opacity *= mist ? 0.25 * sqrt(0.03 / halfWidth_m) : 0.9;
#else
        opacity *= mist ? 0.6 * sqrt(0.03 / halfWidth_m) : 0.9;
#endif
        float pixel_m = distance(eyePosition, points[3]) * pixelSpread;
        float drawn_m = max(halfWidth_m, 0.6 * pixel_m);
        opacity *= halfWidth_m / drawn_m;
        // A streak shorter than a pixel is drawn out to one, fainter by as
        // much, about its middle.
        vec3 path = points[3] - points[0];
        float length_m = length(path), drawnLength_m = max(length_m, pixel_m);
        opacity *= length_m / max(drawnLength_m, 1e-6);
        if (length_m < 1e-4)
            continue; // at birth: nothing has left the crest yet
        vec3 middle = 0.5 * (points[0] + points[3]);
        for (int k = 0; k < 4; ++k)
            points[k] = middle + (points[k] - middle) * (drawnLength_m / length_m);
        if (opacity <= 0.002)
            continue;
        for (int k = 0; k < 4; ++k) {
            vec3 color = sprayColor(points[k]);
            vec3 toEye = normalize(eyePosition - points[k]);
            vec3 side = cross(toEye, path);
            side = dot(side, side) > 1e-12 ? normalize(side) : normalize(cross(toEye, vec3(1.0, 0.0, 0.0)));
            for (int s = -1; s <= 1; s += 2) {
                gRibbon = vec2(float(k) / 3.0, float(s));
                gColor = color;
                gOpacity = opacity;
#ifdef SWELL_BOW_SPRAY
                gSheet = vec2(0.0, -1.0);
#endif
                gl_Position = passViewProj * vec4(points[k] + float(s) * drawn_m * side, 1.0);
                EmitVertex();
            }
        }
        EndPrimitive();
    }
}
