#pragma once
// A plasma simulation run live on the GPU (plasma::GpuPic, compute shaders, float): stepped to the
// step the master's clock asks for, from its current step, or restarted from the seeded start when
// the clock asks for an earlier step; so the state at step n depends only on n. Its density frame
// is computed as the CPU frames' are (the electrons' positions read back, the same deposit at the
// cell centres in double). Needs a current GL 4.5 context.
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::components::plasma {

class LivePic {
public:
    // A frame from the electrons' positions on the grid (sheetFrameDensity, boxFrameDensity).
    using FrameDensity = std::function<std::vector<float>(const simulation::PeriodicGrid&,
                                                          const simulation::Particles&)>;

    // electrons at step 0 (kept for restarts); magneticField (T), dt (s) as the CPU frames' simulation.
    LivePic(const simulation::PeriodicGrid& grid, simulation::Particles electrons,
            glm::dvec3 magneticField, double dt, FrameDensity frameDensity, std::string shaderDir);

    // Steps to step n ≥ 0 (restarting first if n is behind) and computes its frame; nothing when the
    // frame of step n is already there. Returns whether the frame changed.
    bool advanceTo(long n);
    // advanceTo(n), then the frame handed to `upload` (when it changed) and the GPU waited for, so
    // the time spent here is the plasma's whole share of the frame.
    void showStep(long n, const std::function<void(const std::vector<float>&)>& upload);
    long step() const { return gpu_ ? gpu_->stepCount() : 0; }
    // The frame of the last advanceTo's step.
    const std::vector<float>& frame() const { return frame_; }

private:
    simulation::PeriodicGrid grid_;
    simulation::Particles start_;
    glm::dvec3 magneticField_;
    double dt_;
    FrameDensity frameDensity_;
    std::string shaderDir_;
    std::unique_ptr<gpu::GpuPic> gpu_;
    std::vector<float> frame_;
    long frameStep_ = -1;
};

} // namespace aurorawall::components::plasma
