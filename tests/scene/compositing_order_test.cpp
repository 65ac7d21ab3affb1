// The order of the shading steps along a ray (scene/compositing_order.h): by declared shell, front
// to back; within a shell, a component after those of the shell it needs; otherwise as given.
#include "components/registry.h"
#include "scene/compositing_order.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace aurorawall;

namespace {

// A component that declares only a name, a shell, what it needs and the roles it provides.
class Fake : public scene::Component {
public:
    Fake(std::string name, scene::Shell shell, std::vector<std::string> needs = {}, std::vector<std::string> provides = {})
        : name_(std::move(name)), shell_(shell), needs_(std::move(needs)), provides_(std::move(provides))
    {
    }
    std::string name() const override { return name_; }
    std::vector<std::string> needs() const override { return needs_; }
    std::vector<std::string> provides() const override { return provides_; }
    scene::Shell shell() const override { return shell_; }
    double reachKm(const scene::Scene&) const override { return 0.0; }
    std::unique_ptr<scene::ComponentSettings> defaultSettings() const override { return nullptr; }
    void read(const config::TableReader&, scene::Scene&, scene::ComponentSettings&) const override {}
    std::vector<std::string> shaderModules() const override { return {}; }
    std::unique_ptr<scene::ComponentRenderer> makeRenderer(const scene::Scene&, const scene::FindRenderer&) const override
    {
        return nullptr;
    }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene&, const scene::ReferenceContext&) const override
    {
        return nullptr;
    }

private:
    std::string name_;
    scene::Shell shell_;
    std::vector<std::string> needs_;
    std::vector<std::string> provides_;
};

std::string names(const std::vector<const scene::Component*>& components)
{
    std::string s;
    for (const scene::Component* c : components)
        s += (s.empty() ? "" : " ") + c->name();
    return s;
}

} // namespace

TEST(CompositingOrder, ShellsFrontToBackWhateverTheGivenOrder)
{
    const Fake space("a", scene::Shell::Space), ground("b", scene::Shell::Ground), deck("c", scene::Shell::CloudDeck),
        structure("d", scene::Shell::EmittingStructures), layer("e", scene::Shell::EmittingLayers),
        lower("f", scene::Shell::LowerAtmosphere);
    EXPECT_EQ(names(scene::inCompositingOrder({&space, &ground, &deck, &structure, &layer, &lower})), "f e d c b a");
    EXPECT_EQ(names(scene::inCompositingOrder({&lower, &layer, &structure, &deck, &ground, &space})), "f e d c b a");
}

TEST(CompositingOrder, WithinAShellNeedsFirstThenTheGivenOrder)
{
    // x needs y, y needs z (all one shell), w needs nothing; given x w y z: w is ready first in
    // the given order, then z, y, x as their needs are placed.
    const Fake x("x", scene::Shell::Ground, {"y"}), y("y", scene::Shell::Ground, {"z"}), z("z", scene::Shell::Ground),
        w("w", scene::Shell::Ground);
    EXPECT_EQ(names(scene::inCompositingOrder({&x, &w, &y, &z})), "w z y x");
    // Without needs, the given order stays.
    const Fake p("p", scene::Shell::Ground), q("q", scene::Shell::Ground);
    EXPECT_EQ(names(scene::inCompositingOrder({&q, &p})), "q p");
    EXPECT_EQ(names(scene::inCompositingOrder({&p, &q})), "p q");
}

TEST(CompositingOrder, ARoleNeededPlacesItsProviderFirst)
{
    // d needs the role "r" that p provides, without naming p.
    const Fake d("d", scene::Shell::EmittingStructures, {"r"}),
        p("p", scene::Shell::EmittingStructures, {}, {"r"});
    EXPECT_EQ(names(scene::inCompositingOrder({&d, &p})), "p d");
    EXPECT_EQ(names(scene::inCompositingOrder({&p, &d})), "p d");
}

TEST(CompositingOrder, NeedsAcrossShellsDoNotReorder)
{
    // A component needing one of a deeper shell still runs in its own shell; a need of a component
    // not given is ignored.
    const Fake front("front", scene::Shell::LowerAtmosphere, {"back", "absent"}), back("back", scene::Shell::Ground);
    EXPECT_EQ(names(scene::inCompositingOrder({&back, &front})), "front back");
}

TEST(CompositingOrder, ACycleWithinAShellIsAnError)
{
    const Fake a("a", scene::Shell::Space, {"b"}), b("b", scene::Shell::Space, {"a"});
    EXPECT_THROW(scene::inCompositingOrder({&a, &b}), std::logic_error);
}

TEST(CompositingOrder, EveryRegisteredComponentDeclaresAShellAndNoShellHasACycle)
{
    const std::vector<const scene::Component*> all(components::registry().begin(), components::registry().end());
    const std::vector<const scene::Component*> ordered = scene::inCompositingOrder(all);
    ASSERT_EQ(ordered.size(), all.size());
    for (size_t i = 1; i < ordered.size(); ++i)
        EXPECT_LE(ordered[i - 1]->shell(), ordered[i]->shell()) << names(ordered);
}
