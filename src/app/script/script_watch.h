// A scripted viewer stopped from outside (`timeout`'s TERM, Ctrl+C, a CI job's limit) says where
// its script stood before it goes: the command last run, what the viewer was waiting for, how many
// frames it drew and how long ago the last one began. Frames that go on mean a wait that never
// ends; a frame that began long ago means the viewer is stuck inside it.
#pragma once

#include <string_view>

namespace luz::app::script_watch {

// Installs the handlers of SIGTERM and SIGINT, and makes stdout line-buffered so that what the
// script printed before the signal ("saved ...") is in its log too.
void install();

// Where the script stands now, e.g. "radiosity.txt:15 `wait-shots 5`, waiting for: radiosity
// shots"; kept for the handler (its first 512 bytes).
void at(std::string_view where);

// A frame begins: counted, and its time kept.
void frame_begins();

}  // namespace luz::app::script_watch
