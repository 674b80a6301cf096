#pragma once
// The switches of the local models (slides 15-19). One struct, defaults here only: the panel
// edits it, `luz render` fills it from flags, tests construct it.
namespace luz {

enum class Shading {
  flat,     // one colour per triangle: the formula at its centroid with the face normal
  gouraud,  // the formula per vertex, colours interpolated
  phong,    // normals interpolated, the formula per fragment
};

struct LocalOptions {
  Shading shading = Shading::phong;
  bool ambient = true;    // I_A = I_a * k_a
  bool diffuse = true;    // I_D = I_L * k_d * cos(theta)
  bool specular = true;   // I_S = I_L * k_s * cos^n(alpha)
  bool emission = true;   // emissive surfaces show their own Le
  bool blinn = false;     // cos(alpha) from Blinn's half vector N.H instead of Phong's R.V
  bool textures = true;   // baseColorTexture modulates k_d
};

const char* to_string(Shading shading);

}  // namespace luz
