// The caustics pass (caustics_images.comp, caustics.vert): each fragment adds its triangle's
// irradiance to the map's texel (additive blending into R32F).
flat in float gIrradiance;
out vec4 causticsIrradiance;

void main()
{
    causticsIrradiance = vec4(gIrradiance, 0.0, 0.0, 1.0);
}
