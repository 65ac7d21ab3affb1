#include "aurora/footprint_map.h"

#include "common/glsl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::aurora {
namespace {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "aurora/footprint_map.glsl"
} // namespace f64

constexpr double kPi = 3.14159265358979323846;
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
};

// One jump flooding pass with offset `step` (Rong & Tan 2006, §3): texel t takes, among its own seed and
// the seeds of the 8 texels t + step·(±1 or 0, ±1 or 0), the one whose direction has the largest dot product
// with t's centre direction; equal dot products go to the smaller seed number.
void jumpFloodPass(const std::vector<int>& src, std::vector<int>& dst, int n, int step,
                   const std::vector<glm::dvec3>& texelDirection, const Seeds& seeds)
{
    const int none = static_cast<int>(seeds.direction.size()) - 1;
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

// The same pass for the second map: texel t takes the seed nearest to it among those NOT on the
// curtain of its nearest seed first[t], from the candidates its 9 texels hold in either map (a
// neighbour's nearest may well be t's second). JFA's approximation applies as for the first map.
void jumpFloodSecondPass(const std::vector<int>& first, const std::vector<int>& src, std::vector<int>& dst, int n,
                         int step, const std::vector<glm::dvec3>& texelDirection, const Seeds& seeds,
                         const std::vector<char>& wanted)
{
    const int none = static_cast<int>(seeds.direction.size()) - 1;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int t = j * n + i;
            if (!wanted[t]) {
                dst[t] = none;
                continue;
            }
            const glm::dvec3 here = texelDirection[t];
            const int excluded = first[t] == none ? -1 : seeds.curtain[first[t]];
            int best = src[t];
            double bestDot = best == none ? -2.0 : glm::dot(here, seeds.direction[best]);
            auto consider = [&](int s) {
                if (s == none || seeds.curtain[s] == excluded)
                    return;
                const double d = glm::dot(here, seeds.direction[s]);
                const bool better = (d > bestDot) | ((d == bestDot) & (s < best));
                best = better ? s : best;
                bestDot = better ? d : bestDot;
            };
            for (int jj = j - step; jj <= j + step; jj += step)
                for (int ii = i - step; ii <= i + step; ii += step)
                    if (ii >= 0 && ii < n && jj >= 0 && jj < n) {
                        consider(first[jj * n + ii]);
                        consider(src[jj * n + ii]);
                    }
            dst[t] = best;
        }
    }
}

} // namespace

glm::dvec3 footprintTexelDirection(const FootprintMap& map, int i, int j)
{
    const double n = map.spec.size;
    return f64::footprintMapDirection(glm::dvec2((i + 0.5) / n, (j + 0.5) / n), map.centre, map.east,
                                      map.angularRadius);
}

