// The view from under the water: which pixels look out from below the
// surface, and the water's absorption and in-scattering along a path through
// it. Used by mesh.frag, sky.frag and water.frag (through underwater_surface.glsl).
//
// Above or below, per pixel: the renderer draws the water surface alone into
// the waterline mask before the main pass (waterline.cpp), each pixel keeping
// the side from which its nearest water fragment beyond the near plane is
// seen. Seen from below means the near plane there is under the water. A
// camera in the waves at the waterline so gets a split that follows the
// surface exactly, pixel by pixel, instead of one switch that flips for the
// whole frame. Far from the surface the mask is cleared to the eye's side.
#ifndef SWELL_UNDERWATER_GLSL
#define SWELL_UNDERWATER_GLSL
#include "swell/gpu/bindings.h"
#include "frame.glsl"
#include "light_shafts.glsl"
#ifndef SWELL_CLOUD_SHADOWS
#error "SWELL_CLOUD_SHADOWS is given by the program's flags (src/render/programs.h)"
#endif
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif

// 0 in the programs built for passes in which no pixel looks out from below
// the water (render/programs.h): pixelUnderwater() is then false, so the
// compiler drops the underwater shading from every caller.
#ifndef SWELL_SEEN_FROM_BELOW
#error "SWELL_SEEN_FROM_BELOW is given by the program's flags (src/render/programs.h)"
#endif

layout(binding = SWELL_UNIT_WATERLINE) uniform sampler2D waterlineMask;

// Whether this pixel's ray starts (at the near plane) below the water.
// Mask values: SWELL_WATERLINE_ABOVE or _BELOW where the ray meets the
// surface; SWELL_WATERLINE_NO_HIT where it meets no drawn water, so its whole
// drawn length lies in one medium. That length ends at the far plane or where
// the ray leaves the water grid's square skirt, whichever comes first: the
// skirt lies at 0.9 far_m along its axes, so towards the image's borders the
// far plane reaches past it (noDrawnWaterEnd). Where that end lies below every
// trough (waveReachVertical_m under the mean level) the ray is under the
// water, above every crest it is in the air, and within the waves' band the
// end says nothing (a ray from the air passes over a trough below the mean
// level; one from below under a crest above it): the ray then lies on the
// eye's side. Judged by its end against the mean level alone, a ray from the
// air that sank below it beyond the skirt, or over a trough at a near far
// plane, was drawn in the depths' colour: a dark line along the horizon.
// Passes other than the main one bind a 1x1 mask cleared to "above", so the
// coordinate is clamped into the texture.
vec3 noDrawnWaterEnd(vec3 start, vec3 end)
{
    // The segment's parameter where it leaves the square |x|, |z| <= skirt
    // around the grid's centre (the start lies inside it, near the eye).
    vec2 from = start.xz - gridCenter;
    vec2 along = end.xz - start.xz;
    float t = 1.0;
    for (int axis = 0; axis < 2; ++axis)
        if (abs(along[axis]) > 1e-6)
            t = min(t, (sign(along[axis]) * gridSkirt_m - from[axis]) / along[axis]);
    return mix(start, end, clamp(t, 0.0, 1.0));
}

bool pixelUnderwater()
{
#if !SWELL_SEEN_FROM_BELOW
    return false;
#else
    ivec2 texel = min(ivec2(gl_FragCoord.xy - viewportOrigin), textureSize(waterlineMask, 0) - 1);
    float m = texelFetch(waterlineMask, texel, 0).r;
    if (m > 0.75)
        return true;
    if (m > 0.25)
        return false;
    vec2 ndc = viewportUv() * 2.0 - 1.0;
    float endY = noDrawnWaterEnd(nearPlanePoint(ndc), farPlanePoint(ndc)).y;
    if (endY < -waveReachVertical_m)
        return true;
    if (endY > waveReachVertical_m)
        return false;
    return eyeUnderwater != 0;
#endif
}

// Whether a water fragment at p is seen from below (for the mask,
// waterline.frag): the eye lies under the plane of the facet drawn there. The facet's normal comes from the
// position's screen derivatives (what the rasteriser drew, not the shading
// normal), turned to point up; call in uniform control flow.
bool facetSeenFromBelow(vec3 p)
{
    vec3 facet = cross(dFdx(p), dFdy(p));
    facet *= facet.y < 0.0 ? -1.0 : 1.0;
    return dot(facet, eyePosition - p) < 0.0;
}

