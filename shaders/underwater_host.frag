// The host's own geometry seen from under the water (Renderer::draw): the
// water's absorption and in-scattering along the path from the eye (the
// shafts of light included), as
// mesh.frag's underwaterGeometry() gives Swell's own objects. The host's
// colour is not read: the pass blends with two outputs (dual-source),
//   result = inscatter + host colour * transmittance,
// per channel. Its depth is a copy of the host's (hostDepth).
#include "swell/gpu/bindings.h"
#include "frame.glsl"
#include "underwater.glsl"

layout(binding = SWELL_UNIT_HOST_DEPTH) uniform sampler2D hostDepth;

layout(location = 0, index = 0) out vec4 inscatter;
layout(location = 0, index = 1) out vec4 transmittance;

void main()
{
    float depth = texelFetch(hostDepth, ivec2(gl_FragCoord.xy - viewportOrigin), 0).r;
    if (!depthHasGeometry(depth) || !pixelUnderwater())
        discard;
    vec3 p = worldFromScreen(viewportUv(), depth);
    vec3 toPoint = p - eyePosition;
    float path_m = length(toPoint);
    vec3 d = toPoint / max(path_m, 1e-6);
    // The light reaching p through the water above it, then along the path.
    transmittance = vec4(exp(-waterAbsorption * (max(-p.y, 0.0) + path_m)), 1.0);
    // On a display-encoded target the sum is taken on encoded values: exact
    // on a linear one (OutputEncoding::Linear).
    inscatter = vec4(passOutput(underwaterInscatter(d, -eyePosition.y, path_m) + underwaterShafts(eyePosition, d, path_m)).rgb, 0.0);
}
