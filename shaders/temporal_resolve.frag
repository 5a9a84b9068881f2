// The temporal resolve (docs/RENDERING.md "Temporal resolve"): the frame,
// drawn at the render scale with its projection jittered by a sub-pixel
// offset that changes every frame, is blended into the history of the frames
// before it at the output's full size. Each output pixel:
//   1. the frame's own estimate there: its drawn samples nearest the pixel,
//      each weighted by its distance to the pixel's centre in output pixels
//      (a Gaussian fit to Blackman-Harris, exp(-2.29 d^2): Karis 2014,
//      "High-quality temporal supersampling", SIGGRAPH course). Drawn at
//      half the output's size or less (the program built with
//      SWELL_TEMPORAL_HALF_SIZE_OR_LESS), the 2x2 samples about the pixel:
//      the next are 2 output pixels away or more along an axis, where the
//      weight is at most exp(-9.16), 1.05e-4; above that the 3x3 about the
//      nearest;
//   2. where the pixel's point was in the last frame: its depth (the drawn
//      sample nearest the pixel) unprojected, reprojected with the last
//      frame's view and projection (`reprojection`); the water's own motion
//      is not followed (see RENDERING.md): the clip below bounds it;
//   3. the history there (bilinear), clipped to the box of the nearest
//      drawn sample's 3x3 neighbourhood in YCoCg
//      (shaders/temporal_neighbourhood.frag, gathered once per drawn
//      pixel), so that what the frame no longer shows (a disocclusion, a
//      moved crest, a camera cut) does not linger;
//   4. blended by weight: the history carries the weight of the frames in
//      it (alpha, at most SWELL_TEMPORAL_MAX_WEIGHT; on the water, while the
//      waves move, SWELL_TEMPORAL_WATER_MAX_WEIGHT), the frame the weight of
//      its samples near the pixel. A pixel whose history lies off the last
//      frame starts again from the frame alone.
// Colours are the main pass's display-ready (sRGB-encoded) values, in which
// the clip's box and the blend are perceptually even.
#include "swell/gpu/bindings.h"
#include "swell/gpu/temporal.h"
#include "temporal_colour.glsl"

layout(binding = SWELL_UNIT_POST_SOURCE) uniform sampler2D frameColor;
layout(binding = SWELL_UNIT_TEMPORAL_HISTORY) uniform sampler2D history;
// Per drawn pixel (temporal_neighbourhood.frag): the clip box's centre and
// the pixel's water mark; the box's half extent and the pixel's depth.
layout(binding = SWELL_UNIT_TEMPORAL_BOX_CENTRE) uniform sampler2D boxCentre;
layout(binding = SWELL_UNIT_TEMPORAL_BOX_EXTENT) uniform sampler2D boxExtent;

// This frame's clip space (unjittered) to the last frame's (unjittered).
uniform mat4 reprojection;
// This frame's jitter, drawn pixels: the drawn pixel i shows the point at
// i + 0.5 - jitter of the unjittered image.
uniform vec2 jitter_px;
// Window depth to NDC z: z * scale + offset.
uniform vec2 depthToNdc;
// 0 when there is no history (the first frame, a reset).
uniform float historyValid;
// The most weight the water's history holds this frame: SWELL_TEMPORAL_MAX_WEIGHT
// while the time stands, SWELL_TEMPORAL_WATER_MAX_WEIGHT while the waves
// move. The main pass marks the water's pixels with alpha 0.
uniform float waterMaxWeight;

layout(location = 0) out vec4 resolved;
// The same colour for the output, opaque (8 bits: blitted into the output).
layout(location = 1) out vec4 display;

// Moves `h` along the line to the box's centre until it lies in the box
// (clipping rather than clamping each channel keeps the hue).
vec3 clipToBox(vec3 h, vec3 centre, vec3 extent)
{
    vec3 offset = h - centre;
    vec3 units = abs(offset) / max(extent, vec3(1.0e-4));
    float largest = max(units.x, max(units.y, units.z));
    return largest > 1.0 ? centre + offset / largest : h;
}

