// The curtain field's per-frame rebuild (EGL; Mesa llvmpipe in CI), with the footprint map built on the
// CPU and on the GPU: the polylines and the map are rebuilt exactly when the keyframed control points
// change, and the textures kept from earlier frames, built ahead or uploaded ahead while a frame drew,
// then hold the same bytes as those of a field that saw only this frame.
#include "components/aurora/curtain_field.h"
#include "gl/context.h"
#include "gl/functions.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace aurorawall;
using components::aurora::CurtainField;
using components::aurora::MapBuilder;

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

const std::string kShaders = std::string(AURORAWALL_SOURCE_DIR) + "/shaders";

constexpr double unknownNext = std::numeric_limits<double>::quiet_NaN(); // a lone frame: nothing built ahead

bool rebuilt(const CurtainField& field) { return field.summary().find(", rebuilt:") != std::string::npos; }

class CurtainFieldBuiltOn : public testing::TestWithParam<MapBuilder> {};

} // namespace

INSTANTIATE_TEST_SUITE_P(MapBuilders, CurtainFieldBuiltOn, testing::Values(MapBuilder::Cpu, MapBuilder::Gpu),
                         [](const testing::TestParamInfo<MapBuilder>& info) {
                             return std::string(info.param == MapBuilder::Cpu ? "Cpu" : "Gpu");
                         });

TEST_P(CurtainFieldBuiltOn, RebuildsExactlyWhenTheControlPointsChange)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    CurtainField field(model, GetParam(), kShaders);
    field.update(0.0, unknownNext);
    EXPECT_TRUE(rebuilt(field));
    field.update(5.0, unknownNext); // before the first key: held still
    EXPECT_FALSE(rebuilt(field));
    field.update(12.0, unknownNext);
    EXPECT_TRUE(rebuilt(field));
    field.update(12.0, unknownNext);
    EXPECT_FALSE(rebuilt(field));
    field.update(12.5, unknownNext);
    EXPECT_TRUE(rebuilt(field));
    field.update(22.0, unknownNext);
    field.update(25.0, unknownNext); // only the flux moves
    EXPECT_FALSE(rebuilt(field));
    field.update(35.0, unknownNext);
    field.update(40.0, unknownNext); // after the last key: held still
    EXPECT_FALSE(rebuilt(field));
}

TEST_P(CurtainFieldBuiltOn, KeptTexturesHoldTheBytesOfAFreshBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    CurtainField running(model, GetParam(), kShaders);
    for (double t : {11.0, 13.0, 17.0, 25.0}) {
        running.update(t, unknownNext);
        CurtainField fresh(model, GetParam(), kShaders);
        fresh.update(t, unknownNext);
        EXPECT_EQ(readBack(running.footprintMap()), readBack(fresh.footprintMap())) << "t = " << t;
        EXPECT_EQ(readBack(running.polylines()), readBack(fresh.polylines())) << "t = " << t;
    }
}

// Frames that announce their successor's time (cluster::FrameState::nextTimeS), at fixed steps and
// at the uneven steps of a real-time clock: from the second frame on every rebuild takes the build
// made ahead on the worker thread, and its textures hold the bytes of a field that built only this
// frame itself.
TEST_P(CurtainFieldBuiltOn, BuildAheadHoldsTheBytesOfTheFramesOwnBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    for (const std::vector<double>& times : {std::vector<double>{12.0, 12.5, 13.0, 13.5, 14.0, 14.5},
                                             std::vector<double>{12.0, 12.031, 12.097, 12.112, 12.3, 13.9}}) {
        CurtainField running(model, GetParam(), kShaders);
        for (size_t n = 0; n < times.size(); ++n) {
            const double t = times[n];
            running.update(t, n + 1 < times.size() ? times[n + 1] : unknownNext);
            EXPECT_EQ(running.rebuilds(), n + 1);
            EXPECT_EQ(running.rebuildsBuiltAhead(), n) << "t = " << t;
            CurtainField fresh(model, GetParam(), kShaders);
            fresh.update(t, unknownNext);
            EXPECT_EQ(fresh.rebuildsBuiltAhead(), 0u);
            EXPECT_EQ(readBack(running.footprintMap()), readBack(fresh.footprintMap())) << "t = " << t;
            EXPECT_EQ(readBack(running.polylines()), readBack(fresh.polylines())) << "t = " << t;
        }
    }
}

// The same with the upload while each frame draws (uploadAhead, as BandFrame calls it after the frame's
// first draw): the frame's own textures are left as they are; where the CPU builds the map, the next
// update only swaps in the textures uploaded ahead, which hold the bytes of the frame's own build (the
// GPU builds its map at the update: nothing is uploaded ahead).
TEST_P(CurtainFieldBuiltOn, UploadWhileDrawingHoldsTheBytesOfTheFramesOwnBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    const std::vector<double> times{12.0, 12.031, 12.5, 13.0, 13.9};
    CurtainField running(model, GetParam(), kShaders);
    for (size_t n = 0; n < times.size(); ++n) {
        const double t = times[n];
        running.update(t, n + 1 < times.size() ? times[n + 1] : unknownNext);
        EXPECT_EQ(running.rebuildsBuiltAhead(), n) << "t = " << t;
        EXPECT_EQ(running.rebuildsUploadedAhead(), GetParam() == MapBuilder::Cpu ? n : 0u) << "t = " << t;
        CurtainField fresh(model, GetParam(), kShaders);
        fresh.update(t, unknownNext);
        const std::vector<float> map = readBack(fresh.footprintMap()), polylines = readBack(fresh.polylines());
        EXPECT_EQ(readBack(running.footprintMap()), map) << "t = " << t;
        EXPECT_EQ(readBack(running.polylines()), polylines) << "t = " << t;
        running.uploadAhead(); // the frame draws
        EXPECT_EQ(readBack(running.footprintMap()), map) << "t = " << t << ", after the upload ahead";
        EXPECT_EQ(readBack(running.polylines()), polylines) << "t = " << t << ", after the upload ahead";
    }
}

