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

}  // namespace luz::rt
