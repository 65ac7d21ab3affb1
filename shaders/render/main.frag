// Entry point of the march as a fragment shader over a full-screen triangle: one fragment = one
// pixel's ray, written to the float target's attachments 0 (radiance) and 1 (work).
layout(location = 0) out vec4 fragRadiance;
layout(location = 1) out float fragWork;

void main()
{
    gPixelCentre = gl_FragCoord.xy;
    shadePixel(fragRadiance, fragWork);
}
