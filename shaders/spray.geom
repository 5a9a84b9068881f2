// The spray's clumps (spray.vert) as drops of five sizes, each a soft
// puff facing the eye, drawn out along its velocity by the distance it
// flies in a thirtieth of a second (the streak a camera's shutter sees).
// A drop of response time tau under Stokes drag (Stokes 1851) relaxes
// towards the wind's velocity and its terminal fall g tau,
//   v(a) = v_inf + (v0 - v_inf) exp(-a / tau),
//   x(a) = x0 + v_inf a + (v0 - v_inf) tau (1 - exp(-a / tau)),
// closed form, so a drop's place needs no history: the small ones are taken
// up by the wind at once and blown far, the large fall back soon.
#include "frame.glsl"
#include "spray.glsl"

layout(points) in;
layout(triangle_strip, max_vertices = 20) out;

in vec3 vBirth[];
in vec3 vLaunch[];
in vec3 vWind[];
in float vAge_s[];
in flat uint vKey[];
in float vOpacity[];

out vec2 gCorner;     // -1..1 across the quad
out vec3 gPosition;   // relative to the render origin, m
out float gOpacity;

void main()
{
    if (vOpacity[0] <= 0.0)
        return;
    float age_s = vAge_s[0];
    for (uint drop = 0u; drop < 5u; ++drop) {
        // tau 0.05 to 0.4 s: spume drops of about 90 to 270 um
        // (tau = rho_w d^2 / (18 mu_air)).
        float u = (float(drop) + sprayUnit(vKey[0], 10u + drop)) / 5.0;
        float tau_s = 0.05 + 0.35 * u * u;
        vec3 terminal = vWind[0] + vec3(0.0, -9.81 * tau_s, 0.0);
        float relaxed = exp(-age_s / tau_s);
        vec3 p = vBirth[0] + terminal * age_s + (vLaunch[0] - terminal) * tau_s * (1.0 - relaxed);
        vec3 velocity = terminal + (vLaunch[0] - terminal) * relaxed;
        // It fades as it falls back to the crest's height, where the foam takes it.
        float opacity = vOpacity[0] * smoothstep(-0.3, 0.4, p.y - vBirth[0].y);
        if (opacity <= 0.0)
            continue;
        vec3 toEye = normalize(eyePosition - p);
        vec3 along = velocity - dot(velocity, toEye) * toEye;
        float speed = length(along);
        along = speed > 1e-3 ? along / speed : normalize(cross(toEye, vec3(1.0, 0.0, 0.0)));
        vec3 side = normalize(cross(toEye, along));
        // A puff of drops spreading as it flies.
        float r = 0.3 + 0.9 * age_s;
        vec3 halfAlong = along * (r + 0.5 * speed / 30.0), halfSide = side * r;
        for (int i = 0; i < 4; ++i) {
            vec2 c = vec2(i & 1, i >> 1) * 2.0 - 1.0;
            gCorner = c;
            gPosition = p + c.x * halfAlong + c.y * halfSide;
            gOpacity = opacity;
            gl_Position = passViewProj * vec4(gPosition, 1.0);
            EmitVertex();
        }
        EndPrimitive();
    }
}
