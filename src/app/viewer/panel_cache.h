#pragma once
// The panel drawn once and shown on many frames. On Mesa's software rasteriser the ImGui pass
// costs its pixels, not its building: the panel's background blended over a quarter of a
// million pixels and its text take about 2 ms of a 10 ms frame, while the panel changes only
// when the user touches it (a hover, a click, a scroll). So the draw lists that fall inside the
// panel's rectangles (the panel, and the status line under the picture) are drawn into an 8-bit
// copy of the window once they have settled (the same two frames running: a panel that changes
// every frame, radiosity's plot, is drawn as before), and on the next frames that copy's
// rectangles are copied into the window (glBlitFramebuffer). What is drawn is the same either
// way: `enabled = false` draws every list every frame, to compare. Where the window keeps its
// back buffer from frame to frame (gl::WindowContext::keeps_back_buffer: the software
// rasteriser) and shows a part of it, the panel shown on one frame is still on the screen on the
// next: while it stays the cache's, the window need not draw or show its rectangles again (the
// view may even clear them in the back buffer, Viewer::frame).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "gl/pixel_rect.h"
#include "gl/render_target.h"

struct ImDrawData;
struct ImDrawList;

namespace luz::app {

using FramebufferRect = gl::PixelRect;

// Which of a frame's draw lists the cache may hold (`cached`) and which are drawn as they are
// (`live`), each in ImGui's order. A list is the cache's when each of its commands draws inside
// one of the `panel` rectangles, it samples only `font` (an image in the panel changes without
// its vertices changing) and no list before it that reaches into the panel from outside (a
// tooltip, a combo's popup) has to stay on top of it. Returns whether a live list reaches into
// the panel.
bool split_lists(const ImDrawData& frame, std::span<const FramebufferRect> panel, void* font,
                 std::vector<ImDrawList*>& cached, std::vector<ImDrawList*>& live);

class PanelCache {
public:
  // Before anything of the frame is drawn: which of `frame`'s lists come from the cache, whose
  // pixels are the `panel` rectangles (the empty ones left out). Returns true when the frame
  // need neither draw nor show the panel rectangles: `window_kept` (the window shows a part of
  // its back buffer, and nothing this frame reads or shows the rest), the cache's panel was
  // copied into the window and is still this frame's, and no other list reaches into it.
  bool prepare(ImDrawData& frame, std::span<const FramebufferRect> panel, bool window_kept);

  // Draws the prepared frame into the window's framebuffer (bound, window-sized,
  // single-sampled: a blit into a multisampled one fails, see gl::window_is_multisampled):
  // the lists wholly inside the panel from the cache, the rest as ImGui drew them.
  // `background` is what the window shows where nothing is drawn.
  void draw(glm::vec4 background);

  // Whether the prepared frame's panel rectangles are painted whole by draw(): copied from the
  // cache or left as they were, not drawn over what is under them.
  bool paints_panel() const { return panel_is_ != Panel::drawn; }

  bool enabled = true;
  long hits = 0;     // frames whose panel came from the cache
  long redraws = 0;  // frames that drew the panel into it
  long kept = 0;     // frames that left the window's panel pixels as they were

private:
  enum class Panel { drawn, redrawn, cached, kept };  // this frame's: as it is, into the cache, from it, left
  bool unchanged(const ImDrawData& frame);
  void redraw(const ImDrawData& frame, glm::vec4 background);

  ImDrawData* frame_ = nullptr;  // the prepared frame
  std::vector<FramebufferRect> panel_;  // the prepared frame's, none empty
  Panel panel_is_ = Panel::drawn;
  bool reached_into_ = false;   // a live list draws over the panel this frame
  bool in_window_ = false;      // the window's back buffer holds the cache's panel
  std::vector<ImDrawList*> cached_, live_;  // this frame's lists, in ImGui's order within each
  std::vector<std::byte> drawn_, next_;     // what the cache holds; this frame's cached lists
  std::vector<std::byte> previous_;         // the last frame's, while the panel was changing
  std::unique_ptr<gl::RenderTarget> target_;
  int width_ = 0, height_ = 0;
};

}  // namespace luz::app
