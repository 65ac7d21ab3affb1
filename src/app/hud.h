#pragma once
// The heads-up display's text: what the master shows over the wall's first screen and the console
// when H is pressed. A pure function of the last frame's statistics and the camera; the master sends
// the lines in the frame's broadcast (cluster::FrameMessage::hud) and render/hud_font draws them.
#include <string>
#include <vector>

namespace aurorawall::app {

struct HudFacts {
    double framesPerS = 0.0;          // the master's rate over the last frame (0: none yet)
    std::vector<double> rankRenderMs; // each rank's render time of the last frame, rank order
    double timeS = 0.0;               // animation time
    bool paused = false;
    double altitudeKm = 0.0, latitudeDeg = 0.0, longitudeDeg = 0.0; // the camera's
};

constexpr int kHudBarCells = 16; // a rank's bar at the slowest rank's time

// The lines, in the HUD font's characters (capitals, digits, ". - + : / = ( ) #"), at most
// cluster::kHudLines of at most cluster::kHudColumns:
//   FPS 9.5  T 120.00 S
//   ALT 0.500 KM
//   LAT 65.000 LON 15.000
//   IMBALANCE 1.22 (MAX/MEAN)
//   R0  ################ 43.2 MS      one per rank: the bar is kHudBarCells x its time / the slowest,
//   R1  ##########       27.0 MS      rounded; ranks that do not fit are counted on a last line
std::vector<std::string> hudLines(const HudFacts& facts);

} // namespace aurorawall::app
