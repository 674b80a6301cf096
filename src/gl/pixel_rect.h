#pragma once

namespace luz::gl {

// A rectangle of a framebuffer's pixels, GL's way: origin at the bottom left.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

}  // namespace luz::gl
