// The label pass's outputs (swell/dataset/labels.h): in place of a colour, each
// fragment writes the distance from the eye along its ray, m, and its unit
// world normal (attachment 0, 32-bit float), and its semantic class and
// instance (attachment 1, 16-bit unsigned integers: never filtered or
// blended, so no pixel holds a mix of two labels).
#ifndef SWELL_LABELS_GLSL
#define SWELL_LABELS_GLSL

layout(location = 0) out vec4 labelRangeNormal;
layout(location = 1) out uvec2 labelClassInstance;
// The colour programs' output, a plain variable here: their shading after
// the labels are written still compiles, and is never run.
vec4 fragColor;

void writeLabels(float range_m, vec3 normal, uint semanticClass, uint instance)
{
    labelRangeNormal = vec4(range_m, normal);
    labelClassInstance = uvec2(semanticClass, instance);
}

#ifdef SWELL_LABEL_RAYS
// Pixel (relative to the viewport's corner, 1) to the ray's direction in
// world axes. In double precision: near the horizon a ray meets the water
// at a grazing angle, where the range changes by r / tan(angle) per radian
// and single precision's 1e-7 would move it by decimetres at kilometres.
uniform dmat3 labelRayFromPixel;

dvec3 labelPixelRay()
{
    return normalize(labelRayFromPixel * dvec3(dvec2(gl_FragCoord.xy) - dvec2(viewportOrigin), 1.0));
}

// The distance along this pixel's ray to the plane through p (relative to
// the render origin) with normal n: the drawn triangle's, whose interpolated
// point p is exact only to single precision along the plane (which moves no
// intersection with it). Where the ray runs along the plane, the distance to p.
float labelRangeToPlane(vec3 p, vec3 n)
{
    dvec3 d = labelPixelRay();
    double along = dot(d, dvec3(n));
    if (abs(along) < 1e-4)
        return length(p - eyePosition);
    return float(dot(dvec3(p) - dvec3(eyePosition), dvec3(n)) / along);
}
#endif

#endif
