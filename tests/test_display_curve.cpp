// The window's sRGB curve against the PNG encoder's. The viewer's display pass (display.frag,
// srgb.glsl: L^(1/2.4) as a polynomial in L^(1/4), the linear toe near black) must give every
// radiance the 8-bit code `luz render` writes for it (core/image.cpp's srgb_encode), so that a
// screenshot of the window and a rendered PNG are one picture. Drawn through OSMesa over a ramp of
// radiance that is dense near black, where the toe and the curve meet.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/image.h"
#include "gl/functions.h"
#include "gl/render_target.h"
#include "gl/shader.h"

namespace luz {
namespace {

// One row of radiance through the display pass at exposure `scale`: the codes it writes.
std::vector<uint8_t> display_codes(const std::vector<float>& radiance, float scale) {
  const int n = int(radiance.size());
  std::vector<float> rgba;
  for (float L : radiance) rgba.insert(rgba.end(), {L, L, L, 1.0f});
  const gl::RenderTarget input(n, 1, {GL_RGBA32F, GL_RGBA, GL_FLOAT, "RGBA32F"});
  glBindTexture(GL_TEXTURE_2D, input.colour);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, 1, GL_RGBA, GL_FLOAT, rgba.data());

  const gl::RenderTarget output(n, 1, {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, "RGBA8"});
  glBindFramebuffer(GL_FRAMEBUFFER, output.fbo);
  glViewport(0, 0, n, 1);
  // As the viewer draws the pass; the tests before this one in the program may leave them on.
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  gl::Program display({"display.vert", "display.frag"}, {"srgb.glsl"});
  display.use();
  display.set("u_radiance", 0);
  display.set("u_scale", scale);
  display.set("u_origin", glm::vec2(0.0f));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, input.colour);
  GLuint vao = 0;  // the pass's triangle comes from gl_VertexID; core profile still wants a VAO
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);

  std::vector<uint8_t> pixels(size_t(n) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<uint8_t> codes;
  for (int i = 0; i < n; ++i) codes.push_back(pixels[size_t(i) * 4]);
  return codes;
}

// Radiance 0 .. 1.2, quadratic in the index: about 200 values on the toe (L <= 0.0031308).
std::vector<float> ramp() {
  constexpr int n = 4096;
  std::vector<float> radiance;
  for (int i = 0; i < n; ++i) {
    const float t = float(i) / float(n - 1);
    radiance.push_back(1.2f * t * t);
  }
  return radiance;
}

// The code the encoder writes for L, and whether L lies within a hundredth of a code of the edge
// between two (where the shader's float arithmetic may round the other way).
struct Expected {
  int code;
  bool at_edge;
};
Expected expected(float L) {
  const double exact = 255.0 * double(srgb_encode(L));
  return {int(srgb_byte(L)), std::abs(exact - std::floor(exact) - 0.5) < 0.01};
}

TEST(DisplayCurve, EveryRadianceGetsThePngEncodersCode) {
  for (const float scale : {1.0f, 0.25f}) {  // exposure 0 and -2 EV
    const std::vector<float> radiance = ramp();
    const std::vector<uint8_t> codes = display_codes(radiance, scale);
    int checked = 0;
    for (size_t i = 0; i < radiance.size(); ++i) {
      const Expected e = expected(radiance[i] * scale);
      const int d = std::abs(int(codes[i]) - e.code);
      EXPECT_LE(d, e.at_edge ? 1 : 0) << "L = " << radiance[i] << " x " << scale;
      checked += e.at_edge ? 0 : 1;
    }
    EXPECT_GT(checked, 4000);  // the edges are rare: nearly every value is held exactly
  }
}

TEST(DisplayCurve, NegativeAndNotANumberShowBlack) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<uint8_t> codes = display_codes({-1.0f, -1e-6f, nan, 0.0f}, 1.0f);
  for (uint8_t c : codes) EXPECT_EQ(c, 0);
}

}  // namespace
}  // namespace luz
