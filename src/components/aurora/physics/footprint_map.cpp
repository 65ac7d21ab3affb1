#include "components/aurora/physics/footprint_map.h"

#include "physics/constants.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::components::aurora::physics {
namespace {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/angle.glsl"
#include "components/aurora/footprint_map.glsl"
} // namespace f64

constexpr int kMaxExactInteger = 1 << 24; // floats hold every integer below 2^24 exactly

// A float no larger than x (x ≥ 0): round to nearest, then step down if that rounded up.
float roundedDown(double x)
{
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, 0.0f) : f;
}

// The seeds, ordered by curtain then point. One more direction follows the last seed's: "none", a NaN that
// never wins a comparison, so the flooding loop needs no branch for empty texels.
struct Seeds {
    std::vector<glm::dvec3> direction;
    std::vector<int> curtain;
    std::vector<int> point;
    int none() const { return static_cast<int>(direction.size()) - 1; }
};

// Every texel centre's direction, row by row.
std::vector<glm::dvec3> texelDirections(const FootprintMap& map)
{
    const int n = map.spec.size;
    std::vector<glm::dvec3> out(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            out[static_cast<size_t>(j) * n + i] = footprintTexelDirection(map, i, j);
    return out;
}

// One jump flooding pass with offset `step` (Rong & Tan 2006, §3): texel t takes, among its own seed and
// the seeds of the 8 texels t + step·(±1 or 0, ±1 or 0), the one whose direction has the largest dot product
// with t's centre direction; equal dot products go to the smaller seed number.
void jumpFloodPass(const std::vector<int>& src, std::vector<int>& dst, int n, int step,
                   const std::vector<glm::dvec3>& texelDirection, const Seeds& seeds)
{
    const int none = seeds.none();
    for (int j = 0; j < n; ++j) {
        const int* rows[3];
        int rowCount = 0;
        for (int jj = j - step; jj <= j + step; jj += step)
            if (jj >= 0 && jj < n)
                rows[rowCount++] = &src[static_cast<size_t>(jj) * n];
        for (int i = 0; i < n; ++i) {
            const int t = j * n + i;
            const glm::dvec3 here = texelDirection[t];
            int best = src[t];
            double bestDot = best == none ? -2.0 : glm::dot(here, seeds.direction[best]);
            auto consider = [&](int s) {
                const double d = glm::dot(here, seeds.direction[s]);
                const bool better = (d > bestDot) | ((d == bestDot) & (s < best));
                best = better ? s : best;
                bestDot = better ? d : bestDot;
            };
            const bool left = i >= step, right = i + step < n;
            for (int r = 0; r < rowCount; ++r) {
                if (left)
                    consider(rows[r][i - step]);
                consider(rows[r][i]);
                if (right)
                    consider(rows[r][i + step]);
            }
            dst[t] = best;
        }
    }
}

// The coarse map: every seed is offered to the 3×3 texels around its own (so a texel crossed by several
// seeds starts with the best of them), then passes with steps n/2, n/4, …, 1 and one more step-1 pass
// ("JFA+1"). Returns each texel's (approximately) nearest seed.
std::vector<int> jumpFlood(const Seeds& seeds, const std::vector<glm::dvec3>& texelDirection, const FootprintMap& map)
{
    const int n = map.spec.size;
    const int none = seeds.none();
    std::vector<int> nearest(static_cast<size_t>(n) * n, none), scratch(nearest.size());
    for (int s = 0; s < none; ++s) {
        const glm::dvec2 texel = f64::footprintMapTexel(
            f64::footprintMapCoord(seeds.direction[s], map.centre, map.east, map.angularRadius), n);
        for (int j = std::max(int(texel.y) - 1, 0); j <= std::min(int(texel.y) + 1, n - 1); ++j)
            for (int i = std::max(int(texel.x) - 1, 0); i <= std::min(int(texel.x) + 1, n - 1); ++i) {
                const int t = j * n + i;
                const int best = nearest[t];
                // Seeds come in increasing order, so an equal dot product keeps the earlier (smaller) seed.
                if (best == none || glm::dot(texelDirection[t], seeds.direction[s]) >
                                        glm::dot(texelDirection[t], seeds.direction[best]))
                    nearest[t] = s;
            }
    }
    if (none == 0)
        return nearest;
    for (int step = n / 2; step >= 1; step /= 2) {
        jumpFloodPass(nearest, scratch, n, step, texelDirection, seeds);
        std::swap(nearest, scratch);
    }
    jumpFloodPass(nearest, scratch, n, 1, texelDirection, seeds); // JFA+1
    std::swap(nearest, scratch);
    return nearest;
}

// The band: for every texel whose centre lies within `withinKm` of some seed, the exact nearest seed
// and the exact nearest seed on another curtain (if that one is within withinKm too); `none` elsewhere.
// Each seed visits the texels of a box around its own that holds every texel centre within withinKm of it
// (footprintBandBoxTexels). Seeds go in increasing order and
// only a strictly larger dot product wins, so ties go to the smaller seed number, as in jumpFloodPass.
struct Band {
    std::vector<int> first, second;
    std::vector<int> slot;             // index into `direction` of a texel a seed's box reached, else −1
    std::vector<glm::dvec3> direction; // those texels' centre directions
};

Band exactBand(const Seeds& seeds, const FootprintMap& map, double withinKm)
{
    const int n = map.spec.size;
    const int none = seeds.none();
    const size_t texels = static_cast<size_t>(n) * n;
    Band band{std::vector<int>(texels, none), std::vector<int>(texels, none), std::vector<int>(texels, -1), {}};
    const double R = map.planetRadiusKm;
    const double within = withinKm / R;
    const double cosWithin = std::cos(std::min(within, aurorawall::physics::kPi));
    const int box = footprintBandBoxTexels(map, withinKm);
    for (int s = 0; s < none; ++s) {
        const glm::dvec3& seed = seeds.direction[s];
        const glm::dvec2 texel =
            f64::footprintMapTexel(f64::footprintMapCoord(seed, map.centre, map.east, map.angularRadius), n);
        for (int j = std::max(int(texel.y) - box, 0); j <= std::min(int(texel.y) + box, n - 1); ++j)
            for (int i = std::max(int(texel.x) - box, 0); i <= std::min(int(texel.x) + box, n - 1); ++i) {
                const size_t t = static_cast<size_t>(j) * n + i;
                if (band.slot[t] < 0) {
                    band.slot[t] = static_cast<int>(band.direction.size());
                    band.direction.push_back(footprintTexelDirection(map, i, j));
                }
                const glm::dvec3& here = band.direction[static_cast<size_t>(band.slot[t])];
                const double d = glm::dot(here, seed);
                if (d < cosWithin)
                    continue;
                int& first = band.first[t];
                int& second = band.second[t];
                if (first == none || d > glm::dot(here, seeds.direction[first])) {
                    // The old first, if on another curtain than s, is the nearest seed off s's curtain;
                    // otherwise the old second is (it is off the old first's curtain, which is s's).
                    if (first != none && seeds.curtain[first] != seeds.curtain[s])
                        second = first;
                    first = s;
                } else if (seeds.curtain[s] != seeds.curtain[first] &&
                           (second == none || d > glm::dot(here, seeds.direction[second]))) {
                    second = s;
                }
            }
    }
    return band;
}

} // namespace

