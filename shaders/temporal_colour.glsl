// YCoCg (Malvar & Sullivan 2003), the space in which the temporal resolve's
// clip box is drawn: its luma and chroma axes keep a box about a colour
// from skewing its hue (Karis 2014).
vec3 toYCoCg(vec3 c)
{
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 fromYCoCg(vec3 y)
{
    return vec3(y.x + y.y - y.z, y.x + y.z, y.x - y.y - y.z);
}