FootprintMap buildFootprintMap(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec,
                               double planetRadiusKm)
{
    const int n = spec.size;
    if (n < 2 || n > 8192 || (n & (n - 1)) != 0)
        throw std::invalid_argument("buildFootprintMap: size must be a power of two in [2, 8192]");
    if (!(spec.angularRadiusDeg > 0.0 && spec.angularRadiusDeg <= 90.0))
        throw std::invalid_argument("buildFootprintMap: angular radius must be in (0, 90] degrees");
    if (!(planetRadiusKm > 0.0))
        throw std::invalid_argument("buildFootprintMap: planet radius must be positive");
    if (curtains.size() >= static_cast<size_t>(kMaxExactInteger / kSecondPointStride))
        throw std::invalid_argument("buildFootprintMap: too many curtains");

    FootprintMap map;
    map.spec = spec;
    map.planetRadiusKm = planetRadiusKm;
    map.centre = unitFromLatLon(spec.centreLatitudeDeg, spec.centreLongitudeDeg);
    // East = ∂P/∂λ / cos φ = (sin λ, −cos λ, 0) for P = unitFromLatLon(φ, λ); defined at the poles too.
    const double lon = spec.centreLongitudeDeg * kPi / 180.0;
    map.east = glm::dvec3(std::sin(lon), -std::cos(lon), 0.0);
    map.angularRadius = spec.angularRadiusDeg * kPi / 180.0;

    std::vector<glm::dvec3> texelDirection(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            texelDirection[j * n + i] = footprintTexelDirection(map, i, j);

    // Seeds, each offered to the 3×3 texels around its own.
    Seeds seeds;
    double longestArc = 0.0; // radians between consecutive points of a curtain
    for (size_t c = 0; c < curtains.size(); ++c) {
        const std::vector<glm::dvec3>& points = curtains[c].points;
        if (points.size() >= static_cast<size_t>(kSecondPointStride))
            throw std::invalid_argument("buildFootprintMap: too many points in a curtain");
        for (size_t k = 0; k < points.size(); ++k) {
            if (f64::footprintAngle(points[k], map.centre) > map.angularRadius)
                throw std::invalid_argument("buildFootprintMap: curtain " + std::to_string(c) + " point " +
                                            std::to_string(k) + " lies outside the map's cap");
            if (k > 0)
                longestArc = std::max(longestArc, f64::footprintAngle(points[k - 1], points[k]));
            seeds.direction.push_back(points[k]);
            seeds.curtain.push_back(static_cast<int>(c));
            seeds.point.push_back(static_cast<int>(k));
        }
    }
    const int none = static_cast<int>(seeds.direction.size());
    seeds.direction.push_back(glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
    std::vector<int> nearest(static_cast<size_t>(n) * n, none), scratch(nearest.size());
    for (int s = 0; s < none; ++s) {
        const glm::dvec2 texel = f64::footprintMapTexel(
            f64::footprintMapCoord(seeds.direction[s], map.centre, map.east, map.angularRadius), n);
        for (int j = int(texel.y) - 1; j <= int(texel.y) + 1; ++j) {
            for (int i = int(texel.x) - 1; i <= int(texel.x) + 1; ++i) {
                if (i < 0 || i >= n || j < 0 || j >= n)
                    continue;
                const int t = j * n + i;
                const int best = nearest[t];
                const double d = glm::dot(texelDirection[t], seeds.direction[s]);
                // Seeds come in increasing order, so an equal dot product keeps the earlier (smaller) seed.
                if (best == none || d > glm::dot(texelDirection[t], seeds.direction[best]))
                    nearest[t] = s;
            }
        }
    }
    if (none > 0) {
        for (int step = n / 2; step >= 1; step /= 2) {
            jumpFloodPass(nearest, scratch, n, step, texelDirection, seeds);
            std::swap(nearest, scratch);
        }
        jumpFloodPass(nearest, scratch, n, 1, texelDirection, seeds); // JFA+1
        std::swap(nearest, scratch);
    }
    // The nearest seed of another curtain, where curtains come close (overlapping curtains both emit).
    const double h = 2.0 * map.angularRadius / n;
    map.marginKm = planetRadiusKm * (h * (std::sqrt(0.5) + kJfaErrorTexels) + 0.5 * longestArc + 2.0 * map.angularRadius * 1e-6);
    // Only where the stored nearest distance is within secondCurtainWithinKm plus the margin (where
    // the shader looks at curtains at all), with jumps up to that far.
    std::vector<int> second(nearest.size(), none);
    if (curtains.size() > 1) {
        const double texelKm = planetRadiusKm * h;
        const double withinKm = spec.secondCurtainWithinKm + map.marginKm + texelKm;
        const double cosWithin = std::cos(std::min(withinKm / planetRadiusKm, kPi));
        std::vector<char> wanted(nearest.size());
        for (size_t t = 0; t < nearest.size(); ++t)
            wanted[t] = nearest[t] != none && glm::dot(texelDirection[t], seeds.direction[nearest[t]]) >= cosWithin;
        int firstStep = 1;
        while (firstStep < n / 2 && firstStep * texelKm < withinKm)
            firstStep *= 2;
        for (int step = firstStep; step >= 1; step /= 2) {
            jumpFloodSecondPass(nearest, second, scratch, n, step, texelDirection, seeds, wanted);
            std::swap(second, scratch);
        }
        jumpFloodSecondPass(nearest, second, scratch, n, 1, texelDirection, seeds, wanted);
        std::swap(second, scratch);
        // A second curtain farther than that cannot emit here: keep the shader from evaluating it.
        for (size_t t = 0; t < second.size(); ++t)
            if (second[t] != none && glm::dot(texelDirection[t], seeds.direction[second[t]]) < cosWithin)
                second[t] = none;
    }

    const double R = planetRadiusKm;
    map.texels.assign(static_cast<size_t>(n) * n * 4, 0.0f);
    for (int t = 0; t < n * n; ++t) {
        float* texel = &map.texels[4 * static_cast<size_t>(t)];
        const int s = nearest[t];
        if (s == none) {
            texel[0] = texel[1] = -1.0f;
            texel[2] = roundedDown(kPi * R);
        } else {
            texel[0] = static_cast<float>(seeds.curtain[s]);
            texel[1] = static_cast<float>(seeds.point[s]);
            texel[2] = roundedDown(R * f64::footprintAngle(texelDirection[t], seeds.direction[s]));
        }
        const int s2 = second[t];
        texel[3] = s2 == none ? -1.0f : static_cast<float>(seeds.curtain[s2] * kSecondPointStride + seeds.point[s2]);
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

double FootprintMap::conservativeDistanceKm(const glm::dvec3& unitDir) const
{
    return lookup(unitDir).conservativeKm;
}

} // namespace aurorawall::aurora
