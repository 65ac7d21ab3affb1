#include "components/plasma/live_pic.h"

#include "gl/context.h"
#include "gl/functions.h"

#include <stdexcept>
#include <utility>

namespace aurorawall::components::plasma {

namespace pic = aurorawall::components::plasma::simulation;

LivePic::LivePic(const pic::PeriodicGrid& grid, pic::Particles electrons, glm::dvec3 magneticField, double dt,
                 FrameDensity frameDensity, std::string shaderDir)
    : grid_(grid), start_(std::move(electrons)), magneticField_(magneticField), dt_(dt),
      frameDensity_(std::move(frameDensity)), shaderDir_(std::move(shaderDir)),
      gpu_(std::make_unique<gpu::GpuPic>(grid_, start_, magneticField_, dt_, shaderDir_, glm::dvec3(0.0),
                                         gpu::preferredGpuPicSolver(grid_, gl::currentRendererName())))
{
}

bool LivePic::advanceTo(long n)
{
    if (n < 0)
        throw std::invalid_argument("plasma live simulation: step " + std::to_string(n) + " is before the start");
    if (n == frameStep_)
        return false;
    if (!gpu_ || n < gpu_->stepCount()) { // behind, or a restart that failed before
        gpu_.reset(); // its buffers freed before the new one's are made
        gpu_ = std::make_unique<gpu::GpuPic>(grid_, start_, magneticField_, dt_, shaderDir_, glm::dvec3(0.0),
                                             gpu::preferredGpuPicSolver(grid_, gl::currentRendererName()));
    }
    while (gpu_->stepCount() < n)
        gpu_->step();
    pic::Particles electrons;
    electrons.weight = start_.weight;
    electrons.position = gpu_->positions();
    frame_ = frameDensity_(grid_, electrons);
    frameStep_ = n;
    return true;
}

void LivePic::showStep(long n, const std::function<void(const std::vector<float>&)>& upload)
{
    if (advanceTo(n)) {
        upload(frame_);
        gl::glFinish();
    }
}

} // namespace aurorawall::components::plasma
