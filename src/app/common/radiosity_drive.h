#pragma once
// How the viewer drives the radiosity solver: it shoots on the GL thread, a share per frame, so
// the window stays interactive while the light spreads (DESIGN.md, Threads). The radiosity view
// owns one; the lessons start from its defaults.
//
// Also the words of the `radiosity` script verb that set something, in one place for the
// radiosity view (which runs them), the lessons (which write them for every step) and the
// handouts (which play them headless).

#include <span>
#include <string_view>

#include "radiosity/radiosity_options.h"

namespace luz::app {

struct RadiosityDrive {
  bool running = false;
  bool by_time = true;        // a time budget per frame (else a number of shots per frame)
  float budget_ms = 15.0f;    // shooting time per frame while running
  // The budget was chosen (`radiosity budget MS`, the panel's slider): each frame shoots it and
  // no more, so a lesson or a test sees as many shots a frame as it asked for. Left at its
  // default, a viewer that paces its frames (the page's) shoots between them too.
  bool budget_chosen = false;
  int shots_per_frame = 10;
  bool heat_map = false;      // show the unshot power per patch instead of B/pi
  bool show_shooter = true;   // the last shooter in magenta
  bool show_item_buffer = true;  // the small window with its hemicube's five faces
};

// `radiosity NAME on|off|toggle`: a switch of the display or of the solver's options (a row of
// the options table too), or of the drive (the window's alone).
struct RadiositySwitch {
  const char* name;
  bool RadiosityOptions::*option;  // one of the two is set
  bool RadiosityDrive::*drive;
  const char* note;  // what the window says when it is switched ("radiosity heat map" + on/off), a message id, or nullptr
};
std::span<const RadiositySwitch> radiosity_switches();
const RadiositySwitch* find_radiosity_switch(std::string_view name);

// The options table's rows that `radiosity NAME VALUE` sets and that make a new mesh (or other
// form factors), so that the solution starts over (slide 40).
std::span<const char* const> radiosity_mesh_settings();
bool is_radiosity_mesh_setting(std::string_view name);

}  // namespace luz::app
