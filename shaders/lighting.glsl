// Phong diffuse and specular from the sun, and Schlick's Fresnel term.
#ifndef SWELL_LIGHTING_GLSL
#define SWELL_LIGHTING_GLSL
#include "gpu/constants.glsl"
#include "frame.glsl"

float fresnelSchlick(float cosTheta, float f0)
{
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cosTheta, 0.0, 1.0), 5.0);
}

// The sky's light on a surface facing unit n, as an albedo of 1 reflects it:
// the nine harmonics of swell::shHarmonics (y up) weighted by ambientSh
// (src/render/sky_light.cpp: the gradient's old mix of horizon and zenith
// colours exactly, or the physical sky's irradiance).
vec3 skyAmbient(vec3 n)
{
    return ambientSh[0].rgb * 0.282095 + ambientSh[1].rgb * (0.488603 * n.z) + ambientSh[2].rgb * (0.488603 * n.y)
        + ambientSh[3].rgb * (0.488603 * n.x) + ambientSh[4].rgb * (1.092548 * n.x * n.z)
        + ambientSh[5].rgb * (1.092548 * n.z * n.y) + ambientSh[6].rgb * (0.315392 * (3.0 * n.y * n.y - 1.0))
        + ambientSh[7].rgb * (1.092548 * n.x * n.y) + ambientSh[8].rgb * (0.546274 * (n.x * n.x - n.z * n.z));
}

float phongDiffuse(vec3 normal)
{
    return max(dot(normal, sunDirection), 0.0);
}

// Specular lobe of the sun reflected about normal, seen along toEye:
// energy-conserving Phong ((n + 2) / 8pi keeps the reflected energy fixed as
// the lobe narrows), weighted by Fresnel at the half vector, since water
// reflects the sun only as much as it reflects anything at that angle.
float phongSpecular(vec3 normal, vec3 toEye, float shininess, float f0)
{
    vec3 r = reflect(-sunDirection, normal);
    vec3 h = normalize(sunDirection + toEye);
    return fresnelSchlick(dot(h, toEye), f0) * pow(max(dot(r, toEye), 0.0), shininess) * (shininess + 2.0) / (8.0 * SWELL_PI);
}
#endif
