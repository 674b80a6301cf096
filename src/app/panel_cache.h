#pragma once
// The panel drawn once and shown on many frames. On Mesa's software rasteriser the ImGui pass
// costs its pixels, not its building: the panel's background blended over a quarter of a
// million pixels and its text take about 2 ms of a 10 ms frame, while the panel changes only
// when the user touches it (a hover, a click, a scroll). So the draw lists that fall inside the
// panel are drawn into an 8-bit copy of the window once they have settled (the same two frames
// running: a panel that changes every frame, radiosity's plot, is drawn as before), and on the
// next frames that copy's panel rectangle is copied into the window (glBlitFramebuffer). What
// is drawn is the same either way: `enabled = false` draws every list every frame, to compare.
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "gl/render_target.h"

struct ImDrawData;
struct ImDrawList;

namespace luz::app {

// A rectangle of the window's pixels, GL's way: origin at the bottom left.
struct FramebufferRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

// Which of a frame's draw lists the cache may hold (`cached`) and which are drawn as they are
// (`live`), each in ImGui's order. A list is the cache's when every pixel it draws lies in
// `panel`, it samples only `font` (an image in the panel changes without its vertices
// changing) and no list before it that reaches into the panel from outside (a tooltip, a
// combo's popup) has to stay on top of it.
void split_lists(const ImDrawData& frame, FramebufferRect panel, void* font, std::vector<ImDrawList*>& cached,
                 std::vector<ImDrawList*>& live);

class PanelCache {
public:
  // Draws `frame` into the window's framebuffer (bound, window-sized, single-sampled: a blit
  // into a multisampled one fails, see gl::window_is_multisampled): the lists wholly inside
  // `panel` from the cache, the rest as ImGui drew them. `background` is what the window
  // shows where nothing is drawn.
  void draw(ImDrawData& frame, FramebufferRect panel, glm::vec4 background);

  bool enabled = true;
  long hits = 0;     // frames whose panel came from the cache
  long redraws = 0;  // frames that drew the panel into it

private:
  bool unchanged(const ImDrawData& frame, FramebufferRect panel);
  void redraw(const ImDrawData& frame, glm::vec4 background);

  std::vector<ImDrawList*> cached_, live_;  // this frame's lists, in ImGui's order within each
  std::vector<std::byte> drawn_, next_;     // what the cache holds; this frame's cached lists
  std::vector<std::byte> previous_;         // the last frame's, while the panel was changing
  std::unique_ptr<gl::RenderTarget> target_;
  int width_ = 0, height_ = 0;
};

}  // namespace luz::app
