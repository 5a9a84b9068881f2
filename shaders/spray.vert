// The spray's streaks, drawn (src/render/spray_passes.cpp): the ribbons of
// spray_streaks.comp's streaks (spray_clump.glsl), facing the eye. One draw
// of triangle strips, SWELL_SPRAY_STRIP_VERTICES vertices a streak (its 4
// point pairs, the first and the last twice, so that the strips join
// through triangles of no area), the streaks one after another as the
// list has the clumps; each vertex pulls its streak's point and colour
// and stands off its path across the line of sight. A streak not drawn
// (not yet left the crest, too faint) has every vertex at one point, the
// view's centre: its triangles have no area and cover no pixel, and need
// no clipping (a vertex behind the eye would send all its neighbours in
// the draw through a software rasteriser's slow clipping path). (A geometry shader
// emitted these ribbons once: docs/design/performance-log.md, "The spray without a
// geometry shader".)
#include "swell/gpu/spray.h"
#include "frame.glsl"
#include "spray_clump.glsl"

out vec2 vRibbon;     // x: 0 at the streak's tail to 1 at its head; y: -1..1 across
out vec3 vColor;      // lit and fogged, in the pass's output encoding
out float vOpacity;
#ifdef SWELL_BOW_SPRAY
// x: the piece of sheet's own number (0..1), y: the share of it torn open
// (bowSheetTorn); y < 0: a drop's streak.
out flat vec2 vSheet;
#endif

void main()
{
    // Which streak, which of its point pairs and which side of it.
    int streakIndex = gl_VertexID / SWELL_SPRAY_STRIP_VERTICES;
    int corner = clamp(gl_VertexID % SWELL_SPRAY_STRIP_VERTICES - 1, 0, 7);
    int k = corner / 2;
    float s = (corner & 1) == 0 ? -1.0 : 1.0;
    vec4 look = sprayStreaks[streakIndex].look;
    vRibbon = vec2(float(k) / 3.0, s);
    vOpacity = look.x;
#ifdef SWELL_BOW_SPRAY
    vSheet = look.zw;
#endif
    if (look.y == 0.0) {
        vColor = vec3(0.0);
        gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 point = sprayStreaks[streakIndex].points[k].xyz;
    vec4 path = sprayStreaks[streakIndex].path;
    vColor = sprayStreaks[streakIndex].colors[k].rgb;
    vec3 toEye = normalize(eyePosition - point);
    vec3 side = cross(toEye, path.xyz);
    side = dot(side, side) > 1e-12 ? normalize(side) : normalize(cross(toEye, vec3(1.0, 0.0, 0.0)));
    gl_Position = passViewProj * vec4(point + s * path.w * side, 1.0);
}
