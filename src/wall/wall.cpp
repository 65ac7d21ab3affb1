#include "wall/wall.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace aurorawall::wall {

std::vector<int> Wall::screensOfRank(int rank) const
{
    std::vector<int> indices;
    for (int i = 0; i < int(screens.size()); ++i)
        if (screens[i].rank == rank)
            indices.push_back(i);
    return indices;
}

glm::dvec3 Wall::eyePosition(Eye eye) const
{
    const double side = eye == Eye::left ? -0.5 : eye == Eye::right ? 0.5 : 0.0;
    return eyeMm + glm::dvec3(side * interocularMm, 0.0, 0.0);
}

namespace {

bool nearlyEqual(double a, double b, double relative) { return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)); }

// A screen's offset from the canvas's top-left corner in pixels of the given pitch (x right, y down).
glm::dvec2 offsetInPixels(const Screen& s, glm::dvec2 topLeftMm, glm::dvec2 pitchMm)
{
    return {(s.lowerLeftMm.x - topLeftMm.x) / pitchMm.x, (topLeftMm.y - (s.lowerLeftMm.y + s.heightMm)) / pitchMm.y};
}

} // namespace

Wall assembleWall(std::vector<Screen> screens, glm::dvec3 eyeMm, std::string sourceFile)
{
    if (screens.empty())
        throw std::invalid_argument("a wall needs at least one screen");
    Wall wall;
    wall.sourceFile = std::move(sourceFile);
    wall.eyeMm = eyeMm;

    double minX = std::numeric_limits<double>::infinity(), maxY = -minX;
    glm::dvec2 finest = screens.front().pixelPitchMm();
    bool samePitch = true;
    for (const Screen& s : screens) {
        minX = std::min(minX, s.lowerLeftMm.x);
        maxY = std::max(maxY, s.lowerLeftMm.y + s.heightMm);
        const glm::dvec2 pitch = s.pixelPitchMm();
        samePitch = samePitch && nearlyEqual(pitch.x, screens.front().pixelPitchMm().x, 1e-9)
                    && nearlyEqual(pitch.y, screens.front().pixelPitchMm().y, 1e-9);
        finest = glm::min(finest, pitch);
    }
    wall.canvasTopLeftMm = {minX, maxY};
    // Finest pitch: a coarser screen covers fewer pixels than its physical extent, so rounded
    // positions in this pitch never make screens overlap in the gathered image.
    wall.canvasPitchMm = samePitch ? screens.front().pixelPitchMm() : finest;

    bool wholePixels = true;
    for (const Screen& s : screens) {
        const glm::dvec2 offset = offsetInPixels(s, wall.canvasTopLeftMm, wall.canvasPitchMm);
        const glm::dvec2 far = offset + glm::dvec2(s.widthPx, s.heightPx);
        if (far.x > maxCanvasPx || far.y > maxCanvasPx)
            throw std::invalid_argument("the wall canvas is more than " + std::to_string(maxCanvasPx) +
                                        " pixels across; are the sizes in millimetres?");
        const glm::dvec2 rounded = glm::round(offset);
        wholePixels = wholePixels && glm::all(glm::lessThanEqual(glm::abs(offset - rounded), glm::dvec2(1e-6)));
    }
    wall.sharedCanvas = samePitch && wholePixels;

    for (Screen& s : screens) {
        s.canvasOffsetPx = glm::ivec2(glm::round(offsetInPixels(s, wall.canvasTopLeftMm, wall.canvasPitchMm)));
        wall.canvasSizePx = glm::max(wall.canvasSizePx, s.canvasOffsetPx + glm::ivec2(s.widthPx, s.heightPx));
        wall.rankCount = std::max(wall.rankCount, s.rank + 1);
    }
    // Two eyes: the right eye's screens move to a second copy of the canvas on the right.
    const auto isRight = [](const Screen& s) { return s.eye == Eye::right; };
    if (std::any_of(screens.begin(), screens.end(), isRight) && !std::all_of(screens.begin(), screens.end(), isRight)) {
        wall.rightEyeCanvasShiftPx = wall.canvasSizePx.x;
        if (2 * wall.canvasSizePx.x > maxCanvasPx)
            throw std::invalid_argument("the stereo wall canvas is more than " + std::to_string(maxCanvasPx) + " pixels across");
        for (Screen& s : screens)
            if (isRight(s))
                s.canvasOffsetPx.x += wall.rightEyeCanvasShiftPx;
        wall.canvasSizePx.x *= 2;
    }
    wall.screens = std::move(screens);
    return wall;
}

