// The host's motion vectors on the water: the grid's vertex now (exactly as
// water.vert places it) and the same vertex at the previous draw
// (water_previous.vert), so a fragment's point moves as the material point
// of the drawn surface does, as the optical flow's labels move it
// (src/ocean/optical_flow.cpp).
#include "water_vertex.glsl"
#include "motion.glsl"
#include "swell/gpu/bindings.h"

layout(std430, binding = SWELL_STORAGE_WATER_PREVIOUS) readonly buffer PreviousWater {
    vec4 previousWaterPositions[]; // relative to the render origin, m
};

out vec4 vPreviousClip;

void main()
{
    vPreviousClip = motionPreviousViewProj * vec4(previousWaterPositions[gl_VertexID].xyz, 1.0);
    gl_Position = passViewProj * vec4(waterVertexPosition(waterVertex(gl_VertexID)), 1.0);
}
