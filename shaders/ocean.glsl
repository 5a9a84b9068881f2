// The ocean surface, whatever model draws it: the water shaders call
//   SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
// for the displaced grid vertex, and the water's fragment shader calls
//   SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m,
//                             vec3 gridAlongX, vec3 gridAlongZ, float heightScale)
// for the normal and foam one pixel sees (displacement left zero), given the
// partial derivatives the grid's vertices carry, interpolated, having summed
// the surface at gridFootprint_m: a model may add only what the grid filtered out.
// The water's fragment shader calls the overload
//   SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m,
//                             float gridFootprint_m, vec3 gridAlongX, vec3 gridAlongZ, float heightScale)
// whose pixelSteps_m holds the footprint's two sides on the water (the
// rest point's steps across one pixel along the screen's x and y, m; zero
// for no footprint): a model may filter its normals over that shape (long
// along the view, narrow across it, where the water is seen at a slant)
// and otherwise does what the first does.
// and
//   float oceanFoamBelow(vec2 restOffset_m, float footprint_m)
// for the bubbles a breaking drove under the surface there (0 for models without foam), and
//   float oceanFoamAtPoint(vec2 restOffset_m, float heightScale)
// for whether foam covers the point itself, its texture at full detail
// (the labels' foam classes: 1 or 0).
// A model may also hand the water's pixels work its vertices did: it then
// defines SWELL_OCEAN_VERTEX_DATA (a count of vec4s) and
//   void oceanVertexData(vec2 restOffset_m, out vec4 data[SWELL_OCEAN_VERTEX_DATA])
//   SurfacePoint oceanShadingFromVertices(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m,
//                                         vec3 gridAlongX, vec3 gridAlongZ, float heightScale,
//                                         vec4 data[SWELL_OCEAN_VERTEX_DATA], float cellSize_m)
// (with the pixelSteps_m overload beside it, as oceanShading's)
// and the water's fragment shader calls the latter with the data
// interpolated over the triangle and the grid's cell size there (m).
// The renderer builds them with SWELL_OCEAN_FILE naming the model's GLSL
// file (include/swell/wave_model_gpu.h), so no water shader names a model.
#ifndef SWELL_OCEAN_GLSL
#define SWELL_OCEAN_GLSL

// Mirrors swell::SurfacePoint (swell/wave_model.h), plus the whitecap
// foam, which only the GPU tracks.
struct SurfacePoint {
    vec3 displacement; // from the rest point, m
    vec3 normal;       // unit, pointing up: normalize(cross(alongZ, alongX))
    float foam;        // whitecap cover, 0..1 (0 for models without foam)
    vec3 alongX;       // partial derivative of the displaced point along rest x
    vec3 alongZ;       // ... and along rest z
    float slopeVariance; // mean square slope (x plus z) of the waves the normal leaves
                         // out: what shading spreads the highlight by (oceanShading only)
    float breakingFoam;  // the share of the foam a crest breaking now made, 0..1 (oceanShading only)
    vec2 foamSlope;      // the foam's relief: d/dx, d/dz of its bubbles' height (oceanShading only)
};

#ifndef SWELL_OCEAN_FILE
#error SWELL_OCEAN_FILE must name the wave model's GLSL file
#endif
#include SWELL_OCEAN_FILE
#endif
