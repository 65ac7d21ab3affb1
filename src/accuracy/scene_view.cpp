#include "accuracy/scene_view.h"

#include "cluster/master_clock.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/functions.h"
#include "render/tile_renderer.h"
#include "wall/wall_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <thread>

namespace aurorawall::accuracy {

SceneView sceneView(const scene::Scene& scene, const std::string& wallFile, glm::ivec2 sizePx, long long frame)
{
    const wall::Wall single = wall::singleScreenEquivalent(wall::loadWall(wallFile));
    const wall::Screen& screen = single.screens.front();
    wall::GridSpec grid;
    grid.screenPx = sizePx;
    grid.screenMm = {screen.widthMm, screen.heightMm};
    const glm::dvec3 centre(screen.lowerLeftMm + 0.5 * grid.screenMm, 0.0);
    grid.eyeFromCentreMm = single.eyeMm - centre;
    SceneView view;
    view.wall = wall::makeGridWall(grid);
    view.rays = wall::tileRays(view.wall, 0);
    cluster::ClockSettings clock;
    clock.startTimeS = scene.startTimeS;
    clock.timeStepS = scene.timeStepS;
    clock.wallTanHalfFov = wall::tanHalfVerticalFieldOfView(view.wall);
    cluster::MasterClock master(clock, scene.camera, scene.exposure);
    for (long long k = 0; k <= frame; ++k)
        view.frame = master.next(false);
    return view;
}

// tile_rays.h: the direction through canvas point pixelOffset + (x + 1/2, y + 1/2), wall frame; the
// wall frame's x, y, z are the camera's right, up and back (TileRenderer::setFrame).
glm::dvec3 pixelDirection(const SceneView& view, int x, int y)
{
    const wall::TileRays& r = view.rays;
    const glm::dvec2 canvas = glm::dvec2(r.pixelOffset) + glm::dvec2(x + 0.5, y + 0.5);
    const glm::dvec3 wallDir = r.originDir + canvas.x * r.stepRight + canvas.y * r.stepDown;
    return glm::normalize(cluster::wallToPlanet(view.frame) * wallDir);
}

TimedRender renderView(const scene::Scene& scene, const SceneView& view, const std::string& shaderDir, int runs)
{
    return renderView(scene, view, shaderDir, runs, render::preferredMarchStage(gl::currentRendererName()));
}

TimedRender renderView(const scene::Scene& scene, const SceneView& view, const std::string& shaderDir, int runs,
                       render::MarchStage stage)
{
    using Clock = std::chrono::steady_clock;
    render::TileRenderer renderer(scene, shaderDir, stage);
    const glm::ivec2 size(view.wall.screens.front().widthPx, view.wall.screens.front().heightPx);
    gl::FloatTarget target(size.x, size.y);
    gl::FullScreenTriangle triangle;
    std::vector<double> ms;
    for (int i = 0; i <= runs; ++i) {
        const auto start = Clock::now();
        renderer.setFrame(view.frame);
        renderer.renderTile(view.rays, target, triangle);
        gl::glFinish();
        if (i > 0) // the first frame is the warm-up
            ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(ms.begin(), ms.end());
    TimedRender result;
    result.image = io::imageFromGlReadback(size.x, size.y, target.readback());
    result.msPerFrame = ms.empty() ? 0.0 : ms[ms.size() / 2];
    return result;
}

RelativeError relativeError(const std::vector<glm::dvec3>& values, const std::vector<glm::dvec3>& reference,
                            double floor)
{
    RelativeError e;
    double sumSquares = 0.0;
    for (size_t i = 0; i < values.size(); ++i) {
        const double r = glm::length(reference[i]);
        if (!(r >= floor))
            continue;
        const double rel = glm::length(values[i] - reference[i]) / r;
        sumSquares += rel * rel;
        e.max = std::max(e.max, std::isfinite(rel) ? rel : INFINITY);
        ++e.pixels;
    }
    e.rms = e.pixels ? std::sqrt(sumSquares / double(e.pixels)) : 0.0;
    return e;
}

glm::dvec3 pixelRadiance(const io::Image& image, int x, int y)
{
    const float* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

std::vector<glm::dvec3> referencePixels(const render::ReferenceModel& model, const SceneView& view,
                                        const std::vector<glm::ivec2>& pixels, int threads)
{
    std::vector<glm::dvec3> result(pixels.size());
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(threads, 1); ++w)
        workers.emplace_back([&, w] {
            for (size_t i = size_t(w); i < pixels.size(); i += size_t(std::max(threads, 1)))
                result[i] = model.radiance(view.frame.cameraPositionKm, pixelDirection(view, pixels[i].x, pixels[i].y));
        });
    for (std::thread& t : workers)
        t.join();
    return result;
}

std::unique_ptr<gl::Context> openAccuracyContext(std::ostream& out, glm::ivec2 sizePx)
{
    auto context = gl::createContext(gl::Backend::Egl);
    const int largest = gl::largestRenderTargetPx();
    if (sizePx.x > largest || sizePx.y > largest)
        throw std::runtime_error("--size " + std::to_string(sizePx.x) + "x" + std::to_string(sizePx.y) +
                                 ": larger than this GL device's largest render target, " + std::to_string(largest) +
                                 " pixels a side");
    const char* threads = std::getenv("LP_NUM_THREADS");
    out << "renderer: " << context->rendererName() << ", " << context->glVersion() << ", vendor "
        << context->vendorName()
        << (threads ? ", LP_NUM_THREADS=" + std::string(threads) : std::string()) << "\n";
    return context;
}

} // namespace aurorawall::accuracy
