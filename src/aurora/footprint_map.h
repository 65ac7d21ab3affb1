#pragma once
// The footprint map: per frame, a 2D texture over the auroral region that gives, for the texel holding a
// point, the nearest dense curtain point (curtain id, point index) and its great-circle distance — the
// jump-flooded distance field of Lawlor & Genetti 2011 §3.2 extended with the identity of the nearest point.
// The projection (azimuthal equidistant around a centre) is shaders/aurora/footprint_map.glsl, shared
// with the shader.
//
// Build (Rong & Tan, "Jump flooding in GPU with applications to Voronoi diagram and distance transform",
// I3D 2006): the seeds are the dense points of all curtains. Every seed is first offered to the 3×3
// texels around the texel that holds it (so a texel crossed by several seeds starts with the best of
// them), then jump flooding passes with steps N/2, N/4, …, 1 and one more step-1 pass ("JFA+1") let every
// texel take, among the seeds of its 9 texels at ±step, the one nearest to its centre. Nearest means the
// largest dot product of unit vectors, in double, ties to the smaller seed number (curtain, then point):
// the result is a function of the input only, so every rank builds identical bytes.
//
// Conservative distance: for a point p in the cap θ ≤ Θ with stored distance D in its texel,
//   distance(p, nearest curtain polyline) ≥ D − marginKm, where
//   marginKm = R·h·√2/2   (p is at most half a texel diagonal from the texel centre: the inverse projection
//                          shrinks lengths — radial scale 1, tangential sin θ/θ ≤ 1 — so the worst scale
//                          is 1 and a texel of side h = 2Θ/N radians spans at most R·h per side)
//            + g/2        (every polyline point is within half the longest arc g between consecutive
//                          points of a seed)
//            + R·h·kJfaErrorTexels (how much further from the texel centre JFA's seed may be than the
//                          nearest seed: measured on random curtains against brute force, at most 0.26 texel
//                          for N ≥ 128 and 0.67 texel for N = 64, in texels that touch the cap; see
//                          tests/aurora/footprint_map_tests.cpp)
//            + R·2Θ·1e-6  (the float lookup's coordinate error, tested below 1e-6 of the map width).
// Outside the cap (θ > Θ) the map is not read: footprintMapOutsideKm = R(θ − Θ) > 0 is the bound, because
// every curtain point lies inside the cap (the build checks this) and the cap is convex for Θ ≤ 90°.
#include "aurora/curtain_geometry.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::aurora {

// The fourth channel packs (curtain, point) of the nearest other curtain into one exact float.
constexpr int kSecondPointStride = 65536;

// Allowance for jump flooding's errors, in texel sides (see above).
constexpr double kJfaErrorTexels = 1.0;

struct FootprintMapSpec {
    double centreLatitudeDeg = 90.0;  // default: the geographic north pole
    double centreLongitudeDeg = 0.0;  // map −y points toward this longitude from the pole
    double angularRadiusDeg = 40.0;   // Θ: the map's half width, 0 < Θ ≤ 90°
    int size = 512;                   // N texels per side, a power of two ≥ 2
    // The nearest point of another curtain is looked for only where the nearest curtain is closer
    // than this (km; the renderer's emitting reach) plus the map's margin: elsewhere the shader reads
    // no curtain, and jump flooding with steps up to that distance suffices.
    double secondCurtainWithinKm = 50.0;
};

// What the shader reads for a point (footprintMapLookup): the texel's contents and the lower bound.
struct FootprintSample {
    int curtainId = -1;         // −1: no curtain (outside the cap, or no curtains at all)
    int pointIndex = -1;        // index into that curtain's CurtainPolyline::points
    double distanceKm = 0.0;    // stored distance from the texel centre to that point
    double conservativeKm = 0.0; // lower bound of the distance from the point to every curtain polyline
};

struct FootprintMap {
    FootprintMapSpec spec;
    double planetRadiusKm = 0.0;
    // Uniforms of shaders/aurora/footprint_map.glsl: centre and east unit vectors, Θ in radians.
    glm::dvec3 centre{0.0};
    glm::dvec3 east{0.0};
    double angularRadius = 0.0;
    double marginKm = 0.0;      // see the header comment; uniform for footprintConservativeKm
    // RGBA32F, N × N, row-major, bottom row first: texel (i, j) at [4(jN + i)] holds (curtain id, point index,
    // distance km from the texel centre to that point, second), where `second` is the nearest point of
    // any OTHER curtain as curtain id · kSecondPointStride + point index, if it is within
    // secondCurtainWithinKm plus the margin (−1: none that near; overlapping curtains both emit, so the
    // shader evaluates the two nearest curtains). Ids and indices are integers stored exactly
    // (< 2^24); the distance is rounded toward zero. Without curtains every texel is (−1, −1, πR, −1): no
    // curtain is nearer than half the circumference.
    std::vector<float> texels;

    // The shader's lookup in double: outside the cap the far bound R(θ − Θ); inside, texel
    // footprintMapTexel(footprintMapCoord(d)) and footprintConservativeKm(distance, marginKm).
    FootprintSample lookup(const glm::dvec3& unitDir) const;
    // lookup(unitDir).conservativeKm.
    double conservativeDistanceKm(const glm::dvec3& unitDir) const;
};

// The map of the given curtains (all with planetRadiusKm). Throws std::invalid_argument for a bad spec,
// a curtain point outside the cap, 256 curtains or more, or 65536 points or more in a curtain.
FootprintMap buildFootprintMap(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm);

// Unit vector at the centre of texel (i, j): footprintMapDirection((i + 1/2, j + 1/2)/N), in double.
glm::dvec3 footprintTexelDirection(const FootprintMap& map, int i, int j);

} // namespace aurorawall::aurora
