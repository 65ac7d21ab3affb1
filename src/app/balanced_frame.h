#pragma once
// This rank's part of a load-balanced frame (src/cluster/load_balancer.h): it renders
// the bands the master assigned to it, sends those that belong to other ranks' screens, and
// receives its own screens' bands from whoever rendered them. Every pixel is traced with the
// same rays as without balancing (the wall canvas makes a band's rays independent of who traces
// them) and every band is rounded to half floats whoever drew it (as the unbalanced output is), so the
// balanced wall equals the unbalanced one. Moved bands travel as half-float RGB, 6 bytes a pixel.
#include "cluster/load_balancer.h"
#include "cluster/mpi_world.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "io/image.h"
#include "render/tile_renderer.h"
#include "wall/wall.h"

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace aurorawall::app {

struct BandCost {
    int band = 0;
    // Process CPU time to draw and read back the run of bands it was drawn with, times its share of
    // the run's work.
    double cpuMs = 0.0;
    // The band's work: the sum over its pixels of the alpha main.frag writes (1 + aurora samples).
    // Unlike CPU time it does not depend on who drew the band or on the machine's noise.
    double work = 0.0;
};

// What the load balancer balances: measured CPU time, or the rays' work.
enum class BandMeasure { CpuTime, Work };

class BalancedFrame {
public:
    BalancedFrame(const wall::Wall& wall, std::vector<cluster::Band> bands, int rank);

    struct Timing {
        double renderMs = 0.0, renderCpuMs = 0.0, exchangeMs = 0.0, exchangeMB = 0.0;
        double renderWork = 0.0; // the sum of main.frag's alpha (1 + aurora samples) over the drawn pixels
    };

    // Needs the context whose objects it uses current (the GLFW backend: window 0).
    std::vector<BandCost> render(render::TileRenderer& renderer, const std::vector<int>& assignment,
                                 const cluster::MpiWorld& world, Timing& timing);

    // The complete pixels of one of this rank's screens (top-down rows, values rounded to half
    // floats as io/half_pixels.h, alpha 1), after render().
    const io::Image& screenImage(int screen) const { return screens_.at(screen); }

private:
    struct Target {
        std::unique_ptr<gl::FloatTarget> target;
        std::unique_ptr<gl::FullScreenTriangle> triangle;
    };
    Target& targetFor(int width, int height);

    const wall::Wall& wall_;
    std::vector<cluster::Band> bands_;
    int rank_;
    std::map<int, io::Image> screens_;
    std::map<std::pair<int, int>, Target> targets_;
};

// Band costs travel to the master as bytes; it turns them into one value per band (NaN where no
// rank reported one).
std::vector<char> packBandCosts(const std::vector<BandCost>& costs);
// Each band's cost by the measure (NaN where no rank reported it).
std::vector<double> unpackBandCosts(const std::vector<char>& bytes, size_t bandCount, BandMeasure measure);

} // namespace aurorawall::app
