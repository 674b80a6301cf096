#pragma once
// The switches of the local formula's terms (slides 15-18), one per term. The rasterised local
// models and the Whitted tracer evaluate the same formula, so they share this struct: the panel
// and the flags set it once and every model reads it.
namespace luz {

struct TermSwitches {
  bool ambient = true;    // I_A = I_a * k_a
  bool diffuse = true;    // I_D = I_L * k_d * cos(theta)
  bool specular = true;   // I_S = I_L * k_s * cos^n(alpha)
  bool emission = true;   // emissive surfaces show their own Le (seen from the front)
  bool blinn = false;     // cos(alpha) from Blinn's half vector N.H instead of Phong's R.V
  bool textures = true;   // baseColorTexture modulates k_d
  bool operator==(const TermSwitches&) const = default;
};

}  // namespace luz
