#pragma once
// Draws a radiosity solution through GL: the patch mesh with the radiance B/pi of a
// RadianceField, Gouraud-interpolated from the vertices (or flat per patch), optionally with the
// patch outlines. Back sides of patches are black (they have no radiosity).
#include <memory>

#include <glm/vec2.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_options.h"
#include "radiosity/vertex_colours.h"

namespace luz {

class RadiosityRenderer {
public:
  // Uploads the patch mesh to the current GL context (current for the renderer's lifetime).
  // `scene` gives the background; both must outlive the renderer.
  RadiosityRenderer(const Scene& scene, const PatchMesh& mesh);
  ~RadiosityRenderer();
  RadiosityRenderer(const RadiosityRenderer&) = delete;
  RadiosityRenderer& operator=(const RadiosityRenderer&) = delete;

  // New colours (after solver steps), and the elements again if adaptive subdivision changed
  // them. Uses options.flat_patches to pick patch or vertex values. `texture_detail`: the
  // colours are B/pi, which a mesh's kd texture modulates (texture_detail.h); false for colours
  // that are no radiance (the viewer's heat map).
  void update(const RadianceField& field, const RadiosityOptions& options, bool texture_detail = true);

  // Draws into the currently bound framebuffer of the given size. `highlight`: a shooting patch
  // (all its elements) drawn in a flat highlight colour (the solver's last shooter), -1 for none.
  // `shift`: the picture moved by that fraction of a pixel (a sample position in the pixel).
  void draw(const Camera& camera, int width, int height, const RadiosityOptions& options,
            int highlight = -1, glm::vec2 shift = glm::vec2(0.0f));
  // Renders into a float framebuffer and reads back linear radiance (row 0 at the top), the mean
  // of options.pixel_samples pictures at the points of a regular grid over the pixel.
  Image render(const Camera& camera, int width, int height, const RadiosityOptions& options,
               int highlight = -1);

private:
  void upload_elements();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luz
