#pragma once
// Accuracy sweep of the airmass methods against the exact reference (docs/airmass.md).
#include "physics/atmosphere/airmass.h"

#include <string>
#include <vector>

namespace aurorawall::physics::atmosphere {

// Relative error |I − I_exact| / max(|I_exact|, floor): below 1e-30 km (where float results are
// denormal or zero) errors count as absolute, so float underflow of a negligible airmass is no error.
inline constexpr double kAirmassRelativeErrorFloor = 1e-30;

// Max and RMS of |value − exact| / max(|exact|, floor) over a set of results; non-finite values are
// counted and left out.
struct RelativeErrors {
    size_t nonFiniteCount = 0;
    double maxRelativeError = 0.0;
    double rmsRelativeError = 0.0;
    size_t worstIndex = 0;
};
RelativeErrors relativeErrors(const std::vector<double>& values, const std::vector<double>& exact, double floor);

struct MethodAccuracy {
    std::string method;
    AirmassPrecision precision = AirmassPrecision::Float32;
    size_t rayCount = 0;
    size_t nonFiniteCount = 0;       // NaN or infinite results (left out of the errors below)
    double maxRelativeError = 0.0;
    double rmsRelativeError = 0.0;
    AirmassRay worstRay;
    double worstValue = 0.0;
    double worstExact = 0.0;
    double nanosecondsPerEvaluation = 0.0; // 0 when not timed
};

// The sweep's rays (docs/airmass.md lists them), already rounded to float so that every precision
// sees the same input: ground observers at 0–10 km from −1° to 90° elevation (0° included), limb rays
// from 400 km, 800 km and 35786 km with tangent heights 0.1–120 km, rays from space to 1 m above the
// ground, segments inside the atmosphere from 1 m to 3000 km; each for H = 1, 2, 4, 8, 16, 25, 50 km.
std::vector<AirmassRay> airmassAccuracyRays();

// Max and RMS relative error and the worst ray of every method (float32 and float64 rows; `exact`
// only as float64, against itself), optionally with the CPU time per evaluation.
std::vector<MethodAccuracy> measureAirmassAccuracy(const std::vector<AirmassRay>& rays, bool measureTime);

// CPU nanoseconds per evaluation of the method over the rays (a benchmark, not a test).
double airmassNanosecondsPerEvaluation(const AirmassMethod& method, AirmassPrecision precision,
                                       const std::vector<AirmassRay>& rays);

// A plain-text table, one row per method and precision.
std::string formatAirmassAccuracyTable(const std::vector<MethodAccuracy>& rows);

} // namespace aurorawall::physics::atmosphere
