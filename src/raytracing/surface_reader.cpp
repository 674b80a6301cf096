// The surface at a hit, shared by the Whitted and path tracers. See surface_reader.h.
#include "raytracing/surface_reader.h"

#include <cstdint>

#include "raytracing/hit_math.h"

namespace luz::rt {

void SurfaceReader::surface_at(const Ray& ray, const Hit& hit, SurfacePoint& p) const {
  const Mesh& mesh = scene_.meshes[size_t(hit.mesh)];
  const size_t t = size_t(hit.triangle);
  const uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1], i2 = mesh.indices[3 * t + 2];
  const SurfaceGeometry g = surface_geometry(mesh.positions[i0], mesh.positions[i1], mesh.positions[i2],
                                             mesh.normals[i0], mesh.normals[i1], mesh.normals[i2],
                                             hit.u, hit.v, ray.direction);
  p.position = g.position;
  p.geometric = g.geometric;
  p.N = g.N;
  p.front = g.front;
  p.mesh = hit.mesh;
  p.triangle = hit.triangle;
  p.barycentrics = glm::vec2(hit.u, hit.v);
  p.uv = mesh.uv_at(t, p.barycentrics);
  p.material = &material_of(mesh);
}

Rgb SurfaceReader::kd_at(const SurfacePoint& p) const {
  return kd_at(*p.material, p.mesh, p.triangle, p.barycentrics, p.uv);
}

Rgb SurfaceReader::kd_at(const Material& o, int mesh_index, int triangle, glm::vec2 barycentrics,
                         glm::vec2 uv) const {
  const Mesh& mesh = scene_.meshes[size_t(mesh_index)];
  // COLOR_0 multiplies kd (SCENES.md), interpolated as the rasteriser interpolates it.
  const Rgb kd = o.kd * mesh.colour_at(size_t(triangle), barycentrics);
  if (!samples_texture(o, mesh)) return kd;
  // GL's linear filter on the base level: the rasteriser's mipmaps only differ where a texel is
  // smaller than a pixel.
  return kd * scene_.textures[size_t(o.kd_texture)].sample(uv);
}

}  // namespace luz::rt
