#pragma once
// Views of a scene drawn at random from a seed, for the error of the default settings at views nobody
// chose (`aurorawall accuracy --scene FILE --views N`): a camera at one of four kinds of height
// somewhere near the scene's own, looking toward a point of the auroral layer (100–250 km) with its
// aim, roll and animation time drawn too. Deviates are the 53 high bits of std::mt19937_64, fully
// specified by the C++ standard, so a seed gives the same views on every machine.
#include "accuracy/scene_view.h"

#include <cstdint>
#include <random>

namespace aurorawall::accuracy {

enum class ViewKind {
    Ground,      // 0.01–3 km up, within 8° of the scene camera's ground point: grazing rays, long paths
    InsideLayer, // 90–250 km up, inside the emitting layer
    Above,       // 250–1500 km up, looking down through it
    Space,       // 2,000–40,000 km up, within 40°: the layer at the limb or edge-on, zoomed in to about
                 // 1,000 km per unit of the wall's field of view (frame.zoom)
};
constexpr int kViewKinds = 4;
const char* viewKindName(ViewKind kind);

struct RandomViewSettings {
    double planetRadiusKm = 6371.0;
    double timeSpanS = 600.0;   // animation time drawn in [start, start + span) ...
    double hugeTimeShare = 0.25; // ... or, this share of the views, in [start + 1e4, start + 1e8) s, log-uniform
};

class RandomViews {
public:
    RandomViews(std::uint64_t seed, RandomViewSettings settings);

    // `base` (the scene's view: wall, rays and frame) with its camera and time replaced by a draw of
    // the given kind; the field of view and exposure stay the scene's, and so does the zoom but from space.
    SceneView draw(const SceneView& base, ViewKind kind);

private:
    double uniform(double low, double high);
    // A unit vector within `maxAngleRad` of `axis`, uniform in solid angle.
    glm::dvec3 around(glm::dvec3 axis, double maxAngleRad);

    std::mt19937_64 engine_;
    RandomViewSettings settings_;
};

} // namespace aurorawall::accuracy
