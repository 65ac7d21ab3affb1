// The curtain field's per-frame rebuild (EGL; Mesa llvmpipe in CI): the polylines and the footprint map
// are rebuilt exactly when the keyframed control points change, and the textures kept from earlier
// frames then hold the same bytes as those of a field that saw only this frame.
#include "components/aurora/curtain_field.h"
#include "gl/context.h"
#include "gl/functions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace aurorawall;
using components::aurora::CurtainField;

namespace {

// One arc over Scandinavia moving 2 degrees poleward between 10 s and 20 s, brightening until 30 s
// (its flux changes after its control points have stopped).
components::aurora::Settings movingArc()
{
    components::aurora::Settings s;
    s.footprintMapSize = 256;
    components::aurora::Curtain c;
    c.thicknessKm = 2.0;
    components::aurora::CurtainKey a;
    a.timeS = 10.0;
    a.pointsLatLonDeg = {{65.0, 0.0}, {65.5, 10.0}, {65.0, 20.0}};
    a.energyKeV = 4.0;
    a.energyFluxErgPerCm2S = 1.0;
    components::aurora::CurtainKey b = a;
    b.timeS = 20.0;
    b.pointsLatLonDeg = {{67.0, 0.0}, {67.5, 10.0}, {67.0, 20.0}};
    components::aurora::CurtainKey bright = b;
    bright.timeS = 30.0;
    bright.energyFluxErgPerCm2S = 5.0;
    c.keys = {a, b, bright};
    s.curtains = {c};
    return s;
}

std::vector<float> readBack(const gl::Texture& t)
{
    std::vector<float> texels(size_t(t.width()) * t.height() * 4);
    gl::glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

bool rebuilt(const CurtainField& field) { return field.summary().find(", rebuilt:") != std::string::npos; }

} // namespace

TEST(CurtainField, RebuildsExactlyWhenTheControlPointsChange)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    CurtainField field(model);
    field.update(0.0);
    EXPECT_TRUE(rebuilt(field));
    field.update(5.0); // before the first key: held still
    EXPECT_FALSE(rebuilt(field));
    field.update(12.0);
    EXPECT_TRUE(rebuilt(field));
    field.update(12.0);
    EXPECT_FALSE(rebuilt(field));
    field.update(12.5);
    EXPECT_TRUE(rebuilt(field));
    field.update(22.0);
    field.update(25.0); // only the flux moves
    EXPECT_FALSE(rebuilt(field));
    field.update(35.0);
    field.update(40.0); // after the last key: held still
    EXPECT_FALSE(rebuilt(field));
}

TEST(CurtainField, KeptTexturesHoldTheBytesOfAFreshBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    CurtainField running(model);
    for (double t : {11.0, 13.0, 17.0, 25.0}) {
        running.update(t);
        CurtainField fresh(model);
        fresh.update(t);
        EXPECT_EQ(readBack(running.footprintMap()), readBack(fresh.footprintMap())) << "t = " << t;
        EXPECT_EQ(readBack(running.polylines()), readBack(fresh.polylines())) << "t = " << t;
    }
}
