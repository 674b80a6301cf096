#pragma once
// An exposure read off the picture, as a camera's automatic exposure does. For scenes whose light
// is far from the program's units: files from elsewhere, such as Blender's exports, whose lights
// come in candela, 683 times the W/sr that Luz reads them as (SCENES.md "Lights").
#include <cstddef>
#include <optional>
#include <string>

#include "core/image.h"
#include "core/scene.h"

namespace luz {

// A picture's key (Reinhard, Stark, Shirley & Ferwerda 2002, "Photographic tone reproduction for
// digital images", section 3.1) is the log-average luminance of its pixels, exp(mean(log Y)); a
// scene of normal key is exposed so that it shows as middle grey.
inline constexpr double kMiddleGrey = 0.18;

// The pixels that see something lit (finite Rec. 709 luminance Y > 0); a black background or a
// shadow has no logarithm and says nothing about the exposure. A picture of more than 2^16
// pixels is read on a regular grid of about 2^16 of them (exposure.cpp).
struct PictureKey {
  size_t lit = 0;  // of the pixels read
  double log_average = 0.0;  // exp(mean(log Y)) over the lit pixels; 0 when there are none
};
PictureKey picture_key(const Image& picture);

// The most the fit raises the exposure: +16 EV, 65536 times. A picture that calls for more has
// almost no light (its lights off or hidden, an emitter whose texture is black where it is seen):
// exposing its faint remains by 2^31 shows rounding noise as white blobs, so the fit stops here
// and says so (almost_no_light).
inline constexpr float kMaxFittedExposure = 16.0f;

// The exposure, in EV, that shows the lit pixels' log-average luminance as middle grey:
// log2(0.18 / key), rounded to a tenth of an EV so that it can be typed back (--exposure, the
// panel), and at most kMaxFittedExposure. None when nothing is lit.
std::optional<float> fitted_exposure(const PictureKey& key);
// Whether the picture calls for more than kMaxFittedExposure: it has almost no light.
bool almost_no_light(const PictureKey& key);
// The sentence that says so, for the warning of --exposure auto and the viewer's note.
std::string almost_no_light_note(const PictureKey& key);

// How far `ev` is from the fitted exposure before the picture counts as badly exposed: 4 EV,
// sixteen times too bright or too dark. The shipped scenes, dim rooms lit by one or two lamps,
// are within 3.1 EV of their fits at the exposure they were made for.
inline constexpr float kExposureTolerance = 4.0f;

// A sentence on what is wrong with showing `picture` at `ev` (over-exposed, with the share of its
// lit pixels that are white, or under-exposed, with the share that are black; and the fitted
// exposure), or empty
// when `ev` is within kExposureTolerance of the fitted one or nothing is lit. `photometric_hint`:
// add that the file's lights may be photometric (its writer's name, e.g. Blender's exporter).
std::string exposure_problem(const Image& picture, float ev, const std::string& photometric_hint = {});

// That hint for a scene whose punctual lights are likely photometric: those of Blender's glTF
// exporter, whose default Lighting Mode ("Standard") writes a lamp of P watts as P / 4 pi x 683
// candela (io_scene_gltf2, PBR_WATTS_TO_LUMENS), where its "Unitless" mode writes the P / 4 pi
// W/sr Luz reads, and its "Raw" mode writes the P watts themselves as candela, 4 pi times the
// W/sr. Empty for any other scene.
std::string photometric_hint(const Scene& scene);

}  // namespace luz
