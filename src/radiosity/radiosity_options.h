#pragma once
// The settings of progressive radiosity (slides 29-40). One struct, defaults here only: the
// viewer's panel edits it, `luz render --model radiosity` fills it from flags, tests build it.
#include <cstdint>
#include <string>

namespace luz {

struct RadiosityOptions {
  // ---- Meshing (slide 40, "Mallado") ----
  // Longest patch edge in metres; 0 = chosen so the mesh has about `target_patches` patches.
  float patch_size = 0.0f;
  int target_patches = 3000;

  // ---- Form factors: the hemicube (slide 37) ----
  int hemicube_res = 128;       // pixels across the top face (64 .. 1024, even)
  bool random_rotation = true;  // turn the hemicube about the normal at every shot (aliasing)
  uint32_t seed = 1;            // of those rotations: the same seed gives the same solution

  // ---- The shooting loop (slide 39) ----
  int max_shots = 0;        // stop after this many shots (lights included); 0 = no limit
  float converge = 0.01f;   // stop when unshot power < converge x emitted power; 0 = never

  // ---- Display (slide 39 step 3) ----
  bool ambient_estimate = false;  // add Cohen et al.'s ambient term for the light not yet shot
  bool flat_patches = false;      // one colour per patch instead of Gouraud-interpolated vertices
  bool outlines = false;          // draw the patch edges over the picture

  std::string to_string() const;
};

// Smallest and largest hemicube resolutions the panel and the command accept.
inline constexpr int kMinHemicubeRes = 64;
inline constexpr int kMaxHemicubeRes = 1024;

}  // namespace luz
