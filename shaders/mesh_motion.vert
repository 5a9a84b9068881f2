// The host's motion vectors on the world's meshes (mesh.vert's positions):
// each vertex where it is now and where the object's previous pose put it.
#include "motion.glsl"

layout(location = 0) in vec3 position;

uniform mat4 model;         // object to render-origin-relative world, m
uniform mat4 previousModel; // object to the same origin at the previous draw (the pose then), m

out vec4 vPreviousClip;

void main()
{
    vPreviousClip = motionPreviousViewProj * (previousModel * vec4(position, 1.0));
    gl_Position = passViewProj * (model * vec4(position, 1.0));
}
