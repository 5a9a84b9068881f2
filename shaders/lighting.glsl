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
    const float pi = 3.14159265;
    return fresnelSchlick(dot(h, toEye), f0) * pow(max(dot(r, toEye), 0.0), shininess) * (shininess + 2.0) / (8.0 * pi);
}
#endif
