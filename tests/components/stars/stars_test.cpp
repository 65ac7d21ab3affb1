// The stars on the GPU: each star's light, summed over its neighbourhood of pixels, does not depend
// on where within a pixel the star falls, so a last-bit difference between two devices' rays can
// only share a star's light differently between neighbouring pixels, never switch it on or off.
#include "accuracy/scene_view.h"
#include "components/registry.h"
#include "physics/constants.h"
#include "gl/context.h"
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;
const glm::ivec2 kSize(256, 144);
constexpr int kHalfWindow = 4; // the neighbourhood: 9x9 pixels about a star's brightest pixel

double luminance(const io::Image& image, int x, int y)
{
    const glm::dvec3 c = accuracy::pixelRadiance(image, x, y);
    return c.r + c.g + c.b;
}

double windowSum(const io::Image& image, glm::ivec2 centre);

// The light on the border of the 9x9 window: none of the star's, nor of a neighbour's, to speak of.
double borderSum(const io::Image& image, glm::ivec2 centre)
{
    double sum = 0.0;
    for (int d = -kHalfWindow; d < kHalfWindow; ++d)
        sum += luminance(image, centre.x + d, centre.y - kHalfWindow) + luminance(image, centre.x + kHalfWindow, centre.y + d) +
               luminance(image, centre.x - d, centre.y + kHalfWindow) + luminance(image, centre.x - kHalfWindow, centre.y - d);
    return sum;
}

// The brightest pixel of each star away from the edges and from other stars: a strict maximum of
// its 9x9 window, whose border holds less than 1e-4 of the window's light.
std::vector<glm::ivec2> starPeaks(const io::Image& image, double floor)
{
    std::vector<glm::ivec2> peaks;
    const int m = 2 * kHalfWindow;
    for (int y = m; y < image.height - m; ++y)
        for (int x = m; x < image.width - m; ++x) {
            const double v = luminance(image, x, y);
            bool peak = v > floor;
            for (int dy = -kHalfWindow; dy <= kHalfWindow && peak; ++dy)
                for (int dx = -kHalfWindow; dx <= kHalfWindow && peak; ++dx)
                    peak = (dx == 0 && dy == 0) || luminance(image, x + dx, y + dy) < v;
            if (peak && borderSum(image, {x, y}) < 1e-4 * windowSum(image, {x, y}))
                peaks.emplace_back(x, y);
        }
    return peaks;
}

double windowSum(const io::Image& image, glm::ivec2 centre)
{
    double sum = 0.0;
    for (int dy = -kHalfWindow; dy <= kHalfWindow; ++dy)
        for (int dx = -kHalfWindow; dx <= kHalfWindow; ++dx)
            sum += luminance(image, centre.x + dx, centre.y + dy);
    return sum;
}

} // namespace

// The view turned by a quarter, a half and three quarters of a pixel (right and up at once): the
// light of every star alone in its 9x9 neighbourhood stays the same there, within the sum of
//  - aliasing: a Gaussian exp(−x²/σ²) sampled on the pixel grid sums to its integral times
//    1 + 2·Σ exp(−π²σ²k²) cos(2πk x₀) (Poisson summation), so moving it changes the sum by up to
//    4·exp(−π²σ²) per axis, σ in pixels; the shader's σ is the corner pixel's angle (uPixelAngle), at
//    least cos θ_c of any pixel's, θ_c the corner's angle off the view axis;
//  - perspective: the sum is the star's integral over a pixel's solid angle, ∝ cos³θ on a flat image,
//    which changes by 3 tan θ dθ as the star moves by dθ (at most the turn's diagonal);
//  - the window: the star, within 1.25 pixels of the window's centre, leaves beyond its border
//    (3.25 pixels away) at most erfc(3.25) ≈ 4.3e-6 of itself per side, in either image;
//  - float sums of 81 pixels of a few roundings each: about 1e-5 in either image.
// Before a pixel summed the stars of neighbouring cells, a star's Gaussian was cut at its cell's
// edge, and such turns changed sums by up to 30%.
TEST(Stars, FluxOverANeighbourhoodDoesNotDependOnTheSubPixelPosition)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const scene::Scene scene = components::loadScene(kSource + "/tests/render/data/stars-from-orbit.toml");
    accuracy::SceneView view = accuracy::sceneView(scene, kSource + "/config/walls/single.toml", kSize);
    view.frame.zoom = 16.0; // about 6e-4 rad per pixel: σ a fifth of a star cell
    const io::Image reference = accuracy::renderView(scene, view, kSource + "/shaders", 0).image;
    const double floor = 1e-3 / scene.exposure;
    const std::vector<glm::ivec2> peaks = starPeaks(reference, floor);
    std::printf("%zu stars\n", peaks.size());
    ASSERT_GE(peaks.size(), 20u);
    const glm::dvec3 zoomed(1.0 / view.frame.zoom, 1.0 / view.frame.zoom, 1.0); // as the renderer zooms
    const glm::dvec3 corner = zoomed * view.rays.originDir;
    const glm::dvec3 centre = zoomed * (view.rays.originDir + 0.5 * (double(kSize.x) * view.rays.stepRight + double(kSize.y) * view.rays.stepDown));
    const double pixelAngle = glm::length(zoomed * view.rays.stepRight) / glm::length(centre);
    const double tanCorner = glm::length(corner - centre) / glm::length(centre);
    const double sigmaPixels = glm::length(centre) / glm::length(corner); // cos θ_c
    const double aliasing = 2.0 * 4.0 * std::exp(-physics::kPi * physics::kPi * sigmaPixels * sigmaPixels);
    for (const double fraction : {0.25, 0.5, 0.75}) {
        accuracy::SceneView turned = view;
        const double angle = fraction * pixelAngle;
        const double perspective = 3.0 * tanCorner * std::sqrt(2.0) * angle;
        const double bound = aliasing + perspective + 2.0 * 4.0 * 4.3e-6 + 2.0 * 1e-5;
        const glm::dmat4 turn = glm::rotate(glm::rotate(glm::dmat4(1.0), angle, view.frame.cameraUp), angle,
                                            view.frame.cameraRight);
        turned.frame.cameraRight = glm::dvec3(turn * glm::dvec4(view.frame.cameraRight, 0.0));
        turned.frame.cameraUp = glm::dvec3(turn * glm::dvec4(view.frame.cameraUp, 0.0));
        turned.frame.cameraBack = glm::dvec3(turn * glm::dvec4(view.frame.cameraBack, 0.0));
        const io::Image image = accuracy::renderView(scene, turned, kSource + "/shaders", 0).image;
        double largest = 0.0;
        for (const glm::ivec2& p : peaks) {
            const double before = windowSum(reference, p), after = windowSum(image, p);
            largest = std::max(largest, std::abs(after - before) / before);
        }
        std::printf("turned by %.2f pixel: largest relative change of a star's 9x9 sum %.3g (bound %.3g)\n", fraction,
                    largest, bound);
        EXPECT_LT(largest, bound) << fraction;
    }
}