glm::dvec3 footprintTexelDirection(const FootprintMap& map, int i, int j)
{
    const double n = map.spec.size;
    return f64::footprintMapDirection(glm::dvec2((i + 0.5) / n, (j + 0.5) / n), map.centre, map.east,
                                      map.angularRadius);
}

FootprintMap footprintMapFrame(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm)
{
    const int n = spec.size;
    if (n < 2 || n > 8192 || (n & (n - 1)) != 0)
        throw std::invalid_argument("buildFootprintMap: size must be a power of two in [2, 8192]");
    if (!(spec.angularRadiusDeg > 0.0 && spec.angularRadiusDeg <= 90.0))
        throw std::invalid_argument("buildFootprintMap: angular radius must be in (0, 90] degrees");
    if (!(spec.reachKm >= 0.0 && spec.reachKm <= 10000.0))
        throw std::invalid_argument("buildFootprintMap: reach must be in [0, 10000] km");
    if (!(planetRadiusKm > 0.0))
        throw std::invalid_argument("buildFootprintMap: planet radius must be positive");
    if (curtains.size() >= static_cast<size_t>(kMaxExactInteger / kSecondPointStride))
        throw std::invalid_argument("buildFootprintMap: too many curtains");

    FootprintMap map;
    map.spec = spec;
    map.planetRadiusKm = planetRadiusKm;
    map.centre = common::unitFromLatLon(spec.centreLatitudeDeg, spec.centreLongitudeDeg);
    // East = ∂P/∂λ / cos φ = (sin λ, −cos λ, 0) for P = unitFromLatLon(φ, λ); defined at the poles too.
    const double lon = spec.centreLongitudeDeg * aurorawall::physics::kPi / 180.0;
    map.east = glm::dvec3(std::sin(lon), -std::cos(lon), 0.0);
    map.angularRadius = spec.angularRadiusDeg * aurorawall::physics::kPi / 180.0;

    double longestArc = 0.0; // radians between consecutive points of a curtain
    for (size_t c = 0; c < curtains.size(); ++c) {
        const std::vector<glm::dvec3>& points = curtains[c].points;
        if (points.size() >= static_cast<size_t>(kSecondPointStride))
            throw std::invalid_argument("buildFootprintMap: too many points in a curtain");
        for (size_t k = 0; k < points.size(); ++k) {
            if (f64::angleBetween(points[k], map.centre) > map.angularRadius)
                throw std::invalid_argument("buildFootprintMap: curtain " + std::to_string(c) + " point " +
                                            std::to_string(k) + " lies outside the map's cap");
            if (k > 0)
                longestArc = std::max(longestArc, f64::angleBetween(points[k - 1], points[k]));
            ++map.seedCount;
        }
    }
    const double R = planetRadiusKm;
    const double h = 2.0 * map.angularRadius / n;
    map.marginKm = R * (h * std::sqrt(0.5) + 0.5 * longestArc + 2.0 * map.angularRadius * 1e-6);
    if (map.seedCount > 0)
        map.exactWithinKm = spec.reachKm + map.marginKm + R * h;
    return map;
}

