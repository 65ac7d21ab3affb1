#pragma once
// The physical wall: its screens, the viewer's eye, which rank drives which screen, and the wall
// canvas, the pixel space in which all screens' pixels have one global position.
//
// The wall canvas (x right, y down, origin at the top-left of the screens' bounding box):
// when every screen has the same pixel pitch (to 1e-9 relative) and every screen's offset from the
// top-left corner, divided by the pitch, is a whole number of pixels (within 1e-6 px), the canvas is
// shared: canvasOffsetPx are those integers, bezels are gaps of whole pixels, and one pixel grid
// continues across all screens (see tile_rays.h). Otherwise the canvas is not shared and
// canvasOffsetPx is the screen's position measured in the finest pitch of any screen and rounded;
// it then only places the screen in the gathered whole-wall image, where screens never overlap.
//
// Stereo: screens showing the right eye may cover the same wall area as the left eye's screens
// (passive stereo: two projectors on one screen). When a wall has right-eye screens and others,
// the canvas holds the two eyes side by side: the right eye's screens sit rightEyeCanvasShiftPx
// further right, so the gathered image is the left-eye wall next to the right-eye wall.
#include "wall/screen.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace aurorawall::wall {

// How canvas pixels become view directions: through the screens' physical geometry from the eye
// (flat), or an angular fisheye of the whole canvas (dome; see tile_rays.h).
enum class Projection { flat, dome };

struct DomeMaster {
    double fieldOfViewDeg = 180.0; // full angle across the circle inscribed in the canvas height, (0, 360]
    double tiltDeg = 0.0;          // the dome's axis above the camera's view direction, [-90, 90]
};

struct Wall {
    std::string sourceFile;          // the wall file it came from; empty when built in code
    std::vector<Screen> screens;     // grids: row-major from the top-left; lists: file order
    glm::dvec3 eyeMm{0.0};           // the viewer's eye in the wall frame, z > 0
    int rankCount = 0;               // ranks 0..rankCount-1, each driving at least one screen
    glm::ivec2 canvasSizePx{0};      // spans all screens, bezels included as gaps
    bool sharedCanvas = false;       // one pixel grid across all screens (see above)
    glm::dvec2 canvasTopLeftMm{0.0}; // wall-plane position of the canvas's top-left corner
    glm::dvec2 canvasPitchMm{0.0};   // size of one canvas pixel along x and y
    int rightEyeCanvasShiftPx = 0;   // see "Stereo" above; 0 when the canvas holds one eye
    double interocularMm = 0.0;      // distance between the left and right eye
    Projection projection = Projection::flat;
    DomeMaster dome;                 // used when projection == Projection::dome

    // Indices into screens of the screens that rank drives, in screen order.
    std::vector<int> screensOfRank(int rank) const;
    // The position of an eye: eyeMm, moved interocularMm/2 along -x (left) or +x (right).
    glm::dvec3 eyePosition(Eye eye) const;
    // The eye that screen shows (the centre one for a side-by-side screen).
    glm::dvec3 eyeOf(const Screen& screen) const { return eyePosition(screen.eye); }
};

// Largest canvas side: pixel coordinates stay far below float's 2^24 exact integers.
inline constexpr int maxCanvasPx = 1 << 20;

// Completes a wall from its screens (ranks, eyes and lower-left corners set): canvas, rank count.
// Throws std::invalid_argument for no screens or a canvas wider than maxCanvasPx.
Wall assembleWall(std::vector<Screen> screens, glm::dvec3 eyeMm, std::string sourceFile = {});

// How a grid deals groups of screens to ranks: a rank drives screensPerRank screens side by side
// (horizontal) or stacked (vertical); the groups are numbered row-major from the top-left.
enum class Stacking { horizontal, vertical };

struct GridSpec {
    int columns = 1, rows = 1;
    glm::ivec2 screenPx{1};
    glm::dvec2 screenMm{1.0};          // active area of one screen
    glm::dvec2 bezelMm{0.0};           // gap between active areas: x between columns, y between rows
    glm::dvec3 eyeFromCentreMm{0.0, 0.0, 1000.0}; // eye relative to the centre of the wall, z from the wall
    int screensPerRank = 1;
    Stacking stacking = Stacking::horizontal;
};

// A grid wall with screens named "r<row>c<column>" (row 0 at the top), windows at their canvas
// positions. Throws std::invalid_argument if screensPerRank does not divide the stacked dimension.
Wall makeGridWall(const GridSpec& grid);

// One screen covering the whole canvas with the wall's canvas pitch, the same eye and projection:
// the image a wall of any bezels cuts its screens out of. A stereo canvas gets one such screen per eye.
Wall singleScreenEquivalent(const Wall& wall);

// Windowed placement at the canvas positions: window top-left = desktopOriginPx + scale*canvasOffsetPx,
// window size = scale*screen size (both rounded).
void placeWindowsOnCanvas(Wall& wall, glm::ivec2 desktopOriginPx = {0, 0}, double scale = 1.0);

} // namespace aurorawall::wall
