// The caustics pass's draw (render/caustics_map.h): one slice's triangles,
// as caustics_images.comp placed them in the map, each corner read as a
// vertex attribute (x, y: clip space; z: the triangle's irradiance).
layout(location = 0) in vec4 corner;

flat out float gIrradiance; // this triangle's share, over the air's irradiance E s.y

void main()
{
    gIrradiance = corner.z;
    gl_Position = vec4(corner.xy, 0.0, 1.0);
}
