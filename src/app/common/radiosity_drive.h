#pragma once
// How the viewer drives the radiosity solver: it shoots on the GL thread, a share per frame, so
// the window stays interactive while the light spreads (DESIGN.md, Threads). The radiosity view
// owns one; the lessons start from its defaults.

namespace luz::app {

struct RadiosityDrive {
  bool running = false;
  bool by_time = true;        // a time budget per frame (else a number of shots per frame)
  float budget_ms = 15.0f;    // shooting time per frame while running
  int shots_per_frame = 10;
  bool heat_map = false;      // show the unshot power per patch instead of B/pi
  bool show_shooter = true;   // the last shooter in magenta
  bool show_item_buffer = true;  // the small window with its hemicube's five faces
};

}  // namespace luz::app
