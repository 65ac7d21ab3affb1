#pragma once
// The off-axis frustum of one screen seen from the eye: Kooima, "Generalized Perspective
// Projection" (2008). The screen's physical corners pa (lower left), pb (lower right) and
// pc (upper left) give its orthonormal basis vr, vu, vn; the eye pe gives the distance
// d = -vn.(pa - pe) and the extents l = vr.(pa - pe) n/d, r = vr.(pb - pe) n/d,
// b = vu.(pa - pe) n/d, t = vu.(pc - pe) n/d on the near plane n.
#include "wall/screen.h"

#include <glm/glm.hpp>

namespace aurorawall::wall {

struct Frustum {
    double left, right, bottom, top, nearPlane, farPlane; // on the near plane, in mm
    glm::dmat4 projection; // glm::frustum(left, right, bottom, top, nearPlane, farPlane): OpenGL clip space
    glm::dmat4 view;       // wall frame -> eye frame: rotation into (vr, vu, vn) after translation by -eye
};

// projection*view maps the screen's corners to NDC (+-1, +-1). Throws std::invalid_argument when
// the eye is on or behind the screen's plane, or 0 < nearMm < farMm does not hold.
Frustum offAxisFrustum(const Screen& screen, glm::dvec3 eyeMm, double nearMm, double farMm);

} // namespace aurorawall::wall
