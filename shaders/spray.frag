// The spray's streaks (spray.geom): their colour, lit and fogged per
// vertex there, under a Gaussian profile across and a tail fading in along
// them; blended over the frame.
in vec2 gRibbon;
in vec3 gColor;
in float gOpacity;

layout(location = 0) out vec4 fragColor;

void main()
{
    // Across: a Gaussian profile, no edge. Along: the tail fades in (the
    // streak's oldest part has spread into the air), the head ends softly.
    float across = (exp(-3.0 * gRibbon.y * gRibbon.y) - exp(-3.0)) / (1.0 - exp(-3.0));
    float along = smoothstep(0.0, 0.7, gRibbon.x) * (1.0 - 0.6 * smoothstep(0.8, 1.0, gRibbon.x));
    fragColor = vec4(gColor, gOpacity * across * along);
}
