// The sky's one triangle over the whole viewport, at the far plane of the
// view's depth convention (frame.glsl), so that with the depth test at
// GL_LEQUAL (GL_GEQUAL reversed) it covers only what nothing else drew.
#include "frame.glsl"

out vec2 vNdc;

void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    vNdc = p;
    gl_Position = vec4(p, farNdcZ, 1.0);
}
