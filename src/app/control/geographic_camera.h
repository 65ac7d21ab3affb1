#pragma once
// The camera in the words of a person at the wall: where it is (latitude, longitude, altitude above
// the planet's sphere) and where it looks (heading clockwise from north, pitch above the local
// horizontal), and back, in the planet frame of common/planet_frame.h.
#include "scene/scene.h"

namespace aurorawall::app::control {

struct GeographicPose {
    double latitudeDeg = 0.0;
    double longitudeDeg = 0.0; // in [-180, 180]
    double altitudeKm = 0.0;   // above the sphere of the planet's radius
    double headingDeg = 0.0;   // in [0, 360): 0 north, 90 east
    double pitchDeg = 0.0;     // in [-90, 90]: 0 the horizon, 90 the zenith
};

// The pose of `camera` over a planet of radius planetRadiusKm. The camera must not be at the centre.
GeographicPose poseOf(const scene::Camera& camera, double planetRadiusKm);

// A camera at that pose (the construction of the scene files' geographic [camera]: up is the zenith
// made perpendicular to the view; looking straight up or down, up is the heading's direction), with
// the given speed along its view.
scene::Camera cameraAt(const GeographicPose& pose, double planetRadiusKm, double speedKmPerS);

} // namespace aurorawall::app::control
