#pragma once
// `aurorawall accuracy --glory FILE`: error against run time of the glory's quality knobs. The
// table's resolution (angles in the glory's span, wavelengths, size-parameter step of the radius
// quadrature) against the error of its colour and the cost of building it; then the per-pixel colour
// (the colour table, or 1 to 32 wavelengths per pixel spaced evenly or importance sampled) against
// the error of the rendered image and the time per frame.
#include "accuracy/scene_view.h"

#include <iosfwd>

namespace aurorawall::components::glory::tools {

void runGloryAccuracy(const accuracy::SceneAccuracySettings& settings, std::ostream& out);

} // namespace aurorawall::components::glory::tools