// Once the curtains hold still (from 20 s the arc's control points stay), a field whose last build was
// swapped in from the upload ahead keeps it: no rebuild.
TEST_P(CurtainFieldBuiltOn, HoldsStillAfterASwappedInBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    CurtainField running(model, GetParam(), kShaders);
    for (const auto& [t, next] : std::vector<std::pair<double, double>>{{19.0, 19.5}, {19.5, 20.5}, {20.5, 21.0}}) {
        running.update(t, next);
        running.uploadAhead();
    }
    EXPECT_EQ(running.rebuildsUploadedAhead(), GetParam() == MapBuilder::Cpu ? 2u : 0u);
    running.update(21.0, 22.0);
    EXPECT_FALSE(rebuilt(running));
    running.uploadAhead();
    running.update(22.0, unknownNext);
    EXPECT_FALSE(rebuilt(running));
    EXPECT_EQ(running.rebuilds(), 3u);
}

// A command changed the next frame's time (the master announced 16 s, then a new time of 15.7 s was
// set): the build made ahead is dropped, or where it was uploaded while the frame before drew
// (uploadAhead), not swapped in, and the frame builds its own curtains, equal to a fresh field's.
TEST_P(CurtainFieldBuiltOn, WrongPredictionBuildsTheFrameItself)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    for (bool uploadWhileDrawing : {false, true}) {
        CurtainField running(model, GetParam(), kShaders);
        const auto frame = [&](double t, double next) {
            running.update(t, next);
            if (uploadWhileDrawing)
                running.uploadAhead();
        };
        // Where the CPU builds the map, each build made ahead is also uploaded ahead.
        const size_t uploaded = uploadWhileDrawing && GetParam() == MapBuilder::Cpu ? 1 : 0;
        frame(15.0, 15.5);
        frame(15.5, 16.0); // uploads 16 s ahead, which the next frame will not show
        EXPECT_EQ(running.rebuildsBuiltAhead(), 1u);
        running.update(15.7, 16.1);
        EXPECT_EQ(running.rebuildsBuiltAhead(), 1u);
        EXPECT_EQ(running.rebuildsUploadedAhead(), uploaded);
        CurtainField fresh(model, GetParam(), kShaders);
        fresh.update(15.7, unknownNext);
        EXPECT_EQ(readBack(running.footprintMap()), readBack(fresh.footprintMap()));
        EXPECT_EQ(readBack(running.polylines()), readBack(fresh.polylines()));
        if (uploadWhileDrawing)
            running.uploadAhead();
        running.update(16.1, unknownNext); // the announced time came: built ahead
        EXPECT_EQ(running.rebuildsBuiltAhead(), 2u);
        EXPECT_EQ(running.rebuildsUploadedAhead(), 2 * uploaded);
        EXPECT_EQ(running.rebuilds(), 4u);
        CurtainField atTheTime(model, GetParam(), kShaders);
        atTheTime.update(16.1, unknownNext);
        EXPECT_EQ(readBack(running.footprintMap()), readBack(atTheTime.footprintMap()));
        EXPECT_EQ(readBack(running.polylines()), readBack(atTheTime.polylines()));
    }
}

// The GL-free half of the build: buildCurtains made on a worker thread equals the same call on
// this thread, byte for byte (texels and polylines), at times where the curtains move.
TEST(CurtainField, BuildOnAWorkerThreadEqualsTheSameBuildHere)
{
    const components::aurora::Settings settings = movingArc();
    const components::aurora::CurtainModel model(settings, 6371.0, nullptr);
    components::aurora::CurtainBuildAhead ahead(model, MapBuilder::Cpu);
    for (double t : {11.0, 13.25, 19.5}) {
        const auto states = model.statesAt(t);
        const components::aurora::CurtainBuild here = components::aurora::buildCurtains(model, states, MapBuilder::Cpu);
        ahead.start(states);
        const auto there = ahead.take(components::aurora::controlPointsOf(states));
        ASSERT_TRUE(there.has_value()) << "t = " << t;
        EXPECT_EQ(there->polylineTexels, here.polylineTexels) << "t = " << t;
        EXPECT_EQ(there->map.texels, here.map.texels) << "t = " << t;
        EXPECT_EQ(there->pointCounts, here.pointCounts) << "t = " << t;
    }
    ahead.start(model.statesAt(13.0));
    EXPECT_FALSE(ahead.take(components::aurora::controlPointsOf(model.statesAt(13.5))).has_value());
}
