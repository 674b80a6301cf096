#include "hybrid/radiosity_diffuse.h"

#include <cassert>
#include <utility>

namespace luz::hybrid {

RadiosityDiffuse::RadiosityDiffuse(const PatchMesh& mesh, RadianceField field)
    : mesh_(mesh), field_(std::move(field)) {
  assert(field_.corner.size() == 3 * mesh_.size() && "the field belongs to another mesh");
}

void RadiosityDiffuse::update(RadianceField field) {
  assert(field.corner.size() == 3 * mesh_.size() && "the field belongs to another mesh");
  field_ = std::move(field);
}

Rgb RadiosityDiffuse::diffuse_radiance(int mesh, int triangle, glm::vec2 barycentrics) const {
  // B/pi at the hit, Gouraud-interpolated from the element's corners (nodal averages), with the
  // texture's detail, as the radiosity picture shows that point.
  return field_.at(mesh_, mesh, triangle, barycentrics) * mesh_.detail.at(mesh, triangle, barycentrics);
}

}  // namespace luz::hybrid
