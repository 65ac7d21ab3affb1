#include "components/plasma/box_reference.h"

#include "common/glsl.h"
#include "physics/colour.h"
#include "physics/emission_lines.h"
#include "io/table_cache.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace aurorawall::components::plasma {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
using namespace aurorawall::scene::f64; // the ray and its steps
// The shader's march text over a BoxDensity (its plasmaBoxDensity).
struct March {
    const BoxDensity* density;
    real plasmaBoxDensity(vec3 unit) const { return density->at(unit); }
#include "components/plasma/plasma_box_march.glsl"
};
} // namespace f64

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

class BoxReference : public scene::ReferenceShader {
public:
    BoxReference(const Settings& plasma, double planetRadiusKm, double timeS)
        : density_(cachedBoxFrames(boxFramesSpec(plasma), io::defaultCacheDirectory()).frames,
                   boxFramePosition(plasma, timeS)),
          side_(plasma.boxSideKm),
          centreKm_(scene::planetPoint(plasma.boxLatitudeDeg, plasma.boxLongitudeDeg,
                                       planetRadiusKm + plasma.boxAltitudeKm))
    {
        const scene::LocalFrame local = scene::localFrame(plasma.boxLatitudeDeg, plasma.boxLongitudeDeg);
        axes_ = glm::dmat3(local.east, local.north, local.up);
        const aurorawall::physics::LineInfo& green = aurorawall::physics::lineInfo(aurorawall::physics::EmissionLine::Green5577);
        rgbPerDensityKm_ = aurorawall::physics::lineLinearSrgbPerRayleigh(green.wavelengthNm, green.cieXyz) * plasma.boxRayleighPerKm;
    }

    // shadePlasmaBox (plasma_box.glsl) in double, the column exact.
    f64::Ray shade(f64::Ray ray) const override
    {
        const glm::dvec3 o = glm::transpose(axes_) * (ray.origin - centreKm_);
        const glm::dvec3 d = glm::transpose(axes_) * ray.direction;
        glm::dvec2 segment = boxSegment(o, d, 0.5 * side_);
        segment.x = std::max(segment.x, 0.0);
        segment.y = std::min(segment.y, ray.end);
        if (segment.x < segment.y)
            ray.radiance += rgbPerDensityKm_ * f64::transmittanceTo(ray, segment) *
                            density_.exactColumn(o, d, segment, side_);
        return ray;
    }

private:
    BoxDensity density_;
    double side_;
    glm::dvec3 centreKm_;
    glm::dmat3 axes_{1.0}; // columns: east, north, up at the centre
    glm::dvec3 rgbPerDensityKm_{0.0};
};

} // namespace

BoxDensity::BoxDensity(BoxFrames frames, double framePosition) : frames_(std::move(frames))
{
    frame0_ = static_cast<int>(std::floor(framePosition));
    frame1_ = std::min(frame0_ + 1, frames_.frames - 1);
    weight1_ = framePosition - frame0_;
}

double BoxDensity::frameAt(int frame, glm::dvec3 unit) const
{
    const int n = frames_.cells;
    // Texel coordinates: centres at integers; x, y wrap, z held between the first and last centres.
    const glm::dvec3 c(unit.x * n - 0.5, unit.y * n - 0.5, std::clamp(unit.z * n, 0.5, n - 0.5) - 0.5);
    const glm::dvec3 base = glm::floor(c);
    const glm::dvec3 w = c - base;
    const int i[2] = {wrap(int(base.x), n), wrap(int(base.x) + 1, n)};
    const int j[2] = {wrap(int(base.y), n), wrap(int(base.y) + 1, n)};
    const int k[2] = {int(base.z), std::min(int(base.z) + 1, n - 1)};
    double sum = 0.0;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const std::size_t index =
                    ((std::size_t(frame) * n + k[dz]) * n + j[dy]) * std::size_t(n) + std::size_t(i[dx]);
                sum += (dx ? w.x : 1.0 - w.x) * (dy ? w.y : 1.0 - w.y) * (dz ? w.z : 1.0 - w.z) *
                       double(frames_.density[index]);
            }
    return sum;
}

double BoxDensity::at(glm::dvec3 unit) const
{
    return (1.0 - weight1_) * frameAt(frame0_, unit) + weight1_ * frameAt(frame1_, unit);
}

double BoxDensity::exactColumn(glm::dvec3 o, glm::dvec3 d, glm::dvec2 segment, double side) const
{
    const int n = frames_.cells;
    // The cuts: t where the unit coordinate (o + t d)/side + 1/2 is a cell centre (m + 1/2)/n.
    std::vector<double> cuts = {segment.x, segment.y};
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0)
            continue;
        for (int m = 0; m < n; ++m) {
            const double t = (((m + 0.5) / n - 0.5) * side - o[axis]) / d[axis];
            if (t > segment.x && t < segment.y)
                cuts.push_back(t);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    const double gauss = 0.5 / std::sqrt(3.0); // the nodes' offsets from a piece's middle, in its length
    double sum = 0.0;
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double length = cuts[p + 1] - cuts[p], middle = 0.5 * (cuts[p] + cuts[p + 1]);
        if (!(length > 0.0))
            continue;
        const glm::dvec3 lower = o + (middle - gauss * length) * d, upper = o + (middle + gauss * length) * d;
        sum += 0.5 * length * (at(lower / side + 0.5) + at(upper / side + 0.5));
    }
    return sum;
}

double BoxDensity::marchedColumn(glm::dvec3 o, glm::dvec3 d, glm::dvec2 segment, int steps, double side) const
{
    f64::March march{this};
    return march.plasmaBoxColumn(o, d, segment, steps, side);
}

glm::dvec2 boxSegment(glm::dvec3 o, glm::dvec3 d, double halfSide)
{
    f64::March march{nullptr}; // the segment reads no density
    return march.plasmaBoxSegment(o, d, halfSide);
}

std::unique_ptr<scene::ReferenceShader> makeBoxReference(const Settings& plasma, double planetRadiusKm, double timeS)
{
    return std::make_unique<BoxReference>(plasma, planetRadiusKm, timeS);
}

} // namespace aurorawall::components::plasma
