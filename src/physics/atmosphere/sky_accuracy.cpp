#include "physics/atmosphere/sky_accuracy.h"

#include "physics/constants.h"

#include <cmath>

namespace aurorawall::physics::atmosphere {

namespace {

double radians(double degrees) { return degrees * physics::kPi / 180.0; }

} // namespace

TwilightFrame twilightFrame()
{
    glm::dvec3 up = glm::normalize(glm::dvec3(0.3, -0.5, 0.81));
    glm::dvec3 north = glm::normalize(glm::dvec3(0.0, 0.0, 1.0) - up.z * up);
    return {up, north, glm::cross(north, up)};
}

glm::dvec3 twilightDirection(double azimuthDegrees, double elevationDegrees)
{
    TwilightFrame frame = twilightFrame();
    double a = radians(azimuthDegrees), e = radians(elevationDegrees);
    return std::cos(e) * (std::cos(a) * frame.north + std::sin(a) * frame.east) + std::sin(e) * frame.up;
}

std::vector<SkyView> twilightViews(double eyeHeightKm)
{
    const glm::dvec3 origin = (SkyAtmosphereParameters().planetRadiusKm + eyeHeightKm) * twilightFrame().up;
    std::vector<SkyView> views;
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0)
        for (double elevation : {0.0, 1.0, 3.0, 10.0, 30.0, 60.0})
            views.push_back({origin, twilightDirection(azimuth, elevation), 1e30});
    views.push_back({origin, twilightDirection(0.0, 90.0), 1e30});
    return views;
}

std::vector<SkyLight> twilightSuns(int count)
{
    const double solarIlluminanceLux = 1.28e5;
    std::vector<SkyLight> suns;
    for (int i = 0; i < count; ++i) {
        double f = count > 1 ? double(i) / double(count - 1) : 0.5;
        suns.push_back({twilightDirection(20.0 * f, -2.0 - 6.0 * f), glm::dvec3(solarIlluminanceLux / count)});
    }
    return suns;
}

std::vector<glm::dvec3> skyRadiances(const std::vector<SkyView>& views, const SkyAtmosphereParameters& atmosphere,
                                     const std::vector<SkyLight>& lights, SkyLightMethod method, int viewSteps,
                                     int lightSteps, AirmassPrecision precision)
{
    std::vector<glm::dvec3> radiances;
    for (const SkyView& view : views)
        radiances.push_back(skyRadiance(view, atmosphere, lights, method, viewSteps, lightSteps, precision));
    return radiances;
}

RelativeErrors skyErrors(const std::vector<glm::dvec3>& values, const std::vector<glm::dvec3>& reference)
{
    std::vector<double> flatValues, flatReference;
    for (size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            flatValues.push_back(values[i][c]);
            flatReference.push_back(reference[i][c]);
        }
    RelativeErrors errors = relativeErrors(flatValues, flatReference, kSkyRadianceFloor);
    errors.worstIndex /= 3;
    return errors;
}

} // namespace aurorawall::physics::atmosphere
