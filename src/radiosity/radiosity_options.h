#pragma once
// The settings of progressive radiosity (slides 29-40). One struct, defaults here only: the
// viewer's panel edits it, `luz render --model radiosity` fills it from flags, tests build it.
#include <cstdint>
#include <string>

namespace luz {

enum class FormFactorMethod { hemicube, analytic, rays };
const char* to_string(FormFactorMethod method);  // "hemicube", "analytic", "rays"
enum class Meshing { uniform, adaptive };
const char* to_string(Meshing meshing);  // "uniform", "adaptive"
// How the hemicube's five faces reach its item buffer: five draws, each face in its own viewport
// (the slide's picture), or one instanced draw whose instances are the faces, each clipped to its
// rectangle of the atlas (the same pixels, fewer draw calls).
enum class HemicubePasses { five, one };
// Where F_ij is summed: on the CPU over the item buffer read back, or on the GPU, which reads
// back one sum per element (gpu_row_sums.h).
enum class HemicubeSums { cpu, gpu };

struct RadiosityOptions {
  // ---- Meshing (slide 40, "Mallado - Subestructuracion") ----
  // Two levels (Cohen, Greenberg, Immel & Brock 1986): patches shoot, and each patch is cut into
  // elements_per_edge x elements_per_edge elements that receive and are displayed. Shots then
  // scale with the patches and the picture's detail with the elements. 1 = every element is its
  // own patch (plain progressive radiosity).
  // Longest patch edge in metres; 0 = chosen so that subdivision adds about `target_patches`
  // patches to the scene's own triangles (which are the fewest patches there can be).
  float patch_size = 0.0f;
  int target_patches = 500;
  int elements_per_edge = 4;
  // Adaptive subdivision (Cohen et al. 1986): while the solution runs, an element whose
  // irradiance differs from the mean of its neighbours' on the same surface by more than
  // refine_threshold x the scene's mean irradiance (where the light is not the linear ramp Gouraud
  // shading draws) is cut in two (mesh_bisection.h), down to refine_levels cuts (4 cuts halve
  // its edges twice); the new elements gather what every patch has shot so far. The light
  // arriving is compared, not the radiosity, so that a checkerboard's own pattern is not taken
  // for a shadow. uniform: the mesh stays as built.
  Meshing meshing = Meshing::adaptive;
  float refine_threshold = 0.15f;
  int refine_levels = 4;
  // The most elements subdivision may add to the mesh as built. Every element is drawn each frame
  // and gathers at every pass, so a model of many triangles would otherwise grow to millions and
  // the viewer's frames to seconds; subdivision stops at the budget and says so.
  int refine_budget = 200'000;
  // A patch's reflectance rho = kd, times the mean texel of the kd texture its mesh shows, whose
  // detail the picture puts back (texture_detail.h). false: kd alone and no detail, as
  // `--no-textures` (the viewer's T) leaves every model without the texture.
  bool textures = true;

  // ---- Form factors: the hemicube (slide 37) ----
  int hemicube_res = 128;       // pixels across the top face (64 .. 1024, even)
  // The same rows either way (tests hold them equal); on Mesa's software rasteriser five passes
  // and the CPU's sums are the faster (docs/radiosity-meshing.md, "Faster shots").
  HemicubePasses hemicube_passes = HemicubePasses::five;
  HemicubeSums hemicube_sums = HemicubeSums::cpu;
  // hemicube: every F from the hemicube (point-to-area from the shooter's centre).
  // analytic: the hemicube finds how much of each element the shooter sees; F itself is
  // Lambert's exact contour integral from the element to the patch polygon
  // (polygon_form_factor.h), right where the point-to-area estimate fails, next to the shooter
  // (the proximity error of Baum, Rushmeier & Winget 1989).
  // rays: no hemicube; F is the same contour integral and the visibility the fraction of
  // `visibility_rays` rays from the element to points of the patch that arrive
  // (ray_form_factors.h; Wallace, Elmquist & Haines 1989).
  FormFactorMethod form_factors = FormFactorMethod::rays;
  int visibility_rays = 4;
  bool random_rotation = true;  // turn the hemicube about the normal at every shot (aliasing)
  uint32_t seed = 1;            // of those rotations and the rays: the same seed, the same solution

  // ---- The shooting loop (slide 39) ----
  int max_shots = 0;        // stop after this many shots (lights included); 0 = no limit
  float converge = 0.005f;  // stop when unshot power < converge x emitted power; 0 = never
  // The most work a headless run (`luz render`) does when no stopping rule was asked for, in
  // element-shots: the elements each shot reaches, summed over the shots, for a shot's cost
  // grows with them. A bound on work, not on seconds, stops at the same shot on a loaded
  // machine as on a quiet one, so a picture that converges before it is the same everywhere;
  // a scene of tens of thousands of triangles meets it in about a minute and says how far it
  // got. `luz render` lifts it when --shots, --converge or --time is given; 0 = no bound. The
  // viewer shows how far the solution is and leaves the stopping to the user.
  double work_budget = 3e8;
  // Overshooting (Feda & Purgathofer 1992, read as over-relaxation by Gortler, Cohen &
  // Slusallek 1993): a patch shoots `overshoot` times its unshot radiosity and keeps the
  // negative remainder (1 - overshoot) x unshot to shoot back later. 1 = plain shooting;
  // kMinOvershoot .. kMaxOvershoot (successive over-relaxation converges below 2).
  float overshoot = 1.0f;

  // ---- Display (slide 39 step 3) ----
  bool ambient_estimate = false;  // add Cohen et al.'s ambient term for the light not yet shot
  bool flat_patches = false;      // one colour per patch instead of Gouraud-interpolated vertices
  bool outlines = false;          // draw the patch edges over the picture
  // A headless picture is drawn this many times (a square), each shifted within the pixel on a
  // regular grid, and averaged: the box filter the tracers' supersampling also has, so that
  // edges compare with theirs. The viewer draws once.
  int pixel_samples = 16;

  std::string to_string() const;
  // Throws luz::Error (bad_value) naming the first setting that is non-finite or out of its
  // range, so that nothing is built from it.
  void validate() const;
};

inline constexpr int kMaxVisibilityRays = 64;
inline constexpr int kMaxRefineLevels = 12;
inline constexpr int kMaxRefineBudget = 2'000'000;
inline constexpr int kMaxPixelSamples = 256;
inline constexpr double kMaxWorkBudget = 1e15;
inline constexpr float kMinOvershoot = 1.0f;
inline constexpr float kMaxOvershoot = 1.9f;

// The most elements a mesh may have. Each costs about 300 bytes between the mesh, the GPU's
// buffers and the solver, so this is about 600 MB; a finer request is refused before anything
// is allocated (PatchMesh::build throws, naming the numbers).
inline constexpr double kMaxElements = 2'000'000;
inline constexpr int kMaxElementsPerEdge = 16;

// Smallest and largest hemicube resolutions the panel and the command accept.
inline constexpr int kMinHemicubeRes = 64;
inline constexpr int kMaxHemicubeRes = 1024;

}  // namespace luz
