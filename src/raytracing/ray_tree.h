#pragma once
// Slide 24's ray tree: every ray one pixel spawned, as nodes linked to their parent. The command
// writes it as JSON (`luz render ... --ray-tree X,Y`); the viewer draws it over the scene.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/color.h"
#include "raytracing/ray.h"

namespace luz::rt {

struct RayTreeNode {
  int id = 0;
  int parent = -1;        // -1 for a primary ray
  RayKind kind = RayKind::primary;
  int depth = 1;          // slide 26's d of the hit that spawned it (primary: 1)
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f};
  bool hit = false;       // shadow rays: blocked
  float t = 0.0f;         // distance to the hit (or to the light, for a shadow ray)
  glm::vec3 hit_point{0.0f};
  glm::vec3 normal{0.0f}; // shading normal at the hit, facing the ray
  std::string mesh;       // name of the mesh hit ("" for none)
  std::string material;
  int light = -1;         // shadow rays: index into Scene::lights, or lights + area light index
  Rgb weight{1.0f};       // what the parent multiplies this ray's radiance by (kr, kt, 1/spp; S_i)
  Rgb local{0.0f};        // the local part at the hit: Ia*ka + sum S_i IL_i [...] + Le
                          // (hybrid: B/pi + sum S_i IL_i ks cos^n(alpha))
  Rgb radiance{0.0f};     // what the ray returns (shadow ray: the light's term if unblocked)
  Rgb contribution{0.0f}; // its share of the pixel: the weights down the tree x radiance
};

struct RayTree {
  int x = 0, y = 0;          // the pixel
  int width = 0, height = 0; // of the image it belongs to
  Rgb pixel{0.0f};           // the pixel's radiance (sum of the primary rays' contributions)
  std::vector<RayTreeNode> nodes;

  std::string to_json() const;  // the format of README.md "The ray tree"
};

// Fills a RayTree while Whitted's trace() recurses (pbrt's Whitted integrator records its tree
// in the helpers that spawn the rays, the same way). A ray opens a node under the ray whose hit
// spawned it, the innermost one still open, and closes it when it returns its radiance; a shadow
// ray is opened and closed at once. With no tree every call does nothing.
class RayTreeRecorder {
public:
  explicit RayTreeRecorder(RayTree* tree = nullptr) : tree_(tree) {}

  // A primary, reflected or transmitted ray leaves with `weight` (what its radiance is
  // multiplied by: kr, kt, 1/spp) from a hit at depth `depth`.
  void ray(const Ray& ray, RayKind kind, int depth, const Rgb& weight);
  // The open ray met a surface.
  void hit(float t, const glm::vec3& point, const glm::vec3& normal, const std::string& mesh,
           const std::string& material);
  // The local part of the colour at that hit (Ia*ka + sum S_i IL_i [...] + Le).
  void local(const Rgb& local);
  // A shadow ray from that hit toward light `light`, at `distance`; `term` counts if unblocked.
  void shadow(const Ray& ray, bool blocked, float distance, int light, const Rgb& term);
  // The open ray returns its radiance and closes.
  void returned(const Rgb& radiance);

private:
  RayTreeNode& open_node(const Ray& ray, RayKind kind, int depth, const Rgb& weight);
  RayTree* tree_;
  std::vector<int> open_;  // the rays being traced, innermost last
};

}  // namespace luz::rt