void main()
{
    ivec2 outSize = textureSize(history, 0);
    ivec2 inSize = textureSize(frameColor, 0);
    vec2 uv = gl_FragCoord.xy / vec2(outSize);
    vec2 drawnPerOutput = vec2(inSize) / vec2(outSize);
    // The pixel's centre in drawn pixels, shifted so that drawn pixel i's
    // sample lies at i.
    vec2 q = uv * vec2(inSize) + jitter_px - 0.5;
    ivec2 nearest = ivec2(floor(q + 0.5));
    ivec2 last = inSize - 1;

    // Chosen when the program is built, not by a branch here: a software
    // rasteriser runs both sides of a branch for a block of pixels.
    vec3 sum = vec3(0.0);
    float weights = 0.0;
#ifdef SWELL_TEMPORAL_HALF_SIZE_OR_LESS
    ivec2 first = ivec2(floor(q));
    vec2 d0 = (vec2(first) - q) / drawnPerOutput; // output pixels
    vec2 d1 = d0 + 1.0 / drawnPerOutput;
    vec2 w0 = exp(-2.29 * d0 * d0), w1 = exp(-2.29 * d1 * d1);
    for (int dy = 0; dy <= 1; ++dy) {
        for (int dx = 0; dx <= 1; ++dx) {
            vec3 c = texelFetch(frameColor, clamp(first + ivec2(dx, dy), ivec2(0), last), 0).rgb;
            float w = (dx == 0 ? w0.x : w1.x) * (dy == 0 ? w0.y : w1.y);
            sum += c * w;
            weights += w;
        }
    }
#else
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 at = nearest + ivec2(dx, dy);
            vec3 c = texelFetch(frameColor, clamp(at, ivec2(0), last), 0).rgb;
            vec2 d = (vec2(at) - q) / drawnPerOutput; // output pixels
            float w = exp(-2.29 * dot(d, d));
            sum += c * w;
            weights += w;
        }
    }
#endif
    vec3 current = sum / max(weights, 1.0e-6);
    ivec2 drawn = clamp(nearest, ivec2(0), last);
    vec4 centre = texelFetch(boxCentre, drawn, 0);
    vec4 extent = texelFetch(boxExtent, drawn, 0);
    float depth = extent.a;
    vec4 previous = reprojection * vec4(uv * 2.0 - 1.0, depth * depthToNdc.x + depthToNdc.y, 1.0);
    vec2 previousUv = previous.xy / previous.w * 0.5 + 0.5;
    bool onScreen = previous.w > 0.0 && all(greaterThanEqual(previousUv, vec2(0.0)))
                    && all(lessThanEqual(previousUv, vec2(1.0)));

    // The frame's weight: its samples' near the pixel, at most one whole
    // sample's (at scale 1 the nearest alone is about that).
    float frameWeight = min(weights, 1.0);
    if (historyValid < 0.5 || !onScreen) {
        resolved = vec4(current, frameWeight);
        display = vec4(current, 1.0);
        return;
    }
    vec4 h = textureLod(history, previousUv, 0.0); // no derivatives: one level
    vec3 clipped = fromYCoCg(clipToBox(toYCoCg(h.rgb), centre.rgb, extent.rgb));
    bool water = centre.a < 0.5;
    // The history keeps at most the cap less one whole sample's weight: a
    // sample at the pixel's centre then weighs 1/cap, a farther one less,
    // however few the frame's samples near the pixel are.
    float kept = min(h.a, (water ? waterMaxWeight : SWELL_TEMPORAL_MAX_WEIGHT) - 1.0);
    float total = kept + frameWeight;
    float share = frameWeight / max(total, 1.0e-6);
    resolved = vec4(mix(clipped, current, share), total);
    display = vec4(resolved.rgb, 1.0);
}
