// The water's shading pass (water.frag with SWELL_WATER_DEFERRED): drawn
// over the screen tiles that show water (water_tiles.comp,
// water_tiles.vert), it shades each water pixel once. The visibility pass
// (water_visibility.frag) left in each pixel the grid triangle it shows,
// and in the vertex cache (water_vertex_cache.glsl) that triangle's
// vertices; here the pixel takes what the rasteriser would have handed
// water.frag: the vertices' outputs interpolated at the pixel's centre,
// perspective-correct, and their screen derivatives for the footprints
// (render/water_visibility.h says why).
#ifndef SWELL_WATER_DEFERRED_GLSL
#define SWELL_WATER_DEFERRED_GLSL
#include "swell/gpu/bindings.h"
#include "frame.glsl"
#include "water_vertex_cache.glsl"

layout(binding = SWELL_UNIT_WATER_VISIBILITY) uniform usampler2D waterVisibility;
layout(binding = SWELL_UNIT_WATER_DEPTH) uniform sampler2D waterDepth;

// What water.vert hands water.frag, here from the cache.
vec3 vPosition;
vec3 vNormal;
vec3 vAlongX;
vec3 vAlongZ;
vec2 vRestPoint;
float vCellSize;
float vHeightScale;
#if SWELL_SURFACE_SOURCES
vec2 vSourceSlope;
#endif
// (No vOceanData: the shading pass computes the wave model's lookups per
// pixel; water_vertex_cache.glsl says why.)

// fwidth() of the rest point and of the displaced position's x and z,
// which water.frag takes for its footprints, and dFdx() and dFdy() of the
// rest point, for the shading normal's footprint on the water (its long
// axis and its width).
vec2 deferredRestWidth;
vec2 deferredPositionWidth;
vec2 deferredRestDx, deferredRestDy;

// 1 + the grid triangle that pixel `texel` of the viewport shows, 0 for none.
uint visibleTriangle(ivec2 texel)
{
    return texelFetch(waterVisibility, min(texel, textureSize(waterVisibility, 0) - 1), 0).r;
}

// The perspective-correct barycentric weights at NDC point ndc of the
// triangle whose clip-space corners give the edge functions e (the rows of
// the inverse of the matrix of their x, y and w: Olano & Greer 1997,
// "Triangle scan conversion using 2D homogeneous coordinates", which hold
// behind the eye too, where a corner's w is negative).
vec3 barycentricAt(mat3 e, vec2 ndc)
{
    vec3 l = vec3(ndc, 1.0) * e;
    return l / (l.x + l.y + l.z);
}

// Slot `slot` of the triangle's corners a, b, c at the weights.
#define SWELL_INTERPOLATED(slot, weights) \
    ((weights).x * a.v[slot] + (weights).y * b.v[slot] + (weights).z * c.v[slot])

// Fills the inputs above for this pixel, and its depth. A pixel that shows
// no water but shares its 2 x 2 quad with one that does takes that pixel's
// triangle, extended (a helper, as the rasteriser's would be, so that the
// quad's implicit derivatives stay those of one surface), and is then
// discarded; a quad without water is discarded at once.
void loadDeferredWater()
{
    ivec2 texel = ivec2(gl_FragCoord.xy - viewportOrigin);
    uint id = visibleTriangle(texel);
    bool water = id != 0u;
    ivec2 quad = texel & ~1;
    for (int k = 0; k < 4 && id == 0u; ++k)
        id = visibleTriangle(quad + ivec2(k & 1, k >> 1));
    if (id == 0u)
        discard;
    uint triangle = id - 1u;
    // Each corner read once (what is never used is never read).
    CachedWaterVertex a = cachedWaterVertices[waterIndices[3u * triangle]];
    CachedWaterVertex b = cachedWaterVertices[waterIndices[3u * triangle + 1u]];
    CachedWaterVertex c = cachedWaterVertices[waterIndices[3u * triangle + 2u]];
    vec3 ca = (passViewProj * vec4(a.v[0].xyz, 1.0)).xyw;
    vec3 cb = (passViewProj * vec4(b.v[0].xyz, 1.0)).xyw;
    vec3 cc = (passViewProj * vec4(c.v[0].xyz, 1.0)).xyw;
    mat3 edges = mat3(cross(cb, cc), cross(cc, ca), cross(ca, cb));
    // This pixel's centre, and the derivatives the rasteriser takes across
    // a 2 x 2 quad: from its first pixel to the next in x and in y.
    vec2 pixelNdc = 2.0 * viewportInvSize;
    vec2 ndc = viewportUv() * 2.0 - 1.0;
    vec2 quadNdc = (vec2(quad) + 0.5) * pixelNdc - 1.0;
    vec3 w = barycentricAt(edges, ndc);
    vec3 w0 = barycentricAt(edges, quadNdc);
    vec3 wx = barycentricAt(edges, quadNdc + vec2(pixelNdc.x, 0.0));
    vec3 wy = barycentricAt(edges, quadNdc + vec2(0.0, pixelNdc.y));

    vec4 s0 = SWELL_INTERPOLATED(0, w), s1 = SWELL_INTERPOLATED(1, w);
    vec4 s2 = SWELL_INTERPOLATED(2, w), s3 = SWELL_INTERPOLATED(3, w);
    vPosition = s0.xyz;
    vCellSize = s0.w;
    vNormal = s1.xyz;
    vHeightScale = s1.w;
    vAlongX = s2.xyz;
    vAlongZ = s3.xyz;
    vRestPoint = vec2(s2.w, s3.w);
#if SWELL_SURFACE_SOURCES
    vSourceSlope = SWELL_INTERPOLATED(4, w).xy;
#endif

    // The rest point (slots 2.w and 3.w) and the position's x and z (slot
    // 0's) at the quad's three pixels.
    mat3x4 restAndPosition = mat3x4(vec4(a.v[2].w, a.v[3].w, a.v[0].xz), vec4(b.v[2].w, b.v[3].w, b.v[0].xz),
                                    vec4(c.v[2].w, c.v[3].w, c.v[0].xz));
    vec4 at0 = restAndPosition * w0;
    vec4 stepX = restAndPosition * wx - at0, stepY = restAndPosition * wy - at0;
    vec4 width = abs(stepX) + abs(stepY);
    deferredRestDx = stepX.xy;
    deferredRestDy = stepY.xy;
    deferredRestWidth = width.xy;
    deferredPositionWidth = width.zw;
    if (!water)
        discard;
    gl_FragDepth = texelFetch(waterDepth, texel, 0).r;
}
#endif
