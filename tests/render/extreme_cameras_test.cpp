// Numerical stability: the substorm scene rendered from extreme viewpoints and times has no NaN
// or Inf pixel, and shows what it should (sky above, ground below, aurora where it is).
#include "cluster/frame_state.h"
#include "physics/constants.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "io/image.h"
#include "render/tile_renderer.h"
#include "components/aurora/aurora.h"
#include "components/fluid_detail/fluid_detail.h"
#include "components/registry.h"
#include "scene/scene.h"
#include "wall/tile_rays.h"
#include "wall/wall.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <memory>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

class ExtremeCameras : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        context_ = gl::createContext(gl::Backend::Egl);
        scene_ = std::make_unique<scene::Scene>(components::loadScene(kSource + "/config/scenes/substorm.toml"));
        renderer_ = std::make_unique<render::TileRenderer>(*scene_, kSource + "/shaders");
    }
    static void TearDownTestSuite()
    {
        renderer_.reset();
        context_.reset();
    }

    // Renders a 64x36 view with a 70 deg vertical field of view looking along `forward`.
    static io::Image render(glm::dvec3 positionKm, glm::dvec3 forward, glm::dvec3 up, double timeS)
    {
        return renderWith(*renderer_, positionKm, forward, up, timeS);
    }

    static io::Image renderWith(render::TileRenderer& renderer, glm::dvec3 positionKm, glm::dvec3 forward,
                                glm::dvec3 up, double timeS)
    {
        wall::GridSpec grid;
        grid.screenPx = {64, 36};
        grid.screenMm = {64.0, 36.0};
        grid.eyeFromCentreMm = {0.0, 0.0, 18.0 / std::tan(35.0 * aurorawall::physics::kPi / 180.0)};
        const wall::Wall wall = wall::makeGridWall(grid);
        cluster::FrameState frame;
        frame.timeS = timeS;
        frame.cameraPositionKm = positionKm;
        frame.cameraBack = -glm::normalize(forward);
        frame.cameraUp = glm::normalize(up - glm::dot(up, -frame.cameraBack) * -frame.cameraBack);
        frame.cameraRight = glm::cross(-frame.cameraBack, frame.cameraUp);
        gl::FloatTarget target(64, 36);
        gl::FullScreenTriangle triangle;
        renderer.setFrame(frame);
        renderer.renderTile(wall::tileRays(wall, 0), target, triangle);
        return io::imageFromGlReadback(64, 36, target.readback());
    }

    static glm::dvec3 site() { return scene::planetPoint(64.0, 14.0, 1.0); } // under a curtain

    static std::unique_ptr<gl::Context> context_;
    static std::unique_ptr<scene::Scene> scene_;
    static std::unique_ptr<render::TileRenderer> renderer_;
};

std::unique_ptr<gl::Context> ExtremeCameras::context_;
std::unique_ptr<scene::Scene> ExtremeCameras::scene_;
std::unique_ptr<render::TileRenderer> ExtremeCameras::renderer_;

// Radiance is linear sRGB in cd/m^2: 1 kR of 557.7 nm is about 2e-4 cd/m^2, the night sky's glow
// about 2e-5. "Sees the aurora" means a pixel brighter than 1e-3 cd/m^2 (several kR).
constexpr double kAuroraSeen = 1e-3;

double maxRadiance(const io::Image& image)
{
    double m = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
        m = std::max({m, double(image.rgba[i]), double(image.rgba[i + 1]), double(image.rgba[i + 2])});
    return m;
}

// A horizontal direction at the site (toward the north).
glm::dvec3 north(glm::dvec3 up) { return glm::normalize(glm::dvec3(0, 0, 1) - up * up.z); }

} // namespace

TEST_F(ExtremeCameras, OnTheGroundLookingUpSeesTheAurora)
{
    const glm::dvec3 up = site();
    const io::Image image = render(up * 6371.0, up, north(up), 0.0);
    EXPECT_EQ(io::countNonFinite(image), 0u);
    EXPECT_GT(maxRadiance(image), kAuroraSeen);
}

// A camera exactly on the ground (altitude 0, entered as a latitude and longitude) sees the sky at every
// latitude: its |position| lands a few ulps of R below the sphere at half of them, which must not put it
// underground (a black image).
TEST_F(ExtremeCameras, OnTheGroundAtAnyLatitudeSeesTheSky)
{
    for (double lat : {60.0, 61.0, 63.0, 64.0, 67.52, 68.0, 70.0}) {
        const glm::dvec3 up = scene::planetPoint(lat, 20.0, 1.0);
        const glm::dvec3 view = glm::normalize(north(up) + 0.58 * up); // 30 degrees up
        const io::Image image = render(scene::planetPoint(lat, 20.0, 6371.0), view, up, 0.0);
        EXPECT_EQ(io::countNonFinite(image), 0u) << lat;
        EXPECT_GT(maxRadiance(image), 0.0) << "latitude " << lat << ": the camera was taken to be underground";
    }
}

