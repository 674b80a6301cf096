#pragma once
// Screenshots as PNG through io::write_image, so they are encoded exactly as `luz render`
// encodes its pictures (radiance x 2^exposure, sRGB curve, 8 bit).
#include <filesystem>
#include <string>

#include "gl/framebuffer.h"
#include "gl/window_context.h"

namespace luz::app {

// The picture alone: the float radiance of the scene view, with the viewer's exposure.
void save_picture(const gl::Framebuffer& view, const std::filesystem::path& path, float exposure);

// The whole window as this frame drew it (panel included): the default framebuffer's back
// buffer, already encoded for display; it goes through write_image with exposure 0 after the sRGB decode
// (8-bit codes survive decode and encode unchanged).
void save_window(int framebuffer_width, int framebuffer_height, const std::filesystem::path& path);
// What the display shows of the window, read back from the X server: the last frame presented,
// as the window presented it (partly, where it keeps its back buffer).
void save_shown_window(const gl::WindowContext& window, const std::filesystem::path& path);

// "luz-cornell_box-1.png", the first such name not taken in the working folder.
std::filesystem::path next_screenshot_name(const std::filesystem::path& scene, bool with_panel);

}  // namespace luz::app