// Light the water itself scatters towards the eye along a path of length
// path_m starting depth_m below the surface, in direction d.
//
// The model refraction.glsl uses seen from above: Beer-Lambert attenuation
// exp(-a s) per channel with the scene's absorption a (water.absorption_per_m),
// and in-scattered light that tends to the water's own colour W
// (water.deep_color) over a long path. Below the surface the light that is
// scattered is itself attenuated with depth z, as exp(-a z) (daylight decays
// with depth at the diffuse attenuation coefficient K_d ~ (a + b_b) / mu_d,
// Gordon 1989, which absorption dominates in clear water: K_d = a here), and the
// path's depth changes as z(s) = z0 - s*d.y. Single scattering integrates
//
//     L(s) = W a ∫0^s exp(-a z(t)) exp(-a t) dt
//          = W exp(-a z0) (1 - exp(-a (1 - d.y) s)) / (1 - d.y)
//
// which is W for a long level path at the surface (the colour seen from
// above), half of it looking straight down, and W a z0 exp(-a z0) looking
// straight up to the surface (d.y -> 1, the limit taken below).
vec3 underwaterInscatter(vec3 d, float depth_m, float path_m)
{
    vec3 a = waterAbsorption;
    float z0 = max(depth_m, 0.0);
    float up = 1.0 - clamp(d.y, -1.0, 1.0);
    vec3 light = waterDeep * exp(-a * z0);
    if (up < 1e-4)
        return light * a * path_m;
    return light * (1.0 - exp(-a * up * path_m)) / up;
}

// Colour `seen` at the end of a path of path_m through the water from the eye
// (depth_m below the surface), looking along d: attenuated and filled in by
// the water's in-scattering. A path with no end (the depths) gives the water alone.
vec3 underwaterFog(vec3 seen, vec3 d, float depth_m, float path_m)
{
    return seen * exp(-waterAbsorption * path_m) + underwaterInscatter(d, depth_m, path_m);
}

// The background below the surface: the water's depths, no end to the path.
// Only downward and level rays have none; an upward one (a ray between the
// water's triangles, or reflected up by a steep facet) is given a level
// one's colour rather than a path through the surface.
vec3 underwaterBackground(vec3 d, float depth_m)
{
    return underwaterInscatter(vec3(d.x, min(d.y, 0.0), d.z), depth_m, 1e6);
}

// The sun's light the water scatters towards the eye along this pixel's
// ray from start, along d (unit), path_m long: the shafts of light
// (light_shafts.glsl), with the water's absorption (the fog's own) and the
// scene's sun. Added to underwaterFog()'s light and underwaterBackground()'s
// by each caller from the eye; a fragment shader's (the pixel's dither).
vec3 underwaterShafts(vec3 start, vec3 d, float path_m)
{
#if SWELL_CLOUD_SHADOWS
    // The cloud layer's shadow where the shafts start (they reach
    // SWELL_SHAFTS_REACH_M, a texel of the shadow map: cloud_shadow.glsl).
    vec3 sun = sunColor * (sunIntensity * cloudShadowAt(start, 0.0));
#else
    vec3 sun = sunColor * sunIntensity;
#endif
    return shaftsInscatter(start, d, path_m, waterAbsorption, sun,
                           2.0 / (viewportSize.y * projectionFocalY), shaftsDither(gl_FragCoord.xy));
}

// World geometry at p seen from under the water, `lit` as the light that
// reaches p leaves it (mesh.frag: attenuated by the water above p, and the
// sun's light focused by the waves, caustics.glsl): the path from the eye
// to p fogs it.
vec3 underwaterGeometry(vec3 lit, vec3 p)
{
    vec3 toPoint = p - eyePosition;
    float path_m = length(toPoint);
    vec3 d = toPoint / max(path_m, 1e-6);
    return underwaterFog(lit, d, -eyePosition.y, path_m) + underwaterShafts(eyePosition, d, path_m);
}
#endif
