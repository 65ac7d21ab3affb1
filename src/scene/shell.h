#pragma once
// Where a component's shading step lies along a pixel's ray: the concentric shells of a planet and
// what lies behind them, front to back (Lawlor & Genetti 2011, section 3.1). The generated shadeRay
// (src/render/march_shader.cpp) and the CPU reference (src/render/reference_ray.cpp) run the
// shading steps shell by shell in this order (scene/compositing_order.h).
//
// Emission only adds to the ray's radiance, so the order changes nothing but the rounding of those
// sums; it is fixed so that the same scene always gives the same bits, and it follows the shells
// so that what a step reads (the lower atmosphere's segment and transmittance) is set before it.
namespace aurorawall::scene {

enum class Shell {
    // The dense lower atmosphere: its extinction, which sets the transmittance every later step
    // applies to what lies behind it, and the light it scatters.
    LowerAtmosphere,
    // Emission of the upper atmosphere that depends on altitude only: spherical emitting layers
    // around the whole planet.
    EmittingLayers,
    // Emission of the upper atmosphere with a shape of its own: structures with a place and an
    // extent (sheets, boxes), and what gives them their small-scale detail.
    EmittingStructures,
    // An opaque cloud layer below the upper atmosphere, in front of the ground.
    CloudDeck,
    // The ground surface and what lies on it.
    Ground,
    // Beyond the planet's layers: what is seen where a ray leaves them, behind everything.
    Space,
};

} // namespace aurorawall::scene
