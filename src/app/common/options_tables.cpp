#include "app/common/options_tables.h"

#include <cmath>

#include "app/common/i18n.h"
#include "raytracing/sampling.h"

namespace luz::app {
namespace {

constexpr const char* fog_modes[] = {"off", "linear", "exponential"};  // FogMode's order
constexpr const char* form_factor_methods[] = {"hemicube", "analytic", "rays"};  // FormFactorMethod's order
constexpr const char* meshings[] = {"uniform", "adaptive"};                        // Meshing's order
constexpr const char* hemicube_passes[] = {"five", "one"};                         // HemicubePasses' order
constexpr const char* hemicube_sums[] = {"cpu", "gpu"};                            // HemicubeSums' order
constexpr const char* renderers[] = {"wavefront", "recursive"};                    // RendererKind's order

bool even(double v) { return std::fmod(v, 2.0) == 0.0; }
bool square(double v) { return rt::is_square(int(v)); }

const OptionRow local_rows[] = {
    // The terms of I = I_A + I_D + I_S (+ Le), in three groups by the models that have them
    // (model_registry.cpp): the lights' terms, the ambient and emitted terms that radiosity's
    // solution replaces in the hybrid, and the kd texture.
    {"ambient", "--no-ambient", "ambient-emission", OptionKind::on_off, N_("Switch off the ambient term I_A = Ia*ka"), 0, 1,
     LUZ_OPTION_FIELD(LocalOptions, terms.ambient)},
    {"diffuse", "--no-diffuse", "terms", OptionKind::on_off, N_("Switch off the diffuse term I_D = IL*kd*cos(theta)"), 0, 1,
     LUZ_OPTION_FIELD(LocalOptions, terms.diffuse)},
    {"specular", "--no-specular", "terms", OptionKind::on_off,
     N_("Switch off the specular term I_S = IL*ks*cos^n(alpha)"), 0, 1, LUZ_OPTION_FIELD(LocalOptions, terms.specular)},
    {"emission", "--no-emission", "ambient-emission", OptionKind::on_off,
     N_("Do not show the emitted radiance Le of emissive surfaces"), 0, 1, LUZ_OPTION_FIELD(LocalOptions, terms.emission)},
    {"textures", "--no-textures", "textures", OptionKind::on_off, N_("Ignore baseColorTexture"), 0, 1,
     LUZ_OPTION_FIELD(LocalOptions, terms.textures)},
    {"blinn", "--blinn", "terms", OptionKind::on_off, N_("Blinn's half vector N.H instead of Phong's R.V"), 0, 1,
     LUZ_OPTION_FIELD(LocalOptions, terms.blinn)},
    // Slide 19's other possibilities: the local models' only.
    {"fog", "--fog", "local", OptionKind::choice, N_("Atmospheric attenuation (depth cueing) toward the fog colour"), 0, 2,
     LUZ_OPTION_CHOICE(LocalOptions, fog.mode), fog_modes},
    {"fog-near", "--fog-near", "local", OptionKind::real, N_("Linear fog: no fog closer than D metres"), 0, 1000,
     LUZ_OPTION_FIELD(LocalOptions, fog.near)},
    {"fog-far", "--fog-far", "local", OptionKind::real, N_("Linear fog: only fog beyond D metres"), 0, 1000,
     LUZ_OPTION_FIELD(LocalOptions, fog.far)},
    {"fog-density", "--fog-density", "local", OptionKind::real, N_("Exponential fog: f = exp(-K d), K per metre"), 0, 10,
     LUZ_OPTION_FIELD(LocalOptions, fog.density)},
    {"shadows", "--shadows", "local", OptionKind::on_off,
     N_("Blocking of the sources by occlusion (S_i), with shadow maps"), 0, 1, LUZ_OPTION_FIELD(LocalOptions, shadows.on)},
    {"shadow-bias", "--shadow-bias", "local", OptionKind::real, N_("Constant shadow bias in metres"), 0, 0.5,
     LUZ_OPTION_FIELD(LocalOptions, shadows.constant_bias)},
    {"shadow-slope-bias", "--shadow-slope-bias", "local", OptionKind::real,
     N_("Slope-scaled shadow bias, texels per unit of tan(theta)"), 0, 20, LUZ_OPTION_FIELD(LocalOptions, shadows.slope_bias)},
    {"shadow-normal-offset", "--shadow-normal-offset", "local", OptionKind::real,
     N_("Shadow lookup moved this many texels along the normal"), 0, 20, LUZ_OPTION_FIELD(LocalOptions, shadows.normal_offset)},
    {"shadow-map-size", "--shadow-map-size", "local", OptionKind::integer, N_("Texels per side of each shadow map"), 16,
     8192, LUZ_OPTION_FIELD(LocalOptions, shadows.map_size)},
    {"transparency", "--transparency", "local", OptionKind::on_off,
     N_("Non-refractive transparency: I + kt * what lies behind"), 0, 1, LUZ_OPTION_FIELD(LocalOptions, transparency.on)},
    {"reflection-map", "--reflection-map", "local", OptionKind::on_off,
     N_("Reflection maps: kr * Ir from a cube map around each object with kr > 0"), 0, 1,
     LUZ_OPTION_FIELD(LocalOptions, reflection.on)},
    {"reflection-map-size", "--reflection-map-size", "local", OptionKind::integer, N_("Texels per side of each cube face"),
     8, 4096, LUZ_OPTION_FIELD(LocalOptions, reflection.resolution)},
};

const OptionRow whitted_rows[] = {
    {"depth", "--depth", "sampling", OptionKind::integer,
     N_("whitted/hybrid/path: maximum ray depth as on slide 26 (primary rays have depth 1; 1 or 0: no reflected "
     "or transmitted rays; path: default 16)"),
     0, 64, LUZ_OPTION_FIELD(rt::WhittedOptions, max_depth)},
    {"spp", "--spp", "sampling", OptionKind::integer,
     N_("whitted/hybrid: samples per pixel on a jittered sqrt(N) x sqrt(N) grid; path: any N up to 4096 (default "
     "16)"), 1, 4096,
     LUZ_OPTION_FIELD(rt::WhittedOptions, spp), {}, square, N_("a square: 1, 4, 9, 16, ...")},
    {"adaptive", "--adaptive", "whitted", OptionKind::on_off,
     N_("whitted/hybrid: Whitted's adaptive supersampling (pixel corners, subdivided where they differ; instead of "
     "--spp)"),
     0, 1,
     [](const void* o) { return static_cast<const rt::WhittedOptions*>(o)->sampling == rt::Sampling::adaptive ? 1.0 : 0.0; },
     [](void* o, double v) {
       static_cast<rt::WhittedOptions*>(o)->sampling = v != 0.0 ? rt::Sampling::adaptive : rt::Sampling::stratified;
     }},
    {"adaptive-levels", nullptr, "whitted", OptionKind::integer, N_("adaptive: subdivide a pixel at most this often"), 0, 4,
     LUZ_OPTION_FIELD(rt::WhittedOptions, adaptive_levels)},
    {"adaptive-threshold", nullptr, "whitted", OptionKind::real,
     N_("adaptive: corners differing by more (sRGB-encoded) split"), 0, 1, LUZ_OPTION_FIELD(rt::WhittedOptions, adaptive_threshold)},
    {"fresnel", "--fresnel", "whitted", OptionKind::on_off,
     N_("whitted/hybrid: Fresnel's reflectance F splits kt: reflection kr + kt*F, transmission kt*(1-F)"), 0, 1,
     LUZ_OPTION_FIELD(rt::WhittedOptions, fresnel)},
    {"light-samples", "--light-samples", "whitted", OptionKind::integer,
     N_("whitted/hybrid: shadow rays per emissive triangle (1: its centroid; N: soft shadows)"), 1, 1024,
     LUZ_OPTION_FIELD(rt::WhittedOptions, light_samples)},
    {"brute-force", "--brute-force", "whitted", OptionKind::on_off,
     N_("whitted/hybrid: test every ray against every triangle instead of Embree's BVH (counts the tests)"), 0, 1,
     LUZ_OPTION_FIELD(rt::WhittedOptions, brute_force)},
    {"shadow-rays", "--no-shadows", "whitted", OptionKind::on_off,
     N_("whitted/hybrid: no shadow rays (every light unoccluded)"), 0, 1, LUZ_OPTION_FIELD(rt::WhittedOptions, shadows)},
    {"renderer", "--renderer", "whitted", OptionKind::choice,
     N_("whitted/hybrid: wavefront (each generation of a tile's rays traced as one stream: the primary rays, then "
     "the reflected and transmitted ones) or recursive (slide 26's recursion, ray by ray); the same picture, in "
     "another time (adaptive sampling and the ray tree always take the recursion)"), 0, 1,
     LUZ_OPTION_CHOICE(rt::WhittedOptions, renderer), renderers},
};

const OptionRow radiosity_rows[] = {
    {"shots", "--shots", "radiosity", OptionKind::integer, N_("radiosity/hybrid: stop after N shots (lights included)"), 1,
     kUnbounded, [](const void* o) { return double(static_cast<const RadiosityOptions*>(o)->max_shots); },
     [](void* p, double v) {
       auto& o = *static_cast<RadiosityOptions*>(p);
       o.max_shots = int(v);
       o.converge = 0.0f;  // one stopping rule at a time
     }},
    {"converge", "--converge", "radiosity", OptionKind::real,
     N_("radiosity/hybrid: stop when the unshot power is below EPS x the emitted power"), 1e-9, 1,
     [](const void* o) { return double(static_cast<const RadiosityOptions*>(o)->converge); },
     [](void* p, double v) {
       auto& o = *static_cast<RadiosityOptions*>(p);
       o.converge = float(v);
       o.max_shots = 0;
     }},
    {"work-budget", "--work-budget", "radiosity", OptionKind::real,
     N_("radiosity/hybrid: with none of --shots, --converge, --time, stop after N element-shots (the elements "
     "each shot reaches, summed over the shots; 0: no bound)"), 0, kMaxWorkBudget,
     LUZ_OPTION_FIELD(RadiosityOptions, work_budget)},
    {"patch-size", "--patch-size", "radiosity", OptionKind::real,
     N_("radiosity/hybrid: longest patch edge, metres (0: subdivision adds about target-patches patches)"), 0, 100,
     LUZ_OPTION_FIELD(RadiosityOptions, patch_size)},
    {"target-patches", nullptr, "radiosity", OptionKind::integer, N_("the mesh's size when patch-size is 0"), 10, 1000000,
     LUZ_OPTION_FIELD(RadiosityOptions, target_patches)},
    {"hemicube", "--hemicube-res", "radiosity", OptionKind::integer,
     N_("radiosity/hybrid: hemicube resolution, pixels across its top face"), double(kMinHemicubeRes),
     double(kMaxHemicubeRes), LUZ_OPTION_FIELD(RadiosityOptions, hemicube_res), {}, even, N_("even")},
    {"hemicube-passes", "--hemicube-passes", "radiosity", OptionKind::choice,
     N_("radiosity/hybrid: draw the hemicube's faces in five passes (one viewport each) or in one instanced pass"),
     0, 1, LUZ_OPTION_CHOICE(RadiosityOptions, hemicube_passes), hemicube_passes},
    {"hemicube-sums", "--hemicube-sums", "radiosity", OptionKind::choice,
     N_("radiosity/hybrid: sum the hemicube's delta form factors on the cpu (the item buffer read back) or on "
     "the gpu (one sum per element read back)"), 0, 1,
     LUZ_OPTION_CHOICE(RadiosityOptions, hemicube_sums), hemicube_sums},
    {"elements", "--elements", "radiosity", OptionKind::integer,
     N_("radiosity/hybrid: cut each patch into N x N elements that receive and are drawn while the patch shoots "
     "(1: no substructuring)"), 1, double(kMaxElementsPerEdge), LUZ_OPTION_FIELD(RadiosityOptions, elements_per_edge)},
    {"meshing", "--meshing", "radiosity", OptionKind::choice,
     N_("radiosity/hybrid: uniform (the elements as built) or adaptive (elements cut in two, while the solution "
     "runs, where the light arriving is not the linear ramp Gouraud shading draws)"), 0, 1,
     LUZ_OPTION_CHOICE(RadiosityOptions, meshing), meshings},
    {"refine-threshold", "--refine-threshold", "radiosity", OptionKind::real,
     N_("radiosity/hybrid: with --meshing adaptive, cut an element whose irradiance differs from the mean of "
     "its neighbours' by more than T x the scene's mean irradiance"), 0.001, 10, LUZ_OPTION_FIELD(RadiosityOptions, refine_threshold)},
    {"refine-levels", "--refine-levels", "radiosity", OptionKind::integer,
     N_("radiosity/hybrid: with --meshing adaptive, cut an element at most N times (2 cuts halve its edges)"), 1,
     double(kMaxRefineLevels), LUZ_OPTION_FIELD(RadiosityOptions, refine_levels)},
    {"refine-budget", "--refine-budget", "radiosity", OptionKind::integer,
     N_("radiosity/hybrid: with --meshing adaptive, add at most N elements to the mesh as built"), 0,
     double(kMaxRefineBudget), LUZ_OPTION_FIELD(RadiosityOptions, refine_budget)},
    {"overshoot", "--overshoot", "radiosity", OptionKind::real,
     N_("radiosity/hybrid: shoot W x the unshot radiosity (1: plain shooting)"), double(kMinOvershoot),
     double(kMaxOvershoot), LUZ_OPTION_FIELD(RadiosityOptions, overshoot)},
    {"form-factors", "--form-factors", "radiosity", OptionKind::choice,
     N_("radiosity/hybrid: the hemicube's delta form factors; analytic (Lambert's contour integral from each "
     "element to the shooter, the hemicube giving visibility); or rays (the same integral, visibility by rays "
     "to points of the shooter, no hemicube)"), 0, 2,
     LUZ_OPTION_CHOICE(RadiosityOptions, form_factors), form_factor_methods},
    {"visibility-rays", "--visibility-rays", "radiosity", OptionKind::integer,
     N_("radiosity/hybrid: with --form-factors rays, rays from each element to the shooter per shot"), 1,
     double(kMaxVisibilityRays), LUZ_OPTION_FIELD(RadiosityOptions, visibility_rays)},
    {"rotation", nullptr, "radiosity", OptionKind::on_off, N_("turn the hemicube about the normal at every shot"), 0, 1,
     LUZ_OPTION_FIELD(RadiosityOptions, random_rotation)},
    {"ambient-estimate", "--ambient-estimate", "radiosity", OptionKind::on_off,
     N_("radiosity/hybrid: add Cohen's ambient term for the light not yet shot"), 0, 1,
     LUZ_OPTION_FIELD(RadiosityOptions, ambient_estimate)},
    {"flat-patches", "--flat-patches", "radiosity-display", OptionKind::on_off,
     N_("radiosity: one colour per patch instead of Gouraud shading"), 0, 1, LUZ_OPTION_FIELD(RadiosityOptions, flat_patches)},
    {"outlines", "--outlines", "radiosity-display", OptionKind::on_off, N_("radiosity: draw the patch edges"), 0, 1,
     LUZ_OPTION_FIELD(RadiosityOptions, outlines)},
    {"pixel-samples", "--pixel-samples", "radiosity-display", OptionKind::integer,
     N_("radiosity: samples per pixel of the picture, on a sqrt(N) x sqrt(N) grid (1: aliased edges, as the "
     "viewer draws)"), 1, double(kMaxPixelSamples), LUZ_OPTION_FIELD(RadiosityOptions, pixel_samples), {}, square,
     N_("a square: 1, 4, 9, 16, ...")},
};


}  // namespace

const OptionTable& local_table() {
  static const OptionTable table = option_table<LocalOptions>("local", local_rows);
  return table;
}

const OptionTable& whitted_table() {
  static const OptionTable table = option_table<rt::WhittedOptions>("whitted", whitted_rows);
  return table;
}

const OptionTable& radiosity_table() {
  static const OptionTable table = option_table<RadiosityOptions>("radiosity", radiosity_rows);
  return table;
}

}  // namespace luz::app