Wall makeGridWall(const GridSpec& grid)
{
    const int stacked = grid.stacking == Stacking::vertical ? grid.rows : grid.columns;
    if (grid.columns < 1 || grid.rows < 1 || grid.screensPerRank < 1 || stacked % grid.screensPerRank != 0)
        throw std::invalid_argument("makeGridWall: screensPerRank must divide the stacked grid dimension");
    const glm::dvec2 step = grid.screenMm + grid.bezelMm;
    const glm::dvec2 size = glm::dvec2(grid.columns, grid.rows) * step - grid.bezelMm;

    std::vector<Screen> screens;
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            Screen s;
            s.name = "r" + std::to_string(row) + "c" + std::to_string(column);
            s.widthPx = grid.screenPx.x;
            s.heightPx = grid.screenPx.y;
            s.widthMm = grid.screenMm.x;
            s.heightMm = grid.screenMm.y;
            s.lowerLeftMm = {column * step.x, (grid.rows - 1 - row) * step.y};
            // Groups of screensPerRank screens, numbered row-major over the grid of groups.
            if (grid.stacking == Stacking::vertical)
                s.rank = (row / grid.screensPerRank) * grid.columns + column;
            else
                s.rank = row * (grid.columns / grid.screensPerRank) + column / grid.screensPerRank;
            screens.push_back(s);
        }
    Wall wall = assembleWall(std::move(screens), glm::dvec3(size / 2.0, 0.0) + grid.eyeFromCentreMm);
    placeWindowsOnCanvas(wall);
    return wall;
}

Wall singleScreenEquivalent(const Wall& wall)
{
    Screen s;
    s.name = "whole-wall";
    s.widthPx = wall.canvasSizePx.x - wall.rightEyeCanvasShiftPx;
    s.heightPx = wall.canvasSizePx.y;
    s.widthMm = s.widthPx * wall.canvasPitchMm.x;
    s.heightMm = wall.canvasSizePx.y * wall.canvasPitchMm.y;
    s.lowerLeftMm = {wall.canvasTopLeftMm.x, wall.canvasTopLeftMm.y - s.heightMm};
    // A wall of one eye keeps it (a side-by-side screen stays one, split at its middle column).
    const Eye firstEye = wall.screens.front().eye;
    if (std::all_of(wall.screens.begin(), wall.screens.end(), [&](const Screen& x) { return x.eye == firstEye; }))
        s.eye = firstEye;
    std::vector<Screen> screens{s};
    if (wall.rightEyeCanvasShiftPx > 0) {
        screens[0].name = "whole-wall-left";
        screens[0].eye = Eye::left;
        s.name = "whole-wall-right";
        s.eye = Eye::right;
        screens.push_back(s);
    }
    Wall single = assembleWall(std::move(screens), wall.eyeMm, wall.sourceFile);
    single.interocularMm = wall.interocularMm;
    single.projection = wall.projection;
    single.dome = wall.dome;
    placeWindowsOnCanvas(single);
    return single;
}

void placeWindowsOnCanvas(Wall& wall, glm::ivec2 desktopOriginPx, double scale)
{
    for (Screen& s : wall.screens) {
        s.window = WindowPlacement{};
        s.window.x = desktopOriginPx.x + int(std::lround(scale * s.canvasOffsetPx.x));
        s.window.y = desktopOriginPx.y + int(std::lround(scale * s.canvasOffsetPx.y));
        s.window.width = std::max(1, int(std::lround(scale * s.widthPx)));
        s.window.height = std::max(1, int(std::lround(scale * s.heightPx)));
    }
}

} // namespace aurorawall::wall
