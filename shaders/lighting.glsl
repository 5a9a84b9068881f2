// Phong diffuse and specular from the sun, and Schlick's Fresnel term.
#ifndef SWELL_LIGHTING_GLSL
#define SWELL_LIGHTING_GLSL
#include "frame.glsl"

float fresnelSchlick(float cosTheta, float f0)
{
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cosTheta, 0.0, 1.0), 5.0);
}

float phongDiffuse(vec3 normal)
{
    return max(dot(normal, sunDirection.xyz), 0.0);
}

// Specular lobe of the sun reflected about normal, seen along toEye.
float phongSpecular(vec3 normal, vec3 toEye, float shininess)
{
    vec3 r = reflect(-sunDirection.xyz, normal);
    // Normalised Phong, so a tighter lobe is brighter rather than dimmer.
    return pow(max(dot(r, toEye), 0.0), shininess) * (shininess + 2.0) / 8.0;
}
#endif
