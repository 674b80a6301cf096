#include "raytracing/ray_tree.h"

#include <nlohmann/json.hpp>

namespace luz::rt {

namespace {
nlohmann::json vec(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
}  // namespace

std::string RayTree::to_json() const {
  nlohmann::json nodes_json = nlohmann::json::array();
  for (const RayTreeNode& n : nodes) {
    nlohmann::json node = {
        {"id", n.id},
        {"parent", n.parent},
        {"kind", to_string(n.kind)},
        {"depth", n.depth},
        {"origin", vec(n.origin)},
        {"direction", vec(n.direction)},
        {"weight", vec(n.weight)},
        {"radiance", vec(n.radiance)},
        {"contribution", vec(n.contribution)},
    };
    if (n.kind == RayKind::shadow) {
      node["light"] = n.light;
      node["blocked"] = n.hit;
      node["distance"] = n.t;
    } else if (n.hit) {
      node["hit"] = {{"t", n.t}, {"point", vec(n.hit_point)}, {"normal", vec(n.normal)},
                     {"mesh", n.mesh}, {"material", n.material}};
      node["local"] = vec(n.local);
    } else {
      node["hit"] = nullptr;  // the background
    }
    nodes_json.push_back(node);
  }
  const nlohmann::json tree = {{"pixel", {x, y}}, {"size", {width, height}},
                               {"radiance", vec(pixel)}, {"nodes", nodes_json}};
  return tree.dump(2) + "\n";
}

// ---- [the recorder] -----------------------------------------------------------------------------
RayTreeNode& RayTreeRecorder::open_node(const Ray& ray, RayKind kind, int depth, const Rgb& weight) {
  RayTreeNode node;
  node.id = int(tree_->nodes.size());
  node.parent = open_.empty() ? -1 : open_.back();
  node.kind = kind;
  node.depth = depth;
  node.origin = ray.origin;
  node.direction = ray.direction;
  node.weight = weight;
  tree_->nodes.push_back(node);
  return tree_->nodes.back();
}

void RayTreeRecorder::ray(const Ray& ray, RayKind kind, int depth, const Rgb& weight) {
  if (!tree_) return;
  open_.push_back(open_node(ray, kind, depth, weight).id);
}

void RayTreeRecorder::hit(float t, const glm::vec3& point, const glm::vec3& normal,
                          const std::string& mesh, const std::string& material) {
  if (!tree_) return;
  RayTreeNode& n = tree_->nodes[size_t(open_.back())];
  n.hit = true;
  n.t = t;
  n.hit_point = point;
  n.normal = normal;
  n.mesh = mesh;
  n.material = material;
}

void RayTreeRecorder::local(const Rgb& local) {
  if (!tree_) return;
  tree_->nodes[size_t(open_.back())].local = local;
}

void RayTreeRecorder::shadow(const Ray& ray, bool blocked, float distance, int light, const Rgb& term) {
  if (!tree_) return;
  const int depth = tree_->nodes[size_t(open_.back())].depth;
  RayTreeNode& n = open_node(ray, RayKind::shadow, depth, Rgb(blocked ? 0.0f : 1.0f));  // S_i
  n.hit = blocked;
  n.t = distance;
  n.light = light;
  n.radiance = term;
}

void RayTreeRecorder::returned(const Rgb& radiance) {
  if (!tree_) return;
  tree_->nodes[size_t(open_.back())].radiance = radiance;
  open_.pop_back();
}

}  // namespace luz::rt
