#pragma once
// What the browser console hands out as a download.
#include <string>

namespace aurorawall::app::web {

// A recorded camera path (PathRecorder's text, a scene deriving from the played one through
// [scene] base, named relative to `folder`, the recording's) as one self-contained scene: the base
// scenes' tables embedded, so that the copy replays on any machine, wherever it is saved, with no
// other file. The derivation is resolved as the scene reader does it (docs/scenes.md): [scene] key
// by key, [camera] whole from the last file that gives one, a component's table key by key (its
// arrays of tables, such as [[aurora.curtain]], whole), tables of components no longer listed
// dropped. Text without a base is returned as it is. Throws std::runtime_error naming the file
// that cannot be read or parsed (a base scene moved away since the recording).
std::string recordingForDownload(const std::string& text, const std::string& folder);

} // namespace aurorawall::app::web
