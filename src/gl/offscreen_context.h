#pragma once
// A headless OpenGL 3.3 core context through OSMesa (Mesa's llvmpipe): no display needed.
// Renderers draw into their own framebuffer objects; the context's own buffer is 1x1.
namespace luz::gl {

class OffscreenContext {
public:
  // Creates the context, makes it current on this thread and loads the GL function table.
  // Throws luz::Error (kind gl) when OSMesa cannot give a 3.3 core context.
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

private:
  void* context_ = nullptr;  // OSMesaContext, kept opaque so osmesa.h stays in one file
  unsigned char buffer_[4] = {};
};

}  // namespace luz::gl
