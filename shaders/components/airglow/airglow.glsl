// airglow: the night sky's own light, thin emitting layers of the upper atmosphere (O(1S) green
// 557.7 nm near 97 km, Na D 589 nm near 92 km, O(1D) red 630.0 nm near 250 km). Each layer's
// column along the ray comes from airglow_layer.glsl in closed form; its colour is the line's CIE
// colour, and it is seen through the lower atmosphere like the aurora.
#define AIRGLOW_MAX_LAYERS 4
// Layers are cut off where the upper exponential has fallen by e^-40 (4e-18).
const float AIRGLOW_TOP_SCALE_HEIGHTS = 40.0;

uniform int uAirglowLayerCount;
uniform vec4 uAirglowLayer[AIRGLOW_MAX_LAYERS];           // base km, Hu km, Hl km, A rayleigh per km
uniform vec3 uAirglowRgbPerRayleigh[AIRGLOW_MAX_LAYERS];  // linear sRGB cd/m^2 of one rayleigh of the line

Ray shadeAirglow(Ray ray)
{
    for (int i = 0; i < uAirglowLayerCount; ++i) {
        vec4 layer = uAirglowLayer[i];
        float base = layer.x, top = layer.x + AIRGLOW_TOP_SCALE_HEIGHTS * layer.y;
        ShellSegments shell = rayShell(ray.origin, ray.direction, uPlanetRadiusKm + base, ray.altitude - base,
                                       uPlanetRadiusKm + top, ray.altitude - top, ray.end);
        for (int k = 0; k < 2; ++k) {
            vec2 part = k == 0 ? shell.first : shell.second;
            if (part.x < part.y)
                ray.radiance += uAirglowRgbPerRayleigh[i] * transmittanceTo(ray, part) *
                                airglowColumn(ray.origin, ray.direction, part.x, part.y, layer, uPlanetRadiusKm + base);
        }
    }
    return ray;
}
