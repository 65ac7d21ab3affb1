#include "app/console_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace aurorawall::app {

int consoleHeightPx(int canvasWidth, int canvasHeight)
{
    return std::max(1, static_cast<int>(std::lround(double(kConsoleWidthPx) * canvasHeight / canvasWidth)));
}

glm::ivec2 consolePositionPx(const wall::Wall& wall)
{
    bool windowed = false;
    glm::ivec2 position{std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
    for (const wall::Screen& screen : wall.screens) {
        const wall::WindowPlacement& w = screen.window;
        if (w.fullscreen)
            continue;
        windowed = true;
        const int height = w.height > 0 ? w.height : screen.heightPx;
        position.x = std::min(position.x, w.x);
        position.y = std::max(position.y, w.y + height);
    }
    return windowed ? position : glm::ivec2{-1, -1};
}

namespace {

// The canvas pixels [first, end) whose centres fall into console pixel i of n over `size` pixels;
// at least the nearest one.
void span(int i, int n, int size, int& first, int& end)
{
    const double scale = double(size) / n;
    first = static_cast<int>(std::ceil(i * scale - 0.5));
    end = static_cast<int>(std::ceil((i + 1) * scale - 0.5));
    if (end <= first) {
        first = std::min(size - 1, static_cast<int>((i + 0.5) * scale));
        end = first + 1;
    }
}

} // namespace

std::vector<float> previewTexels(const io::Image& canvas, int width, int height)
{
    if (canvas.width <= 0 || canvas.height <= 0 || width <= 0 || height <= 0)
        throw std::invalid_argument("console preview: an empty canvas or size");
    std::vector<float> texels(4 * std::size_t(width) * height);
    for (int y = 0; y < height; ++y) {
        int y0 = 0, y1 = 0;
        span(y, height, canvas.height, y0, y1);
        for (int x = 0; x < width; ++x) {
            int x0 = 0, x1 = 0;
            span(x, width, canvas.width, x0, x1);
            double sum[4] = {0, 0, 0, 0};
            for (int cy = y0; cy < y1; ++cy)
                for (int cx = x0; cx < x1; ++cx)
                    for (int c = 0; c < 4; ++c)
                        sum[c] += canvas.pixel(cx, cy)[c];
            const double count = double(y1 - y0) * (x1 - x0);
            float* out = &texels[4 * (std::size_t(height - 1 - y) * width + x)]; // bottom-up
            for (int c = 0; c < 4; ++c)
                out[c] = static_cast<float>(sum[c] / count);
        }
    }
    return texels;
}

} // namespace aurorawall::app
