#pragma once
// The heads-up display's font: a fixed 5x7 bitmap font (the glyph shapes of the HD44780 character
// LCD's ROM) for the digits, the capital letters and a few symbols, drawn into a coverage mask that
// the window's display shader lays over the image. '#' is a full 5x7 block (the HUD's bars).
#include <string>
#include <vector>

namespace aurorawall::render {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
constexpr int kCellWidth = 6, kCellHeight = 9; // a glyph and the space after it and below it
constexpr int kHudMarginPx = 2;                // around the text, in mask pixels

// Whether the font has a glyph for `c` (lower-case letters have none).
bool hasGlyph(char c);

// The lines as mask pixels, rows top-down: 1 where a glyph's dot is, 0 elsewhere (the box behind
// the text). Width kCellWidth x the longest line + 2 margins, height kCellHeight x lines + 2
// margins. Throws std::invalid_argument for a character without a glyph.
struct HudMask {
    int width = 0, height = 0;
    std::vector<float> coverage; // width x height, x fastest
};
HudMask rasterizeHud(const std::vector<std::string>& lines);

} // namespace aurorawall::render
