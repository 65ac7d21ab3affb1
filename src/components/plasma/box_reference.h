#pragma once
// The plasma box in the double-precision CPU reference: the same frames (box_frames.h, through the
// table cache), the same lookup and time interpolation as shaders/components/plasma/plasma_box*.glsl,
// the same slab segment (plasma_box_march.glsl compiled in double), and the column of n/n₀ along the
// ray integrated exactly instead of by the shader's midpoint march.
#include "components/plasma/box_frames.h"
#include "components/plasma/plasma.h"
#include "scene/component.h"

#include <glm/glm.hpp>

#include <memory>

namespace aurorawall::components::plasma {

// n/n₀ of the box at one frame position, as the shader's lookup: each frame trilinear between the
// cell centres, periodic across the field (x, y), held at the first and last centres along z;
// linear in time between frames floor(p) and min(floor(p) + 1, frames − 1).
class BoxDensity {
public:
    BoxDensity(BoxFrames frames, double framePosition);

    // unit: the point in the box's coordinates scaled to [0, 1].
    double at(glm::dvec3 unit) const;

    // ∫ n/n₀ dt (km) over [segment.x, segment.y] of o + t d (box frame centred at 0, km, |d| = 1,
    // inside the cube of this side). Exact up to rounding: the chord is cut where it crosses a plane
    // of cell centres on any axis; between two cuts the density is a product of three functions
    // linear in t (or constant along z beyond the outer centres), a cubic, which the two-point
    // Gauss–Legendre rule integrates exactly (Abramowitz & Stegun 1964, 25.4.29).
    double exactColumn(glm::dvec3 o, glm::dvec3 d, glm::dvec2 segment, double side) const;

    // The shader's march (plasma_box_march.glsl, midpoint rule of `steps` steps) in double.
    double marchedColumn(glm::dvec3 o, glm::dvec3 d, glm::dvec2 segment, int steps, double side) const;

private:
    double frameAt(int frame, glm::dvec3 unit) const;

    BoxFrames frames_;
    int frame0_ = 0, frame1_ = 0;
    double weight1_ = 0.0; // of frame1_
};

// The slab segment of o + t d through the cube of half side h (plasma_box_march.glsl in double).
glm::dvec2 boxSegment(glm::dvec3 o, glm::dvec3 d, double halfSide);

// The box's part of the reference at clock time t: its emission, box_rayleigh_per_km in the green
// line's colour per km at n = n₀, along each ray's chord through the box up to the ray's end, seen
// through the lower atmosphere's transmittance. Frames: cachedBoxFrames in the default cache.
std::unique_ptr<scene::ReferenceShader> makeBoxReference(const Settings& plasma, double planetRadiusKm, double timeS);

} // namespace aurorawall::components::plasma
