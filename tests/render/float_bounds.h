#pragma once
// What float arithmetic allows a render against the double-precision CPU reference, from the unit
// roundoff and the problem's own condition, not from any device's output.
//
// u = 2^-24. GLSL 4.60 (§4.7.1) allows: +, −, × and conversions correctly rounded (u relative); a
// division 2.5 ULP (5u); exp and exp2 3 + 2|x| ULP ((6 + 4|x|)u); inversesqrt 2 ULP (4u); sqrt as
// 1/inversesqrt (9u); log and log2 3 ULP (6u) away from 1. One ULP is at most 2u. GLSL gives the
// trigonometric built-ins no precision; the bounds take Vulkan's: atan and asin 4096 ULP.
#include "accuracy/scene_view.h"
#include "render/reference_ray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace aurorawall::test {

inline const double kUnitRoundoff = std::ldexp(1.0, -24);

// GLSL's atan and asin, relative (Vulkan's 4096 ULP).
inline const double kGlslInverseTrigError = 8192.0 * kUnitRoundoff;

// GLSL's exp of an argument of magnitude up to |x|, relative.
inline double glslExpError(double x) { return (6.0 + 4.0 * std::abs(x)) * kUnitRoundoff; }

// The closed-form airmass's own error (shaders/physics/atmosphere/airmass_chapman.glsl), relative, for scale
// height H on a sphere of radius r: the erfcx fit's 1.0e-6, the J₂ fit's 0.1% of the correction term
// (at most 3/(8x), x = r/H) and the neglected O(1/x²) term, 7e-6 at x = 127. (Its safe form, the
// trapezoid rule, is taken only on segments whose height varies by less than 0.08 H; each caller
// says why those do not matter to it.)
inline double closedFormAirmassError(double H, double r)
{
    const double x = r / H;
    return 1.0e-6 + 1e-3 * 3.0 / (8.0 * x) + 7e-6 * (127.0 / x) * (127.0 / x);
}

// The float error of one exponential column (airmassChapmanAsymptotic), relative: each end's
// density e^-w, w = h/H up to `scaleHeights`, from a height of float's relative precision (2u·w) and
// GLSL's exp ((6 + 4w)u), and the Chapman function's some 40 operations, whose polynomials' terms
// add to at most twice their value (100u).
inline double floatAirmassError(double scaleHeights)
{
    return 2.0 * scaleHeights * kUnitRoundoff + glslExpError(scaleHeights) + 100.0 * kUnitRoundoff;
}

// Each pixel's relative error against its own bound.
struct BoundedError {
    size_t pixels = 0;
    double rms = 0.0, max = 0.0; // the error, relative
    double rmsBound = 0.0;       // the bound's RMS, relative
    double worstRatio = 0.0;     // the largest error / bound (infinite after a non-finite error)
    bool finite = true;
    void add(double error, double bound)
    {
        ++pixels;
        if (!std::isfinite(error)) {
            finite = false;
            worstRatio = INFINITY;
            return;
        }
        squares_ += error * error;
        boundSquares_ += bound * bound;
        max = std::max(max, error);
        worstRatio = std::max(worstRatio, error / bound);
        rms = std::sqrt(squares_ / double(pixels));
        rmsBound = std::sqrt(boundSquares_ / double(pixels));
    }

private:
    double squares_ = 0.0, boundSquares_ = 0.0;
};

// How far the rounding of pixel (x, y)'s ray to float can move the reference's radiance there
// (absolute, the Euclidean norm of linear RGB), to first order. The GPU gets the camera position
// rounded to float, each coordinate by up to u of itself, and forms the direction as
// normalize(origin + x·right + y·down) from the three float uniforms (shaders/render/tile_rays.glsl):
// with S the sum of the three terms' lengths over the result's, the uniforms' rounding, the two
// products and the two sums each turn it by at most S·u, the normalization by 3u: an angle of at
// most (5S + 3)·u. The change is the reference's own derivative along each of the three axes of the
// camera position and the two directions across the ray (central differences at the rounding's
// size) times that rounding.
inline double rayRoundingBound(const render::ReferenceModel& model, const accuracy::SceneView& view, int x, int y)
{
    const double u = kUnitRoundoff;
    const wall::TileRays& r = view.rays;
    const glm::dvec2 canvas = glm::dvec2(r.pixelOffset) + glm::dvec2(x + 0.5, y + 0.5);
    const glm::dvec3 wallDirection = r.originDir + canvas.x * r.stepRight + canvas.y * r.stepDown;
    const double terms = (glm::length(r.originDir) + canvas.x * glm::length(r.stepRight) +
                          canvas.y * glm::length(r.stepDown)) / glm::length(wallDirection);
    const double angle = (5.0 * terms + 3.0) * u;
    const glm::dvec3 o = view.frame.cameraPositionKm, d = accuracy::pixelDirection(view, x, y);
    const auto change = [&](glm::dvec3 originShift, glm::dvec3 directionShift) {
        return 0.5 * glm::length(model.radiance(o + originShift, d + directionShift) -
                                 model.radiance(o - originShift, d - directionShift));
    };
    const glm::dvec3 axis = std::abs(d.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 across = glm::normalize(glm::cross(d, axis));
    const glm::dvec3 other = glm::cross(d, across);
    double bound = change(glm::dvec3(0.0), angle * across) + change(glm::dvec3(0.0), angle * other);
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 shift(0.0);
        shift[a] = u * std::abs(o[a]);
        bound += change(shift, glm::dvec3(0.0));
    }
    return bound;
}

} // namespace aurorawall::test
