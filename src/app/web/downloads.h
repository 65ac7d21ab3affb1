#pragma once
// What the browser console hands out as a download.
#include <string>

namespace aurorawall::app::web {

// A recorded camera path (PathRecorder's text) as the downloaded copy needs it: its [scene] base,
// written relative to the recording's folder, made absolute from `folder`, so that the copy replays
// wherever it is saved on this machine. Any other text is returned as it is.
std::string recordingForDownload(const std::string& text, const std::string& folder);

} // namespace aurorawall::app::web
