#include "app/viewer/screenshot.h"

#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "core/image.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "io/image_io.h"

namespace luz::app {

void save_picture(const gl::Framebuffer& view, const std::filesystem::path& path, float exposure) {
  const Image image = [&] {
    const gl::KeptBinding kept;
    return view.read();
  }();
  io::write_image(image, path, exposure);
}

void save_window(int width, int height, const std::filesystem::path& path) {
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba[(size_t(height - 1 - y) * width + x) * 4];  // GL rows go bottom-up
      image.at(x, y) = Rgb(srgb_decode(p[0] / 255.0f), srgb_decode(p[1] / 255.0f), srgb_decode(p[2] / 255.0f));
    }
  io::write_image(image, path, 0.0f);
}

void save_shown_window(const gl::WindowContext& window, const std::filesystem::path& path) {
  const glm::ivec2 size = window.framebuffer_size();
  const std::vector<std::uint8_t> rgba = window.shown_pixels();  // rows from the top
  Image image(size.x, size.y);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::uint8_t* p = &rgba[(size_t(y) * size.x + x) * 4];
      image.at(x, y) = Rgb(srgb_decode(p[0] / 255.0f), srgb_decode(p[1] / 255.0f), srgb_decode(p[2] / 255.0f));
    }
  io::write_image(image, path, 0.0f);
}

std::filesystem::path next_screenshot_name(const std::filesystem::path& scene, bool with_panel) {
  for (int n = 1;; ++n) {
    std::filesystem::path name = fmt::format("luz-{}{}-{}.png", scene.stem().string(),
                                             with_panel ? "-panel" : "", n);
    if (!std::filesystem::exists(name)) return name;
  }
}

}  // namespace luz::app
