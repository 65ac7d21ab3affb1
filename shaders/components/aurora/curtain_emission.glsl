// The line emission of each curtain's electrons over altitude (docs/aurora-physics.md, "Tables"): one row
// per curtain, rebuilt when its energy changes (src/components/aurora/physics/emission_table.h).
// Needs aurora/deposition_coords.glsl before it. Texture: GL_LINEAR along the altitude, clamp to edge.
uniform sampler2DArray uCurtainEmission; // RGBA32F, x: altitude node, layer: curtain; linear sRGB (cd/m²)
                                         // per km of path per erg cm⁻² s⁻¹ of incident energy flux
uniform vec3 uCurtainEmissionAxes;       // (z_0 km, node spacing km, node count)

// Linear sRGB added per km of path per erg cm⁻² s⁻¹ by curtain c's electrons at altitude z (km):
// multiply by the local energy flux and the path length in km.
vec3 curtainEmissionRgbPerKm(real altitudeKm, int c)
{
    return vec3(textureLod(uCurtainEmission, vec3(emissionTexCoord(altitudeKm, uCurtainEmissionAxes), 0.5, real(c)), 0.0));
}
