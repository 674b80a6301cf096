#pragma once
// The unoccluded form factor from a receiving element to a shooting patch, F(element -> patch),
// by Lambert's contour integral (polygon_form_factor.h), integrated over the element where the
// integrand varies fastest: from the element's centroid far from the patch, from 3, 12 or 48
// points of the element near it, more the closer it is. Both analytic ways of slide 40's
// "multitud de métodos" use it; they differ only in where the visibility comes from (the
// hemicube, or rays).
#include "radiosity/patch_mesh.h"

namespace luz {

// Elements whose centre lies within this many of the shooting patch's radii (centroid to
// farthest corner) are near it: integrated over their area, not from their centroid, and (the
// solver) lit by each of the patch's elements with its own factor.
inline constexpr float kNearRadii = 3.0f;
bool near_the_patch(const Patch& element, const ShootingPatch& shooter);

double element_to_patch_form_factor(const PatchMesh& mesh, const Patch& element,
                                    const ShootingPatch& shooter);

}  // namespace luz
