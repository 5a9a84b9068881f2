// The water grid's vertices at the view's previous draw, for the host's
// motion vectors: each vertex of THIS draw's grid (its rest points, cells
// and fade) displaced by the wave model bound for the previous time
// (WaveModelGpu::prepareEarlierView), kept at its index. Drawn as points
// with the rasteriser off.
#include "water_vertex.glsl"
#include "swell/gpu/bindings.h"

layout(std430, binding = SWELL_STORAGE_WATER_PREVIOUS) writeonly buffer PreviousWater {
    vec4 previousWaterPositions[]; // relative to the render origin, m
};

void main()
{
    previousWaterPositions[gl_VertexID] = vec4(waterVertexPosition(waterVertex(gl_VertexID)), 1.0);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
