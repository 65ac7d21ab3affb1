#pragma once
// The footprint map: per frame, a 2D texture over the auroral region that gives, for the texel holding a
// point, the nearest dense curtain point (curtain id, point index) and a lower bound of its distance — the
// distance field of Lawlor & Genetti 2011 §3.2 extended with the identity of the nearest point.
// The projection (azimuthal equidistant around a centre) is shaders/components/aurora/footprint_map.glsl, shared
// with the shader.
//
// Build, in two parts, because the shader needs the nearest point only near the curtains and elsewhere
// just a distance to skip by:
// * the band (texel centres within exactWithinKm = reach + margin + one texel of some seed): exact. Every
//   seed visits the texels around its own that can be that near and keeps, per texel, the nearest seed and
//   the nearest seed of another curtain (overlapping curtains both emit). Cost ~ seeds × (band width)²,
//   not texels × passes.
// * everywhere else: a coarse map (kCoarseMapSize² texels at most) built by jump flooding (Rong & Tan,
//   "Jump flooding in GPU with applications to Voronoi diagram and distance transform", I3D 2006: every
//   seed offered to the 3×3 texels around its own, passes with steps N/2, …, 1, then one more step-1 pass)
//   gives a distance from each coarse texel centre to some seed; the fine texel stores that distance less
//   JFA's error allowance and the distance between the centres, and at least exactWithinKm. Those texels'
//   ids are the coarse seed's, which the shader never reads (their bound exceeds the reach).
// Nearest means the largest dot product of unit vectors, in double, ties to the smaller seed number (curtain,
// then point): the result is a function of the input only, so every rank builds identical bytes.
//
// Conservative distance: for a point p in the cap θ ≤ Θ with stored distance D in its texel, D is at most the
// distance from the texel centre to the nearest seed, and
//   distance(p, nearest curtain polyline) ≥ D − marginKm, where
//   marginKm = R·h·√2/2   (p is at most half a texel diagonal from the texel centre: the inverse projection
//                          shrinks lengths — radial scale 1, tangential sin θ/θ ≤ 1 — so the worst scale
//                          is 1 and a texel of side h = 2Θ/N radians spans at most R·h per side)
//            + g/2        (every polyline point is within half the longest arc g between consecutive
//                          points of a seed)
//            + R·2Θ·1e-6  (the float lookup's coordinate error, tested below 1e-6 of the map width).
// Outside the cap (θ > Θ) the map is not read: footprintMapOutsideKm = R(θ − Θ) > 0 is the bound, because
// every curtain point lies inside the cap (the build checks this) and the cap is convex for Θ ≤ 90°.
#include "components/aurora/physics/curtain_geometry.h"
#include "physics/constants.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora::physics {

// The fourth channel packs (curtain, point) of the nearest other curtain into one exact float.
constexpr int kSecondPointStride = 65536;

// Allowance for jump flooding's errors in the coarse map, in coarse texel sides: how much further from
// the texel centre JFA's seed may be than the nearest seed. Measured on random curtains against brute
// force, at most 0.26 texel for N ≥ 128 and 0.67 texel for N = 64 (tests/components/aurora/physics/footprint_map_tests.cpp).
constexpr double kJfaErrorTexels = 1.0;

// Side of the coarse jump-flooded map (or the map's own size, if smaller).
constexpr int kCoarseMapSize = 128;

struct FootprintMapSpec {
    double centreLatitudeDeg = 90.0;  // default: the geographic north pole
    double centreLongitudeDeg = 0.0;  // map −y points toward this longitude from the pole
    double angularRadiusDeg = 40.0;   // Θ: the map's half width, 0 < Θ ≤ 90°
    int size = 512;                   // N texels per side, a power of two ≥ 2
    // The renderer's emitting reach (km): the shader reads the stored points only where the stored
    // distance is within reach plus the margin, so the map is exact there (see exactWithinKm).
    double reachKm = 50.0;
};

// What the shader reads for a point (footprintMapLookup): the texel's contents and the lower bound.
struct FootprintSample {
    int curtainId = -1;         // −1: no curtain (outside the cap, or no curtains at all)
    int pointIndex = -1;        // index into that curtain's CurtainPolyline::points
    double distanceKm = 0.0;    // stored distance (or lower bound, outside the band) from the texel centre
    double conservativeKm = 0.0; // lower bound of the distance from the point to every curtain polyline
};

struct FootprintMap {
    FootprintMapSpec spec;
    double planetRadiusKm = 0.0;
    // Uniforms of shaders/components/aurora/footprint_map.glsl: centre and east unit vectors, Θ in radians.
    glm::dvec3 centre{0.0};
    glm::dvec3 east{0.0};
    double angularRadius = 0.0;
    double marginKm = 0.0;      // see the header comment; uniform for footprintConservativeKm
    double exactWithinKm = 0.0; // reach + margin + one texel: texels whose centre is that near a seed are exact
    int seedCount = 0;          // curtain points (0: every texel says "no curtain")
    // RGBA32F, N × N, row-major, bottom row first: texel (i, j) at [4(jN + i)] holds (curtain id, point index,
    // distance km, second). In the band (the centre within exactWithinKm of a seed): the nearest seed, the
    // distance from the texel centre to it, and `second`, the nearest point of any OTHER curtain within
    // exactWithinKm as curtain id · kSecondPointStride + point index (−1: none that near; overlapping
    // curtains both emit, so the shader evaluates the two nearest curtains). Elsewhere: the coarse map's
    // seed, a lower bound (≥ exactWithinKm) of the centre's distance to every seed, and −1. Ids and indices
    // are integers stored exactly (< 2^24); distances are rounded toward zero. Without curtains every texel
    // is (−1, −1, πR, −1): no curtain is nearer than half the circumference.
    std::vector<float> texels;

    // The shader's lookup in double: outside the cap the far bound R(θ − Θ); inside, texel
    // footprintMapTexel(footprintMapCoord(d)) and footprintConservativeKm(distance, marginKm).
    FootprintSample lookup(const glm::dvec3& unitDir) const;
};

// Everything of the map of these curtains but its texels: the projection's frame, the margin, the band's
// radius (the uniforms, and the inputs of a build on the GPU, footprint_map_gpu.h). Throws as buildFootprintMap.
FootprintMap footprintMapFrame(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm);

// Texels each way around a seed's own texel that hold every texel centre within withinKm of the seed:
// a geodesic of length w from a seed in the cap stays within θ ≤ Θ + w/R, where the projection stretches
// lengths by at most θ/sin θ.
int footprintBandBoxTexels(const FootprintMap& map, double withinKm);
// Side of the coarse jump-flooded map, and how much a fine texel's bound is lowered below its coarse
// texel's seed distance: JFA's allowance plus the distance between the fine and coarse texel centres.
int footprintCoarseMapSize(const FootprintMap& map);
double footprintCoarseSlackKm(const FootprintMap& map);
// The distance stored without curtains: half the circumference, nearer than any curtain could be.
inline double footprintNoCurtainKm(const FootprintMap& map) { return aurorawall::physics::kPi * map.planetRadiusKm; }

// The map of the given curtains (all with planetRadiusKm). Throws std::invalid_argument for a bad spec,
// a curtain point outside the cap, 256 curtains or more, or 65536 points or more in a curtain.
FootprintMap buildFootprintMap(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm);

// Unit vector at the centre of texel (i, j): footprintMapDirection((i + 1/2, j + 1/2)/N), in double.
glm::dvec3 footprintTexelDirection(const FootprintMap& map, int i, int j);

} // namespace aurorawall::components::aurora::physics
