#include "physics/atmosphere/airmass_accuracy.h"

#include "physics/atmosphere/airmass_exact.h"
#include "physics/constants.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace aurorawall::physics::atmosphere {
namespace {

constexpr double kPlanetRadius = 6371.0;
constexpr double kTopAltitude = 1000.0; // segments leaving the atmosphere end at this altitude

// A local frame away from the coordinate axes, so that float rounding is as in general use.
const glm::dvec3 kUp = glm::normalize(glm::dvec3(0.3, -0.5, 0.81));
const glm::dvec3 kHorizontal = glm::normalize(glm::cross(kUp, glm::dvec3(0.0, 0.0, 1.0)));

double radians(double degrees) { return degrees * physics::kPi / 180.0; }

// Ray parameter where the ray leaves the sphere of the given radius (origin inside or the far side).
double farCrossing(glm::dvec3 origin, glm::dvec3 d, double radius)
{
    double b = glm::dot(origin, d);
    double c = glm::dot(origin, origin) - radius * radius;
    return -b + std::sqrt(std::max(b * b - c, 0.0));
}

// Ray parameter of the first ground hit ahead, or +inf.
double groundHit(glm::dvec3 origin, glm::dvec3 d)
{
    double b = glm::dot(origin, d);
    double c = glm::dot(origin, origin) - kPlanetRadius * kPlanetRadius;
    double discriminant = b * b - c;
    if (discriminant < 0.0 || b > 0.0) return std::numeric_limits<double>::infinity();
    double t = c / (-b + std::sqrt(discriminant)); // near root, stable form
    return t > 0.0 ? t : std::numeric_limits<double>::infinity();
}

void addRay(std::vector<AirmassRay>& rays, glm::dvec3 origin, glm::dvec3 d, double t1, double H)
{
    if (!(t1 > 0.0)) return;
    rays.push_back(roundedToFloat({origin, d, 0.0, t1, H, kPlanetRadius}));
}

} // namespace

std::vector<AirmassRay> airmassAccuracyRays()
{
    std::vector<AirmassRay> rays;
    for (double H : {1.0, 2.0, 4.0, 8.0, 16.0, 25.0, 50.0}) {
        // Ground observers: to the ground if the ray hits it, else to the top.
        for (double altitude : {0.0, 0.001, 0.1, 1.0, 3.0, 10.0}) {
            for (double elevation : {-1.0, -0.5, -0.2, -0.05, 0.0, 0.05, 0.2, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0,
                                     20.0, 30.0, 45.0, 60.0, 75.0, 85.0, 90.0}) {
                glm::dvec3 origin = (kPlanetRadius + altitude) * kUp;
                glm::dvec3 d = std::cos(radians(elevation)) * kHorizontal + std::sin(radians(elevation)) * kUp;
                double t1 = std::min(groundHit(origin, d), farCrossing(origin, d, kPlanetRadius + kTopAltitude));
                addRay(rays, origin, d, t1, H);
            }
        }
        // Limb rays from orbit, from the observer through the tangent point to the top on the far side.
        for (double orbit : {400.0, 800.0, 35786.0}) {
            glm::dvec3 origin = (kPlanetRadius + orbit) * kUp;
            for (double tangentHeight : {0.1, 0.3, 1.0, 3.0, 10.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0}) {
                double beta = std::asin((kPlanetRadius + tangentHeight) / (kPlanetRadius + orbit));
                glm::dvec3 d = -std::cos(beta) * kUp + std::sin(beta) * kHorizontal;
                addRay(rays, origin, d, farCrossing(origin, d, kPlanetRadius + kTopAltitude), H);
            }
            // Down to 1 m (along the ray) above the ground, from nadir to just inside the horizon.
            double horizon = std::asin(kPlanetRadius / (kPlanetRadius + orbit));
            for (double fraction : {0.0, 0.3, 0.6, 0.9, 0.99, 0.999}) {
                double beta = fraction * horizon;
                glm::dvec3 d = -std::cos(beta) * kUp + std::sin(beta) * kHorizontal;
                addRay(rays, origin, d, groundHit(origin, d) - 0.001, H);
            }
        }
        // Segments inside the atmosphere, clipped at the ground.
        for (double altitude : {0.5, 5.0, 20.0, 60.0}) {
            for (double elevation : {-30.0, -5.0, -1.0, 0.0, 1.0, 5.0, 30.0, 90.0}) {
                glm::dvec3 origin = (kPlanetRadius + altitude) * kUp;
                glm::dvec3 d = std::cos(radians(elevation)) * kHorizontal + std::sin(radians(elevation)) * kUp;
                for (double length : {0.001, 0.01, 0.1, 1.0, 10.0, 100.0, 1000.0, 3000.0}) {
                    addRay(rays, origin, d, std::min(length, groundHit(origin, d)), H);
                }
            }
        }
    }
    return rays;
}

