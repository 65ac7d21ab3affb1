#pragma once
// The order of the components' shading steps along a ray (the generated shadeRay and the CPU
// reference run them in this order). The rule:
//   1. by shell, front to back (scene/shell.h: each component declares its Component::shell());
//   2. within a shell, a component after every component of the same shell it needs
//      (Component::needs: what it adds to presupposes them, e.g. light scattered by a medium
//      after the medium's extinction, lights on a surface after the surface);
//   3. otherwise in the order given (the registry order).
// No component is named here: the rule reads only the shells and needs the components declare.
#include "scene/component.h"

#include <vector>

namespace aurorawall::scene {

// `components` in compositing order. Throws std::logic_error when components of one shell need
// each other in a cycle.
std::vector<const Component*> inCompositingOrder(const std::vector<const Component*>& components);

} // namespace aurorawall::scene
