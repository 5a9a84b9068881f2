// Renders one face of the procedural sky cubemap (drawn with fullscreen.vert
// into a face of the cubemap; see src/render/sky_cubemap.cpp): the gradient
// sky, or with SWELL_SKY_PHYSICAL 1 the atmosphere's with its cloud layer
// (clouds.glsl; none while cloudCover is 0, and then the sky is the clear one
// to the bit).
#include "frame.glsl"
#if SWELL_SKY_PHYSICAL
#include "atmosphere.glsl"
#include "clouds.glsl"
// SkySettings::exposure: displayed colour per unit radiance over the sun's irradiance.
uniform float skyExposure;
#else
#include "sky_procedural.glsl"
#endif

uniform int face; // 0..5: +x, -x, +y, -y, +z, -z

in vec2 vNdc;
out vec4 fragColor;

// The direction of the texel at face coordinates (s, t) in -1..1: the inverse
// of the OpenGL cube map face selection table (spec 8.13). Window x and y of
// a face attachment are its s and t.
vec3 faceDirection(int f, vec2 st)
{
    float s = st.x, t = st.y;
    if (f == 0) return vec3(1.0, -t, -s);
    if (f == 1) return vec3(-1.0, -t, s);
    if (f == 2) return vec3(s, 1.0, t);
    if (f == 3) return vec3(s, -1.0, -t);
    if (f == 4) return vec3(s, -t, 1.0);
    return vec3(-s, -t, -1.0);
}

void main()
{
    // Linear radiance: the cubemap is half-float, as the glow can exceed 1.
    vec3 d = normalize(faceDirection(face, vNdc));
#if SWELL_SKY_PHYSICAL
    vec3 radiance = atmosphereSkyRadiance(d, sunDirection);
    if (cloudCover > 0.0)
        radiance = cloudySkyRadiance(d, sunDirection, radiance);
    fragColor = vec4(skyExposure * radiance, 1.0);
#else
    fragColor = vec4(proceduralSky(d), 1.0);
#endif
}
