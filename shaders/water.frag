// Water shading: reflection weighed against refraction by Fresnel, Phong
// diffuse and a specular lobe spread by the slopes the normal leaves out,
// light through backlit crests, whitecap foam (the waves' and the bodies'
// wake's), and fog; seen from below, Snell's window
// (underwater_surface.glsl). Each term can be left out for the benchmark
// (SWELL_TERM_* in swell/gpu/variants.h).
#include "swell/gpu/label_classes.h"
#include "swell/gpu/variants.h"
#include "frame.glsl"
#include "fog.glsl"
#include "lighting.glsl"
#include "reflection.glsl"
#include "refraction.glsl"
#include "ocean.glsl"
#include "underwater_surface.glsl"
#include "subsurface.glsl"
#include "surf.glsl"
#include "contact.glsl"
#ifndef SWELL_CLOUD_SHADOWS
#error "SWELL_CLOUD_SHADOWS is given by the program's flags (src/render/programs.h)"
#endif
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif
#if SWELL_SURFACE_SOURCES
#include "surface_sources.glsl"
#endif

#ifndef SWELL_WATER_DEFERRED
#error "SWELL_WATER_DEFERRED is given by the program's flags (src/render/program_flags.h)"
#endif
#if SWELL_WATER_DEFERRED
// The shading pass of a frame whose water was drawn in two (render/water_visibility.h):
// the same inputs, read from the vertices the visibility pass kept.
#include "water_deferred.glsl"
#else
in vec3 vPosition;
in vec3 vNormal;
in vec3 vAlongX;
in vec3 vAlongZ;
in vec2 vRestPoint;
in float vCellSize;
in float vHeightScale;
#if SWELL_SURFACE_SOURCES
in vec2 vSourceSlope;
#endif
#ifdef SWELL_OCEAN_VERTEX_DATA
in vec4 vOceanData[SWELL_OCEAN_VERTEX_DATA];
#endif
#endif
#if SWELL_LABEL_PASS
#define SWELL_LABEL_RAYS
#include "labels.glsl"
#else
out vec4 fragColor;
#endif

// A term of the shading is in unless the benchmark left it out.
#define SWELL_HAS_TERM(term) ((SWELL_OMITTED_TERMS & (term)) == 0)

