#include "core/exposure.h"

#include <algorithm>
#include <cmath>

#include "core/i18n.h"
#include "core/image_compare.h"

namespace luz {
namespace {

// A pixel that sees light: a finite luminance above 0.
bool lit(double y) { return y > 0.0 && std::isfinite(y); }

// The pixels read: every one of a picture of up to 2^16, else every s-th pixel of every s-th
// row, about 2^16 of them. A mean of logarithms has settled long before that many samples, and
// a megapixel render's check then costs a millisecond, not the 10-15 ms a logarithm per pixel
// takes (a tenth of the fixed cost of `luz render`).
template <class Visit>
void for_each_read(const Image& picture, Visit visit) {
  const double pixels = double(picture.width) * double(picture.height);
  const int step = std::max(1, int(std::ceil(std::sqrt(pixels / 65536.0))));
  for (int y = step / 2; y < picture.height; y += step)
    for (int x = step / 2; x < picture.width; x += step) visit(picture.at(x, y));
}

}  // namespace

PictureKey picture_key(const Image& picture) {
  PictureKey key;
  double log_sum = 0.0;
  for_each_read(picture, [&](const Rgb& c) {
    const double y = rec709_luminance(c);
    if (!lit(y)) return;
    log_sum += std::log(y);
    ++key.lit;
  });
  if (key.lit > 0) key.log_average = std::exp(log_sum / double(key.lit));
  return key;
}

namespace {
// The fit before the bound.
float unbounded_fit(const PictureKey& key) {
  // + 0: a fit of -0.0 would print as "-0 EV".
  return float(std::round(10.0 * std::log2(kMiddleGrey / key.log_average)) / 10.0) + 0.0f;
}
}  // namespace

std::optional<float> fitted_exposure(const PictureKey& key) {
  if (key.lit == 0) return std::nullopt;
  return std::min(unbounded_fit(key), kMaxFittedExposure);
}

bool almost_no_light(const PictureKey& key) { return key.lit > 0 && unbounded_fit(key) > kMaxFittedExposure; }

std::string almost_no_light_note(const PictureKey& key) {
  return i18n::trf("the picture has almost no light (its mid-tones call for {:+.1f} EV): the exposure "
                   "stops at {:+g} EV; are the scene's lights on and in view?",
                   unbounded_fit(key), kMaxFittedExposure);
}

std::string exposure_problem(const Image& picture, float ev, const std::string& photometric_hint) {
  const std::optional<float> fitted = fitted_exposure(picture_key(picture));
  if (!fitted || std::abs(*fitted - ev) <= kExposureTolerance) return {};
  // The PNG's white is radiance 1 after 2^ev; its black, the 8-bit code 0 of the sRGB curve's
  // linear segment (12.92 x below 0.5 / 255).
  const double scale = std::exp2(double(ev));
  constexpr double kBlack = 0.5 / 255.0 / 12.92;
  size_t counted = 0, white = 0, black = 0;
  for_each_read(picture, [&](const Rgb& c) {
    if (!lit(rec709_luminance(c))) return;
    ++counted;
    const double brightest = std::max({double(c.r), double(c.g), double(c.b)}) * scale;
    white += brightest >= 1.0;
    black += brightest < kBlack;
  });
  const double percent = 100.0 / double(counted);
  // The messages are fmt strings: "{:.0f}% of" is no printf directive.
  std::string problem;
  if (*fitted < ev)
    // xgettext:no-c-format
    problem = i18n::trf("at {:+g} EV the picture is over-exposed: {:.0f}% of its lit pixels are white, and its "
                        "mid-tones call for {:+.1f} EV",
                        ev, percent * double(white), *fitted);
  else
    // xgettext:no-c-format
    problem = i18n::trf("at {:+g} EV the picture is under-exposed: {:.0f}% of its lit pixels are black, and its "
                        "mid-tones call for {:+.1f} EV",
                        ev, percent * double(black), *fitted);
  if (*fitted < ev && !photometric_hint.empty()) problem += " (" + photometric_hint + ")";
  return problem;
}

std::string photometric_hint(const Scene& scene) {
  const bool punctual = !scene.lights.empty() && !scene.default_lights;
  if (!punctual || scene.generator.find("Blender") == std::string::npos) return {};
  return i18n::trf("{} writes lights in candela: in its Lighting Mode \"Standard\" 683 times the W/sr Luz "
                   "reads, in \"Raw\" its point and spot lights 4 pi times; \"Unitless\" writes W/sr",
                   scene.generator);
}

}  // namespace luz
