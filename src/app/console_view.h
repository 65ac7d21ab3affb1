#pragma once
// The master's console window (render --console): the whole gathered wall, downsampled to
// kConsoleWidthPx wide at the wall's aspect, shown each frame with the HUD. It is one more window of
// the master's GLFW context, so its keys and drags reach the navigation like any window's.
#include "gl/full_screen_triangle.h"
#include "gl/texture.h"
#include "io/image.h"
#include "wall/wall.h"

#include <memory>
#include <vector>

namespace aurorawall::app {

constexpr int kConsoleWidthPx = 480;

struct ConsoleView {
    int window = 0; // in the master's context, after its screens' windows
    std::unique_ptr<gl::Texture> image; // the downsampled wall, RGBA32F
    std::unique_ptr<gl::FullScreenTriangle> triangle;
};

// The console's height for a canvas of canvasWidth x canvasHeight pixels: the same aspect, at least 1.
int consoleHeightPx(int canvasWidth, int canvasHeight);

// Where the console opens on the master's desktop: windowed walls put every screen's window on one
// desktop, so the console goes just below the lowest of them, at the leftmost one's x, covering none;
// {-1, -1} (the window system chooses) when every screen is fullscreen.
glm::ivec2 consolePositionPx(const wall::Wall& wall);

// The canvas (rows top-down) averaged over boxes into width x height pixels as RGBA floats with rows
// bottom-up (a texture's upload order): each console pixel the mean of the canvas pixels whose centres
// fall into it (the nearest one when none does, as when enlarging). Throws std::invalid_argument for
// an empty canvas or size.
std::vector<float> previewTexels(const io::Image& canvas, int width, int height);

} // namespace aurorawall::app