void main()
{
    // The screen derivatives the footprints below take, in uniform control
    // flow: the rasteriser's, or the shading pass's from the triangle.
#if SWELL_WATER_DEFERRED
    loadDeferredWater();
    vec2 restWidth = deferredRestWidth;
    mat2 restSteps = mat2(deferredRestDx, deferredRestDy);
    vec2 positionWidth = deferredPositionWidth;
#else
    vec2 restWidth = fwidth(vRestPoint);
    mat2 restSteps = mat2(dFdx(vRestPoint), dFdy(vRestPoint));
    vec2 positionWidth = fwidth(vPosition.xz);
#endif
    // The sun's direct light here: the cloud layer's shadow shades it
    // (cloud_shadow.glsl), averaged over the pixel's footprint on the
    // water (taken here, in uniform control flow, for its derivatives).
#if SWELL_CLOUD_SHADOWS
    vec2 shadowFootprint = positionWidth * footprintScale;
    float cloudSun = cloudShadowAt(vPosition, max(shadowFootprint.x, shadowFootprint.y));
    vec3 directSun = sunColor * (sunIntensity * cloudSun);
#else
    vec3 directSun = sunColor * sunIntensity;
#endif
#if SWELL_HAS_TERM(SWELL_TERM_WAVE_NORMALS)
    // The grid carries only the waves it can sample; the shading normal takes
    // every wave this pixel can resolve, filtered by the pixel's footprint on
    // the water instead of the grid spacing: the model adds to the grid's
    // interpolated derivatives what the two footprints see differently.
    // The footprint's two sides on the water (the pixel's steps along the
    // screen's x and y), m: seen at a slant it is long along the view and
    // narrow across it, and a model may filter its normals over that shape
    // rather than over a square as wide as it is long (ocean.glsl).
#if SWELL_HAS_TERM(SWELL_TERM_FILTERING)
    vec2 footprint = restWidth * footprintScale;
    float pixelSize_m = max(max(footprint.x, footprint.y), 1e-3);
    mat2 pixelSteps_m = restSteps * footprintScale;
#else
    float pixelSize_m = 1e-3; // every wave, however small the pixel sees it
    mat2 pixelSteps_m = mat2(0.0);
#endif
    // The shading pass computes what the one pass interpolates from the
    // vertices (water_vertex_cache.glsl says why).
#if defined(SWELL_OCEAN_VERTEX_DATA) && !SWELL_WATER_DEFERRED
    SurfacePoint surface = oceanShadingFromVertices(vRestPoint - gridCenter, pixelSize_m, pixelSteps_m, vCellSize,
                                                    vAlongX, vAlongZ, vHeightScale, vOceanData, vCellSize);
#else
    SurfacePoint surface = oceanShading(vRestPoint - gridCenter, pixelSize_m, pixelSteps_m, vCellSize, vAlongX, vAlongZ,
                                        vHeightScale);
#endif
    vec3 n = surface.normal;
    float foam = surface.foam;
    float breakingFoam = surface.breakingFoam;
    vec2 foamSlope = surface.foamSlope;
#if SWELL_HAS_TERM(SWELL_TERM_FILTERING)
    float slopeVariance = surface.slopeVariance;
#else
    float slopeVariance = 0.0;
#endif
#else
    vec3 n = normalize(vNormal);
    float foam = 0.0;
    float breakingFoam = 0.0;
    vec2 foamSlope = vec2(0.0);
    float slopeVariance = 0.0;
#endif
    // The whitecaps' reflectance (see the foam term below).
    float foamAlbedo = mix(0.5, 0.65, breakingFoam);
#if SWELL_SURFACE_SOURCES
    // The sources' waves (the wake's are as short as 2 of its cells) are
    // finer than the grid far from the camera: the pixel takes the slopes it
    // sees itself in place of those the grid's vertices interpolated (n / n.y
    // is (-dh/dx, 1, -dh/dz) for a height field). Where a source breaks (the
    // wake's stern wash), its foam joins the waves' whitecaps.
    vec4 sources = surfaceSourcesAt(vRestPoint);
    n = normalize(n / max(n.y, 0.1) - vec3(sources.y - vSourceSlope.x, 0.0, sources.z - vSourceSlope.y));
    // The sources' foam (the wake's stern wash and breaking crests) takes
    // the whitecaps' look (whitecap_foam.glsl) from its amount: dense and
    // bright where it breaks now, thinning into lace as it ages, with the
    // same relief; its lattices are anchored to the world at the render
    // origin, where vRestPoint is measured from.
    vec2 sourceFootprint = restWidth * footprintScale;
    FoamLook sourceLook = foamLook(sourceFoamNoise, sourceBreakingFoamAmount, sources.w, vRestPoint,
                                   max(max(sourceFootprint.x, sourceFootprint.y), 1e-3));
    float sourceFoam = sourceLook.cover;
    // Where the sources' foam is the larger share, the foam is theirs.
    if (sourceFoam > foam) {
        foamAlbedo = mix(0.5, 0.65, sourceLook.breaking);
        foamSlope = sourceLook.slope;
    }
    foam = max(foam, sourceFoam);
#else
    float sourceFoam = 0.0;
#endif
    // The surf where the coast's waves break (surf.glsl): its foam rides the
    // crests (the grid's normal: the long waves', not the ripples') and
    // thins behind them; where it is the larger share, the foam is the surf's.
    // The waves' wash against what stands in the water (contact.glsl) is the
    // surf's foam too: the larger of the two amounts.
    float surfFoamAmount = max(surfAmount(vRestPoint - gridCenter, vPosition.y, normalize(vNormal)),
                               contactAmount(vPosition, vPosition.y));
#if SWELL_HAS_TERM(SWELL_TERM_FOAM)
    if (surfFoamAmount > 0.0) {
        vec2 surfFootprint = restWidth * footprintScale;
        FoamLook surf = surfLook(surfFoamAmount, vRestPoint, max(max(surfFootprint.x, surfFootprint.y), 1e-3));
        if (surf.cover > foam) {
            foamAlbedo = mix(0.5, 0.65, surf.breaking);
            foamSlope = surf.slope;
        }
        foam = max(foam, surf.cover);
    }
#endif
    vec3 toEye = eyePosition - vPosition;
    float distance_m = length(toEye);
    vec3 v = toEye / distance_m;
#if SWELL_LABEL_PASS
    // Foam where it covers the point the pixel's centre ray meets, as the
    // range is that point's (docs/LABELS.md): the texture at full detail
    // there, so the share of a frame's sea labelled foam is the foam's
    // covered share at every distance (a rule of half the pixel's area
    // counted none of the lace finer than a pixel: from 300 m most of the
    // sea's foam). The wake's (every surface source's) where it is the
    // larger share, else the waves' whitecaps.
    float pointFoam = oceanFoamAtPoint(vRestPoint - gridCenter, vHeightScale);
#if SWELL_SURFACE_SOURCES
    float pointSourceFoam = foamAtPoint(sourceFoamNoise, sourceBreakingFoamAmount, sources.w, vRestPoint);
#else
    float pointSourceFoam = 0.0;
#endif
    // The surf's whitewater is a class of its own: the coast's breaking and
    // the waves' wash against what stands in them, where its foam is the
    // larger share at the point.
    float pointSurfFoam = surfFoamAtPoint(surfFoamAmount, vRestPoint);
    uint label = SWELL_LABEL_WATER;
    if (max(max(pointFoam, pointSurfFoam), pointSourceFoam) >= SWELL_LABEL_FOAM_COVER) {
        if (pointSourceFoam >= max(pointFoam, pointSurfFoam))
            label = SWELL_LABEL_WAKE_FOAM;
        else
            label = pointSurfFoam > pointFoam ? SWELL_LABEL_SURF : SWELL_LABEL_WHITECAP_FOAM;
    }
    writeLabels(labelRangeToPlane(vPosition, normalize(vNormal)), n, label, 0u);
    return;
#endif
    // Underwater hook: the surface seen from below is Snell's window and the
    // water's own colour, shaded in underwater_surface.glsl. The waterline
    // mask says so: it holds the side this very fragment is seen from when
    // the eye is near the surface, and the eye's side elsewhere (so a
    // folded facet of a choppy sea never turns a view from the air to one
    // from below).
#if SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED
    if (pixelUnderwater()) {
        fragColor = passOutput(surfaceFromBelow(vPosition, n, viewportUv()));
        fragColor.a = passMarksWater != 0 ? 0.0 : 1.0;
        return;
    }
#endif
    // Seen from a grazing angle, an interpolated normal can face away.
    if (dot(n, v) < 0.0)
        n = normalize(n - v * dot(n, v) * 1.01);

#if SWELL_HAS_TERM(SWELL_TERM_REFLECTION)
    vec3 reflected = reflectedRadiance(vPosition, reflect(-v, n));
#else
    vec3 reflected = skyHorizon;
#endif
#if SWELL_HAS_TERM(SWELL_TERM_REFRACTION)
    vec2 screenUv = viewportUv();
    float path_m;
    vec3 refracted = refractedRadiance(vPosition, n, screenUv, path_m);
#else
    float path_m = 100.0;
    vec3 refracted = waterDeep;
#endif
    float fresnel = fresnelSchlick(dot(n, v), fresnelF0);
#if SWELL_HAS_TERM(SWELL_TERM_LIGHTING)
    // Phong diffuse lights the light scattered inside the water. The sky
    // lights it from every side, whatever the surface's facing: 0.35 of it,
    // so a face turned from the sun keeps a third of the water's colour
    // rather than going black; the sun's 0.65 follows the facing.
    // The relighting fades in along the refracted path, at 0.2 per metre
    // (over its first 5 m, e-folding): what lies close under the surface was
    // lit by its own pass already and keeps that light, while the water's
    // own colour, behind a long path, takes the surface's. The path is cut
    // at 100 m, where the weight is 1 to 2e-9, so the 1e6 m that stands for
    // "nothing under the water" (refraction.glsl) changes nothing.
#if SWELL_CLOUD_SHADOWS
    // The water's own colour (waterDeep) is the scene's, chosen for its
    // prevailing light, which the sun's intensity never entered: the
    // layer's shadows scale the sun's share of it by the sun reaching here
    // against the layer's mean, capped at the clear sky's (cloud_shadow.glsl).
    // So under scattered clouds a patch in a gap is lit as under a clear
    // sky and one in a cloud's shadow keeps little more than the sky's
    // share, while a deck that lets through under 2% of the sun anywhere
    // (the storm's) leaves it as it was.
    float bodySun = min((cloudSun + 0.02) / (cloudShadowMean() + 0.02), 1.0);
    float lit = 0.35 + 0.65 * phongDiffuse(n) * bodySun;
#else
    float lit = 0.35 + 0.65 * phongDiffuse(n);
#endif
    refracted *= mix(1.0, lit, 1.0 - exp(-0.2 * min(path_m, 100.0)));
#endif
#if SWELL_HAS_TERM(SWELL_TERM_FOAM)
    // The bubbles a breaking crest drove under the surface, seen through the
    // water: a diffuse cloud kBubbleDepth_m down along the refracted ray (so
    // it shifts against the surface foam as the view tilts: parallax),
    // blurred over 1.5 m, scattering the daylight that reaches it back up
    // through that much water each way: pale turquoise under and beside
    // the whitecaps. Its strength (up to 0.8 of the way toward half the
    // light a foam layer would send) is chosen by eye.
    const float kBubbleDepth_m = 0.6;
    vec3 underRay = refract(-v, n, 1.0 / 1.333);
    vec2 bubblePoint = vRestPoint - gridCenter + underRay.xz / max(-underRay.y, 0.2) * kBubbleDepth_m;
    vec2 bubbleFootprint = restWidth * footprintScale;
    float bubbles = oceanFoamBelow(bubblePoint, max(1.5, max(bubbleFootprint.x, bubbleFootprint.y)));
#if SWELL_SURFACE_SOURCES
    // And those a source's breaking drove down (the wake's stern wash), the
    // same way: its amount squared, which its cells (a metre or so) already
    // blur.
    float sourceBelow = surfaceSourcesAt(vRestPoint + underRay.xz / max(-underRay.y, 0.2) * kBubbleDepth_m).w;
    bubbles = max(bubbles, sourceBelow * sourceBelow);
#endif
    // And the surf's: its roller drives a cloud of bubbles (and the sand it
    // stirs) through the shallow water under and behind it, as the wash
    // does at a structure's face.
    bubbles = max(bubbles, surfFoamAmount * surfFoamAmount);
    bubbles *= step(kBubbleDepth_m, path_m);
    vec3 bubbleLight = (directSun * max(sunDirection.y, 0.0) + max(skyAmbient(vec3(0.0, 1.0, 0.0)), vec3(0.0))) *
                       exp(-2.0 * kBubbleDepth_m * waterAbsorption);
    refracted = mix(refracted, 0.5 * bubbleLight, 0.8 * clamp(bubbles, 0.0, 1.0));
#endif
    vec3 color = mix(refracted, reflected, fresnel);
#if SWELL_HAS_TERM(SWELL_TERM_LIGHTING)
    // The slopes the normal leaves out spread the sun's highlight: the Phong
    // lobe is about a Gaussian of variance 1/shininess in the reflected
    // direction, and a slope variance s2 (x plus z) tilts the reflection by
    // twice the slope, adding 2*s2 (Toksvig 2005's widening of filtered
    // normals; Bruneton et al. 2010, sec. 4.2, for waves). The lobe's
    // normalisation keeps its energy.
    float spreadShininess = shininess / (1.0 + 2.0 * shininess * slopeVariance);
    color += directSun * specularStrength * phongSpecular(n, v, spreadShininess, fresnelF0) * step(0.0, sunDirection.y);
#endif

#if SWELL_HAS_TERM(SWELL_TERM_SUBSURFACE)
    // Thin, backlit crests glow blue-green (subsurface.glsl); the light
    // leaves through the surface, so what Fresnel reflects does not.
#if SWELL_CLOUD_SHADOWS
    color += (1.0 - fresnel) * crestGlow(vPosition.y, v) * cloudSun;
#else
    color += (1.0 - fresnel) * crestGlow(vPosition.y, v);
#endif
#endif

#if SWELL_HAS_TERM(SWELL_TERM_FOAM)
    // Whitecaps: a layer of bubbles that scatters nearly all light back,
    // lit by the sun and the sky (Lambertian, as foam is close to; Koepke
    // 1984 measured its effective reflectance at about 0.55 in the visible):
    // the dense foam of a crest breaking now brighter (0.65), the thinning
    // lace, through which the water shows, darker (0.5). The sky's light is
    // its irradiance on the foam's normal (skyAmbient, as the world's
    // objects get it), so foam under an overcast deck, the sun hidden, is
    // lit white-grey by the whole sky rather than by a fraction of the
    // horizon's colour. Its own normal is
    // the water's tilted by the bubbles' relief (n / n.y is (-dh/dx, 1,
    // -dh/dz)), so foam is shaded by its mounds and hollows, and its wet
    // bubbles catch the sun in a broad highlight (a Phong lobe of exponent
    // 12, a quarter of the sun's light at its peak: chosen by eye).
    float foamCover = clamp(foam, 0.0, 1.0); // the share of the pixel foam covers
    vec3 foamNormal = normalize(n / max(n.y, 0.1) - vec3(foamSlope.x, 0.0, foamSlope.y));
    vec3 sunLight = directSun * max(sunDirection.y, 0.0);
    vec3 foamLight = sunLight * (0.6 + 0.4 * phongDiffuse(foamNormal)) + max(skyAmbient(foamNormal), vec3(0.0));
    float sheen = 0.25 * pow(max(dot(reflect(-sunDirection, foamNormal), v), 0.0), 12.0);
    color = mix(color, foamAlbedo * foamLight + sheen * sunLight, foamCover);
#else
    float foamCover = 0.0;
#endif

#if SWELL_DEBUG_VIEW == SWELL_VIEW_NORMALS
    color = n * 0.5 + 0.5;
#elif SWELL_DEBUG_VIEW == SWELL_VIEW_REFLECTION
    color = reflected;
#elif SWELL_DEBUG_VIEW == SWELL_VIEW_REFRACTION
    color = refracted;
#elif SWELL_DEBUG_VIEW == SWELL_VIEW_FOAM
    // The share of the pixel the shading covers with foam, as a grey level
    // (sRGB-encoded like every colour: tests decode it).
    color = vec3(foamCover);
#elif SWELL_DEBUG_VIEW == SWELL_VIEW_LOD
    // Cell size on a log scale: 0.25 m red ... 256 m blue, with stripes per level.
    float level = log2(max(vCellSize, 0.01) / 0.25) / 10.0;
    color = mix(vec3(1.0, 0.2, 0.1), vec3(0.1, 0.3, 1.0), clamp(level, 0.0, 1.0)) * (0.75 + 0.25 * fract(level * 10.0));
#endif
#if (SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED || SWELL_DEBUG_VIEW == SWELL_VIEW_REFLECTION || SWELL_DEBUG_VIEW == SWELL_VIEW_REFRACTION) && SWELL_HAS_TERM(SWELL_TERM_FOG)
    color = applyFog(color, distance_m, -toEye);
#endif
    fragColor = passOutput(color);
    fragColor.a = passMarksWater != 0 ? 0.0 : 1.0; // frame.glsl: for the temporal resolve
}