TEST_F(ExtremeCameras, OneMetreAboveGroundAlongTheHorizon)
{
    const glm::dvec3 up = site();
    const io::Image image = render(up * (6371.0 + 0.001), north(up), up, 0.0);
    EXPECT_EQ(io::countNonFinite(image), 0u);
    // The horizon dips sqrt(2h/R) = 0.03 deg below the view's middle, a sixtieth of a pixel: in every column
    // the 18 rows above the middle see the sky and the 18 below the ground, with no stripes of one in the
    // other. The night ground is darker than any sky pixel, which looks through the glowing atmosphere (and
    // the aurora): every sky pixel of a column is brighter than every ground pixel of it.
    const auto luminance = [&](int x, int y) {
        const float* c = image.pixel(x, y);
        return double(c[0]) + c[1] + c[2];
    };
    for (int x = 0; x < image.width; ++x) {
        double darkestSky = 1e30, brightestGround = 0.0;
        for (int y = 0; y < image.height / 2; ++y)
            darkestSky = std::min(darkestSky, luminance(x, y));
        for (int y = image.height / 2; y < image.height; ++y)
            brightestGround = std::max(brightestGround, luminance(x, y));
        EXPECT_GT(brightestGround, 0.0) << "column " << x;
        EXPECT_GT(darkestSky, brightestGround) << "column " << x;
    }
}

TEST_F(ExtremeCameras, InsideACurtainAndStraightDown)
{
    const glm::dvec3 up = site();
    const io::Image inside = render(up * (6371.0 + 110.0), north(up), up, 0.0);
    EXPECT_EQ(io::countNonFinite(inside), 0u);
    EXPECT_GT(maxRadiance(inside), kAuroraSeen);
    const io::Image down = render(up * (6371.0 + 400.0), -up, north(up), 180.0); // at the break-up
    EXPECT_EQ(io::countNonFinite(down), 0u);
    EXPECT_GT(maxRadiance(down), 0.5 * kAuroraSeen);
}

TEST_F(ExtremeCameras, FarInSpace)
{
    const glm::dvec3 up = site();
    // 10^6 km away the planet is 0.73 deg across, less than a pixel: no NaN anywhere.
    EXPECT_EQ(io::countNonFinite(render(up * 1.0e6, -up, north(up), 0.0)), 0u);
    // 10^5 km away it is 7.3 deg, about 4 pixels: the pixels at the centre see it.
    const io::Image image = render(up * 1.0e5, -up, north(up), 0.0);
    EXPECT_EQ(io::countNonFinite(image), 0u);
    EXPECT_GT(image.pixel(32, 18)[0] + image.pixel(32, 18)[1] + image.pixel(32, 18)[2], 0.0f);
}

TEST_F(ExtremeCameras, HugeAnimationTime)
{
    const glm::dvec3 up = site();
    const io::Image image = render(up * 6371.0, up, north(up), 1.0e9);
    EXPECT_EQ(io::countNonFinite(image), 0u);
    EXPECT_GT(maxRadiance(image), kAuroraSeen);
}

TEST_F(ExtremeCameras, ZeroAndMaximumCurtains)
{
    // Every curtain dark, then every curtain at the largest flux and electron energy a scene
    // accepts (1e4 erg cm^-2 s^-1, 50 keV): finite everywhere; dark curtains add nothing to the
    // same view without the aurora component; the brightest ones are far above the usual ~1e-2.
    const glm::dvec3 up = site(), position = up * (6371.0 + 110.0);
    scene::Scene withoutAurora = *scene_;
    withoutAurora.remove("fluid_detail");
    withoutAurora.remove("aurora");
    render::TileRenderer plain(withoutAurora, kSource + "/shaders");
    const io::Image reference = renderWith(plain, position, north(up), up, 180.0);
    for (double flux : {0.0, 1e4}) {
        scene::Scene s = *scene_;
        for (components::aurora::Curtain& c : s.settings<components::aurora::Settings>().curtains)
            for (components::aurora::CurtainKey& k : c.keys) {
                k.energyFluxErgPerCm2S = flux;
                k.energyKeV = flux > 0 ? 50.0 : k.energyKeV;
            }
        render::TileRenderer renderer(s, kSource + "/shaders");
        const io::Image image = renderWith(renderer, position, north(up), up, 180.0);
        EXPECT_EQ(io::countNonFinite(image), 0u) << "flux " << flux;
        if (flux == 0.0)
            EXPECT_LT(io::compareImages(reference, image).maxAbs, 1e-7);
        else
            EXPECT_GT(maxRadiance(image), 0.1);
    }
}

TEST_F(ExtremeCameras, PrecomputesOnlyForListedComponents)
{
    // The precomputation log names one table per listed component that needs one, and nothing
    // for components the scene leaves out (the shader source side is tests/render/fragment_shader_test).
    auto logOf = [](const std::vector<std::string>& components) {
        scene::Scene s = *scene_;
        for (const scene::Component* c : scene_->components())
            if (std::find(components.begin(), components.end(), c->name()) == components.end())
                s.remove(c->name());
        render::TileRenderer renderer(s, kSource + "/shaders");
        std::string log;
        for (const std::string& line : renderer.precomputationLog())
            log += line + "\n";
        return log;
    };
    const std::string starsOnly = logOf({"planet", "stars"});
    EXPECT_EQ(starsOnly, "");
    const std::string aurora = logOf({"planet", "atmosphere", "aurora"});
    EXPECT_NE(aurora.find("aurora deposition table"), std::string::npos) << aurora;
    EXPECT_EQ(aurora.find("fluid_detail"), std::string::npos) << aurora;
    EXPECT_EQ(aurora.find("planet_texture"), std::string::npos) << aurora;
    const std::string all = logOf({"planet", "planet_texture", "atmosphere", "aurora", "fluid_detail"});
    EXPECT_NE(all.find("fluid_detail: 512 x 128 cells"), std::string::npos) << all;
    EXPECT_NE(all.find("planet_texture"), std::string::npos) << all;
}
