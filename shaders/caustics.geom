// The caustics pass: each triangle of the source grid carries the sun's
// flux that crosses it, Phi = E (A . s) T (A its area vector, s towards the
// sun, T Fresnel's transmittance), down the refracted rays to each slice,
// and spreads it evenly over the triangle it lands on there: irradiance
// Phi / A' with A' that triangle's area. Added up over the map (additive
// blending), every cell's flux lands once per slice, so the map's mean is
// the light the surface lets in, whatever the waves (beam tracing, Watt
// 1990, "Light-water interaction using backward beam tracing", run forward
// from the sun: the ratio of the areas is the focusing).
//
// Stored over the air's irradiance on a level plane, E s.y. No image is
// smaller than the sun's disc allows: a cell's rays diverge by the sun's
// angular diameter in the water, so its image is at least that blur wide
// over the cell's side; a smaller one is grown about its centre to that
// area, its flux kept.
#include "caustics.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3 * SWELL_CAUSTICS_SLICES) out;

in vec3 vSurface[];
in vec3 vRay[];
in float vTransmittance[];

flat out float gIrradiance; // this triangle's share, over the air's irradiance E s.y

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

void main()
{
    // The grid's triangles are wound so that a level one's area vector
    // points up (render/caustics_map.cpp).
    vec3 area = 0.5 * cross(vSurface[2] - vSurface[0], vSurface[1] - vSurface[0]);
    float transmittance = (vTransmittance[0] + vTransmittance[1] + vTransmittance[2]) / 3.0;
    float flux = max(dot(area, causticsSun), 0.0) * transmittance / causticsSun.y;
    // A ray the surface sends up or along it (a steep facet under a low sun) lights nothing below.
    if (flux <= 0.0 || max(vRay[0].y, max(vRay[1].y, vRay[2].y)) > -0.05)
        return;
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
        vec2 image[3];
        float path_m = 0.0;
        for (int i = 0; i < 3; ++i) {
            float travel = (vSurface[i].y + causticsSliceDepth_m[k]) / -vRay[i].y;
            image[i] = vSurface[i].xz + vRay[i].xz * travel;
            path_m += travel / 3.0;
        }
        vec2 centre = (image[0] + image[1] + image[2]) / 3.0;
        float imageArea = 0.5 * abs(cross2(image[1] - image[0], image[2] - image[0]));
        float blur_m = path_m * SWELL_SUN_ANGULAR_DIAMETER_RAD / SWELL_WATER_IOR;
        float leastArea = blur_m * causticsCellSize_m;
        float grow = imageArea < leastArea ? sqrt(leastArea / max(imageArea, 1e-12)) : 1.0;
        // A triangle whose rays meet in a line has no area to grow: its
        // flux is left out (a set of measure zero of the cells).
        if (imageArea <= 1e-12)
            continue;
        gIrradiance = flux / max(imageArea, leastArea);
        for (int i = 0; i < 3; ++i) {
            vec2 uv = (centre + (image[i] - centre) * grow - causticsMapCorner_m) / causticsMapSize_m;
            gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
            gl_Layer = k;
            EmitVertex();
        }
        EndPrimitive();
    }
}
