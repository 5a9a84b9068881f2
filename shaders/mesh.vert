// World geometry: terrain, rocks, buoys, boats and user glTF models.
#include "frame.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;

uniform mat4 model; // object to render-origin-relative world, m

out vec3 vPosition;
out vec3 vNormal;
out vec3 vColor;

void main()
{
    vec4 world = model * vec4(position, 1.0);
    vPosition = world.xyz;
    vNormal = mat3(model) * normal;
    vColor = color;
    gl_ClipDistance[0] = dot(clipPlane, world);
    gl_Position = passViewProj * world;
}