int footprintBandBoxTexels(const FootprintMap& map, double withinKm)
{
    const int n = map.spec.size;
    const double within = withinKm / map.planetRadiusKm;
    const double thetaMax = map.angularRadius + within;
    const double stretch = thetaMax < 3.0 ? thetaMax / std::sin(thetaMax) : 1e30;
    return static_cast<int>(
        std::min(std::ceil(within * stretch / (2.0 * map.angularRadius) * n) + 1.0, static_cast<double>(n)));
}

int footprintCoarseMapSize(const FootprintMap& map) { return std::min(map.spec.size, kCoarseMapSize); }

double footprintCoarseSlackKm(const FootprintMap& map)
{
    const int k = map.spec.size / footprintCoarseMapSize(map);
    const double h = 2.0 * map.angularRadius / map.spec.size;
    return map.planetRadiusKm * h * (k * kJfaErrorTexels + (k - 1) * std::sqrt(0.5));
}

FootprintMap buildFootprintMap(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm)
{
    FootprintMap map = footprintMapFrame(curtains, spec, planetRadiusKm);
    const int n = spec.size;
    const double R = planetRadiusKm;

    Seeds seeds;
    for (size_t c = 0; c < curtains.size(); ++c)
        for (size_t k = 0; k < curtains[c].points.size(); ++k) {
            seeds.direction.push_back(curtains[c].points[k]);
            seeds.curtain.push_back(static_cast<int>(c));
            seeds.point.push_back(static_cast<int>(k));
        }
    const int none = static_cast<int>(seeds.direction.size());
    seeds.direction.push_back(glm::dvec3(std::numeric_limits<double>::quiet_NaN()));

    map.texels.assign(static_cast<size_t>(n) * n * 4, 0.0f);
    if (none == 0) {
        for (size_t t = 0; t < map.texels.size(); t += 4) {
            map.texels[t] = map.texels[t + 1] = map.texels[t + 3] = -1.0f;
            map.texels[t + 2] = roundedDown(footprintNoCurtainKm(map));
        }
        return map;
    }

    // Near the curtains (where the shader reads the stored point): exact.
    const Band band = exactBand(seeds, map, map.exactWithinKm);

    // Elsewhere only a lower bound of the distance matters (for skipping): a coarse jump-flooded map
    // gives the distance from each coarse texel centre c to a seed, at most kJfaErrorTexels coarse texels
    // more than the nearest; a fine texel centre p in that coarse texel is within R·h·(k − 1)/√2 of c, so
    // distance(p) ≥ distance(c) − that. Every seed is also farther than exactWithinKm from p (p is not in the band).
    const int coarse = footprintCoarseMapSize(map);
    const int k = n / coarse;
    FootprintMap coarseFrame = map;
    coarseFrame.spec.size = coarse;
    const std::vector<glm::dvec3> coarseDirection = texelDirections(coarseFrame);
    const std::vector<int> coarseNearest = jumpFlood(seeds, coarseDirection, coarseFrame);
    const double slackKm = footprintCoarseSlackKm(map);
    std::vector<float> coarseBound(coarseNearest.size());
    for (size_t t = 0; t < coarseNearest.size(); ++t)
        coarseBound[t] = roundedDown(std::max(
            map.exactWithinKm, R * f64::angleBetween(coarseDirection[t], seeds.direction[coarseNearest[t]]) - slackKm));

    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const size_t t = static_cast<size_t>(j) * n + i;
            float* texel = &map.texels[4 * t];
            const int s = band.first[t];
            if (s != none) {
                texel[0] = static_cast<float>(seeds.curtain[s]);
                texel[1] = static_cast<float>(seeds.point[s]);
                texel[2] = roundedDown(
                    R * f64::angleBetween(band.direction[static_cast<size_t>(band.slot[t])], seeds.direction[s]));
                const int s2 = band.second[t];
                texel[3] = s2 == none ? -1.0f
                                      : static_cast<float>(seeds.curtain[s2] * kSecondPointStride + seeds.point[s2]);
            } else {
                const size_t c = static_cast<size_t>(j / k) * coarse + i / k;
                texel[0] = static_cast<float>(seeds.curtain[coarseNearest[c]]);
                texel[1] = static_cast<float>(seeds.point[coarseNearest[c]]);
                texel[2] = coarseBound[c];
                texel[3] = -1.0f;
            }
        }
    return map;
}

FootprintSample FootprintMap::lookup(const glm::dvec3& unitDir) const
{
    FootprintSample out;
    const double outsideKm = f64::footprintMapOutsideKm(unitDir, centre, angularRadius, planetRadiusKm);
    if (outsideKm > 0.0) {
        out.distanceKm = out.conservativeKm = outsideKm;
        return out;
    }
    const glm::dvec2 texel =
        f64::footprintMapTexel(f64::footprintMapCoord(unitDir, centre, east, angularRadius), spec.size);
    const float* value = &texels[4 * (static_cast<size_t>(texel.y) * spec.size + static_cast<size_t>(texel.x))];
    out.curtainId = static_cast<int>(value[0]);
    out.pointIndex = static_cast<int>(value[1]);
    out.distanceKm = value[2];
    out.conservativeKm = f64::footprintConservativeKm(value[2], marginKm);
    return out;
}

} // namespace aurorawall::components::aurora::physics
