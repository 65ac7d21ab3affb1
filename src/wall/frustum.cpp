#include "wall/frustum.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

namespace aurorawall::wall {

Frustum offAxisFrustum(const Screen& screen, glm::dvec3 eyeMm, double nearMm, double farMm)
{
    if (!(nearMm > 0.0 && nearMm < farMm))
        throw std::invalid_argument("offAxisFrustum: need 0 < near < far");
    const glm::dvec3 pa = screen.lowerLeft(), pb = screen.lowerRight(), pc = screen.upperLeft();
    // Kooima 2008, eq. 1-3: the screen's orthonormal basis.
    const glm::dvec3 vr = glm::normalize(pb - pa);
    const glm::dvec3 vu = glm::normalize(pc - pa);
    const glm::dvec3 vn = glm::normalize(glm::cross(vr, vu));
    // Eq. 4-8: eye-to-corner vectors, the eye's distance from the screen plane, the extents.
    const glm::dvec3 va = pa - eyeMm, vb = pb - eyeMm, vc = pc - eyeMm;
    const double d = -glm::dot(va, vn);
    if (!(d > 0.0))
        throw std::invalid_argument("offAxisFrustum: the eye is on or behind the screen '" + screen.name + "'");
    Frustum f;
    f.nearPlane = nearMm;
    f.farPlane = farMm;
    f.left = glm::dot(vr, va) * nearMm / d;
    f.right = glm::dot(vr, vb) * nearMm / d;
    f.bottom = glm::dot(vu, va) * nearMm / d;
    f.top = glm::dot(vu, vc) * nearMm / d;
    f.projection = glm::frustum(f.left, f.right, f.bottom, f.top, nearMm, farMm);
    // Eq. 9-10: rotate the screen basis onto the axes (rows vr, vu, vn; GLM is column-major),
    // after moving the eye to the origin.
    glm::dmat4 rotation(1.0);
    for (int i = 0; i < 3; ++i) {
        rotation[i][0] = vr[i];
        rotation[i][1] = vu[i];
        rotation[i][2] = vn[i];
    }
    f.view = rotation * glm::translate(glm::dmat4(1.0), -eyeMm);
    return f;
}

} // namespace aurorawall::wall