double airmassNanosecondsPerEvaluation(const AirmassMethod& method, AirmassPrecision precision,
                                       const std::vector<AirmassRay>& rays)
{
    if (rays.empty()) return 0.0;
    const int repetitions = method.float32 ? 100 : 1;
    volatile double sink = 0.0;
    auto start = std::chrono::steady_clock::now();
    for (int repetition = 0; repetition < repetitions; ++repetition) {
        double sum = 0.0;
        for (const AirmassRay& ray : rays) sum += evaluateAirmass(method, ray, precision);
        sink = sink + sum;
    }
    std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
    return elapsed.count() / (double(repetitions) * double(rays.size()));
}

RelativeErrors relativeErrors(const std::vector<double>& values, const std::vector<double>& exact, double floor)
{
    RelativeErrors errors;
    double sumSquares = 0.0;
    for (size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            ++errors.nonFiniteCount;
            continue;
        }
        double error = std::abs(values[i] - exact[i]) / std::max(std::abs(exact[i]), floor);
        sumSquares += error * error;
        if (error >= errors.maxRelativeError) {
            errors.maxRelativeError = error;
            errors.worstIndex = i;
        }
    }
    size_t finiteCount = values.size() - errors.nonFiniteCount;
    errors.rmsRelativeError = finiteCount == 0 ? 0.0 : std::sqrt(sumSquares / double(finiteCount));
    return errors;
}

std::vector<MethodAccuracy> measureAirmassAccuracy(const std::vector<AirmassRay>& rays, bool measureTime)
{
    std::vector<double> exact;
    exact.reserve(rays.size());
    for (const AirmassRay& ray : rays) exact.push_back(exactAirmass(ray));

    std::vector<MethodAccuracy> rows;
    for (const AirmassMethod& method : airmassMethods()) {
        for (AirmassPrecision precision : {AirmassPrecision::Float32, AirmassPrecision::Float64}) {
            if (!method.float32 && precision == AirmassPrecision::Float32) continue;
            std::vector<double> values;
            values.reserve(rays.size());
            for (const AirmassRay& ray : rays) values.push_back(evaluateAirmass(method, ray, precision));
            RelativeErrors errors = relativeErrors(values, exact, kAirmassRelativeErrorFloor);
            MethodAccuracy row;
            row.method = method.name;
            row.precision = precision;
            row.rayCount = rays.size();
            row.nonFiniteCount = errors.nonFiniteCount;
            row.maxRelativeError = errors.maxRelativeError;
            row.rmsRelativeError = errors.rmsRelativeError;
            row.worstRay = rays[errors.worstIndex];
            row.worstValue = values[errors.worstIndex];
            row.worstExact = exact[errors.worstIndex];
            if (measureTime) row.nanosecondsPerEvaluation = airmassNanosecondsPerEvaluation(method, precision, rays);
            rows.push_back(row);
        }
    }
    return rows;
}

std::string formatAirmassAccuracyTable(const std::vector<MethodAccuracy>& rows)
{
    std::string table = "method               prec   rays   nonfinite max_rel    rms_rel    ns/eval  worst ray: altitude_km "
                        "cos_zenith t0 t1 H -> value exact\n";
    for (const MethodAccuracy& row : rows) {
        const AirmassRay& ray = row.worstRay;
        double distance = glm::length(ray.origin);
        double cosZenith = distance > 0.0 ? glm::dot(ray.origin / distance, glm::normalize(ray.direction)) : 0.0;
        char line[512];
        std::snprintf(line, sizeof line, "%-20s %-6s %-6zu %-9zu %-10.3g %-10.3g %-8.1f %.6g %.6f %.6g %.6g %g -> %.9g %.9g\n",
                      row.method.c_str(), row.precision == AirmassPrecision::Float32 ? "f32" : "f64", row.rayCount,
                      row.nonFiniteCount, row.maxRelativeError, row.rmsRelativeError, row.nanosecondsPerEvaluation,
                      distance - ray.planetRadius, cosZenith, ray.t0, ray.t1, ray.scaleHeight, row.worstValue,
                      row.worstExact);
        table += line;
    }
    return table;
}

} // namespace aurorawall::physics::atmosphere
