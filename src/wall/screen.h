#pragma once
// One display of the wall: its pixels, its active area in the wall plane, the rank that drives it
// and where its window goes.
//
// Wall frame: millimetres, x right, y up, z out of the wall toward the viewer. The wall is flat:
// every screen lies in the plane z = 0.
#include <glm/glm.hpp>
#include <string>

namespace aurorawall::wall {

// Where the GLFW backend opens a screen's window: at a desktop position, or fullscreen on a monitor.
struct WindowPlacement {
    int x = -1, y = -1;          // desktop position of the window's top-left corner (windowed)
    int width = -1, height = -1; // window size in desktop pixels (windowed); -1: the screen's pixel size
    int monitor = -1;            // GLFW monitor index (fullscreen)
    bool fullscreen = false;
};

// The eye a screen shows: the wall's eye, or it moved half the interocular distance to the left or
// right along the wall's x axis (stereo); sideBySide: the left eye's view of the whole screen
// squeezed into its left half of the pixels, the right eye's into its right half.
enum class Eye { centre, left, right, sideBySide };

struct Screen {
    std::string name;
    int widthPx = 0, heightPx = 0;
    double widthMm = 0.0, heightMm = 0.0; // active area: the lit pixels, bezel excluded
    glm::dvec2 lowerLeftMm{0.0};          // active area's lower-left corner in the wall plane
    int rank = 0;                         // MPI rank that renders and shows this screen
    WindowPlacement window;
    glm::ivec2 canvasOffsetPx{0};         // this screen's top-left pixel in the wall canvas, x right, y DOWN
    Eye eye = Eye::centre;

    glm::dvec3 lowerLeft() const { return {lowerLeftMm, 0.0}; }
    glm::dvec3 lowerRight() const { return {lowerLeftMm.x + widthMm, lowerLeftMm.y, 0.0}; }
    glm::dvec3 upperLeft() const { return {lowerLeftMm.x, lowerLeftMm.y + heightMm, 0.0}; }
    glm::dvec3 upperRight() const { return {lowerLeftMm.x + widthMm, lowerLeftMm.y + heightMm, 0.0}; }
    // Millimetres per pixel along x and y.
    glm::dvec2 pixelPitchMm() const { return {widthMm / widthPx, heightMm / heightPx}; }
};

} // namespace aurorawall::wall
