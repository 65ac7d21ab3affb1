#include "scene/compositing_order.h"

#include <algorithm>
#include <stdexcept>

namespace aurorawall::scene {

namespace {

// Does `a` need `b`: by its name, or by a role `b` provides?
bool needs(const Component& a, const Component& b)
{
    const std::vector<std::string> n = a.needs();
    const std::vector<std::string> roles = b.provides();
    return std::find(n.begin(), n.end(), b.name()) != n.end() ||
           std::find_first_of(n.begin(), n.end(), roles.begin(), roles.end()) != n.end();
}

} // namespace

std::vector<const Component*> inCompositingOrder(const std::vector<const Component*>& components)
{
    std::vector<const Component*> byShell = components;
    std::stable_sort(byShell.begin(), byShell.end(),
                     [](const Component* a, const Component* b) { return a->shell() < b->shell(); });
    std::vector<const Component*> ordered;
    ordered.reserve(byShell.size());
    for (auto first = byShell.begin(); first != byShell.end();) {
        const Shell shell = (*first)->shell();
        const auto last = std::find_if(first, byShell.end(), [&](const Component* c) { return c->shell() != shell; });
        // The shell's components, each placed once all those of the shell it needs are: the first
        // ready one in the given order each time.
        std::vector<const Component*> waiting(first, last);
        while (!waiting.empty()) {
            const auto ready = std::find_if(waiting.begin(), waiting.end(), [&](const Component* c) {
                return std::none_of(waiting.begin(), waiting.end(),
                                    [&](const Component* other) { return other != c && needs(*c, *other); });
            });
            if (ready == waiting.end())
                throw std::logic_error("the components '" + waiting.front()->name() +
                                       "' and others of its shell need each other in a cycle");
            ordered.push_back(*ready);
            waiting.erase(ready);
        }
        first = last;
    }
    return ordered;
}

} // namespace aurorawall::scene
