// One pixel's ray as the components composite it, front to back (Lawlor & Genetti 2011,
// section 3.1, figure 8). Shared by the shader and the C++ reference (src/common/glsl.h): the
// generated shadeRay (src/render/march_shader.cpp) passes it through each listed component's
// geometry step, then through each shading step shell by shell, front to back (src/scene/shell.h).
//
// The ray x(t) = origin + t direction, t >= 0 in km, |direction| = 1, starts at the camera, or for a
// far camera beyond the scene (src/cluster/frame_state.h, rayStart), `altitude` km above the ground. The layers are concentric shells that
// never overlap (ground, lower atmosphere, the emitting upper atmosphere above it), so along any ray each
// emitting part lies wholly in front of or wholly behind the lower atmosphere.
//
// Besides the ray's own state, the fields belong to roles (src/components/roles/names.h), not to
// components: the provider of the role "ground" sets altitude, blocked and groundT in its geometry step
// (boundByGround, render/layers.glsl), and the provider of the role "lower atmosphere" sets
// lowerAtmosphere and transmittance in its shading step (the first shell), for the later steps of
// whichever components are listed. A component keeps anything else it needs in its own module: the
// struct is compiled once as C++ for every scene, so it has no field that only some scenes set.
struct Ray {
    vec3 origin;
    vec3 direction;
    real altitude;        // ground: the ray's start above the ground, km (0 without a planet)
    bool blocked;         // ground: nothing is seen (the start is below the ground)
    real groundT;         // ground: where the ray meets it; negative if it never does or something hides it
    real end;             // where the ray stops: the ground or an opaque layer (a cloud deck), else 1e30
    vec2 lowerAtmosphere; // lower atmosphere: the part of the ray inside it (empty when x >= y)
    vec3 transmittance;   // lower atmosphere: through it, for whatever lies behind it
    vec3 radiance;        // gathered so far (cd/m^2, linear sRGB)
};
