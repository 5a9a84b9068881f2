// The caustics pass, second step (render/caustics_map.h): each triangle of
// the source grid carries the sun's flux that crosses it,
// Phi = E (A . s) T (A its area vector, s towards the sun, T Fresnel's
// transmittance), down the refracted rays to each slice, and spreads it
// evenly over the triangle it lands on there: irradiance Phi / A' with A'
// that triangle's area. Added up over the map (additive blending,
// caustics.vert/.frag), every cell's flux lands once per slice, so the map's
// mean is the light the surface lets in, whatever the waves (beam tracing,
// Watt 1990, "Light-water interaction using backward beam tracing", run
// forward from the sun: the ratio of the areas is the focusing).
//
// Stored over the air's irradiance on a level plane, E s.y. No image is
// smaller than the sun's disc allows: a cell's rays diverge by the sun's
// angular diameter in the water, so its image is at least that blur wide
// over the cell's side; a smaller one is grown about its centre to that
// area, its flux kept.
//
// Each slice's images are written in a scattered order (a multiplicative
// permutation of the triangles), so the triangles drawn one after another
// lie far apart: neighbouring triangles share the edges of their images,
// and a GPU that blends in the order of the primitives waits on each one
// touching the texels of the one before (an NVIDIA H100 took 12.2 ms for
// the pass in the grid's order, 2.1 ms scattered).
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"
#include "gpu/constants.glsl"
#include "caustics.glsl"

layout(local_size_x = SWELL_CAUSTICS_GROUP) in;

struct CausticsSource {
    vec4 surface; // xyz: the displaced point, relative to the render origin, m; w: the transmittance
    vec4 ray;     // xyz: the sun's refracted ray, unit, pointing down
};
layout(std430, binding = SWELL_STORAGE_CAUSTICS_SOURCES) readonly buffer CausticsSources {
    CausticsSource sources[];
};
// Per slice, per triangle, its three corners: xy the place in the map's
// clip space, z the triangle's irradiance over the air's E s.y.
layout(std430, binding = SWELL_STORAGE_CAUSTICS_IMAGES) writeonly buffer CausticsImages {
    vec4 corners[];
};

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Outside the clip volume: the rasteriser drops such a triangle unseen.
const vec4 kNoCorner = vec4(4.0, 4.0, 0.0, 0.0);

void main()
{
    const int triangles = 2 * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_CELLS;
    int triangle = int(gl_GlobalInvocationID.x);
    if (triangle >= triangles)
        return;
    // Two triangles a cell, wound so that a level one's area vector
    // cross(v2 - v0, v1 - v0) points up.
    int perSide = causticsCells + 1;
    int cell = triangle / 2;
    int v00 = (cell / causticsCells) * perSide + cell % causticsCells;
    int v10 = v00 + 1, v01 = v00 + perSide, v11 = v01 + 1;
    ivec3 corner = triangle % 2 == 0 ? ivec3(v00, v10, v01) : ivec3(v10, v11, v01);
    vec3 surface[3], ray[3];
    float transmittance = 0.0;
    for (int i = 0; i < 3; ++i) {
        CausticsSource s = sources[corner[i]];
        surface[i] = s.surface.xyz;
        ray[i] = s.ray.xyz;
        transmittance += s.surface.w / 3.0;
    }
    // The slot in each slice's draw order.
    uint slot = (uint(triangle) * uint(SWELL_CAUSTICS_ORDER_STRIDE)) % uint(triangles);
    vec3 area = 0.5 * cross(surface[2] - surface[0], surface[1] - surface[0]);
    float flux = max(dot(area, causticsSun), 0.0) * transmittance / causticsSun.y;
    // A ray the surface sends up or along it (a steep facet under a low sun) lights nothing below.
    bool lit = flux > 0.0 && max(ray[0].y, max(ray[1].y, ray[2].y)) <= -0.05;
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
        uint first = 3u * (uint(k * triangles) + slot);
        vec2 image[3];
        float path_m = 0.0;
        for (int i = 0; i < 3; ++i) {
            float travel = (surface[i].y + causticsSliceDepth_m[k]) / -ray[i].y;
            image[i] = surface[i].xz + ray[i].xz * travel;
            path_m += travel / 3.0;
        }
        vec2 centre = (image[0] + image[1] + image[2]) / 3.0;
        float imageArea = 0.5 * abs(cross2(image[1] - image[0], image[2] - image[0]));
        float blur_m = path_m * SWELL_SUN_ANGULAR_DIAMETER_RAD / SWELL_WATER_IOR;
        float leastArea = blur_m * causticsCellSize_m;
        float grow = imageArea < leastArea ? sqrt(leastArea / max(imageArea, 1e-12)) : 1.0;
        // A triangle whose rays meet in a line has no area to grow: its
        // flux is left out (a set of measure zero of the cells).
        if (!lit || imageArea <= 1e-12) {
            for (int i = 0; i < 3; ++i)
                corners[first + uint(i)] = kNoCorner;
            continue;
        }
        float irradiance = flux / max(imageArea, leastArea);
        for (int i = 0; i < 3; ++i) {
            vec2 uv = (centre + (image[i] - centre) * grow - causticsMapCorner_m) / causticsMapSize_m;
            corners[first + uint(i)] = vec4(uv * 2.0 - 1.0, irradiance, 1.0);
        }
    }
}
