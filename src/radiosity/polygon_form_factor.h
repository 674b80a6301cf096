#pragma once
// The exact form factor of slide 40's "multitud de métodos": from
// a point to a polygon, by Lambert's contour integral (Lambert 1760; Hottel & Sarofim,
// "Radiative Transfer", 1967; Baum, Rushmeier & Winget, SIGGRAPH 1989, use it where the
// hemicube's point-to-area estimate fails, for receivers close to the shooter):
//
//   F(dA -> P) = 1/(2 pi) * sum over the polygon's edges k of  gamma_k (n . G_k),
//   G_k = unit(R_k x R_{k+1}),  gamma_k = the angle between R_k and R_{k+1},
//
// with R_k the vector from the point to polygon vertex k and n the point's unit normal. It
// integrates cos(theta) cos(theta') / (pi r^2) over the polygon exactly, with no visibility:
// the caller supplies that (from the hemicube, or from rays: shooting.cpp, ray_form_factors.cpp).
// The part of the polygon below the point's tangent plane is clipped off first (the formula
// assumes it sees all of it).
//
// The solver integrates it over a receiving element (element_form_factor.h): the light element j
// gets is rho_j F(j -> patch) unshot, with F(j -> patch) near the patch the mean of this formula
// at three points of the element (the degree-2 quadrature points (2/3, 1/6, 1/6)) or more.
#include <span>

#include <glm/vec3.hpp>

namespace luz {

// From the point x with unit normal n to the polygon with vertices counter-clockwise seen from
// its front. 0 if the polygon shows x its back or lies wholly below x's tangent plane.
double point_to_polygon_form_factor(const glm::vec3& x, const glm::vec3& n,
                                    std::span<const glm::vec3> polygon);

// The same in single precision, about twice as fast; what the solver uses. Float's seven digits
// leave the factor good to about 1e-6 of itself, and 3e-4 at worst where the edges' terms nearly
// cancel (a sliver seen edge-on, a polygon many hundreds of its sizes away).
double point_to_polygon_form_factor_single(const glm::vec3& x, const glm::vec3& n,
                                        std::span<const glm::vec3> polygon);

// The single-precision factor averaged over the triangle (a, b, c) as a receiver (its normal n), by the three-point
// rule above on each of 4^splits similar sub-triangles: F from the triangle's area to the polygon.
// The integrand varies as log(distance) next to an edge the two share, where three points are
// 1.5% off; one split brings that to a few tenths of a percent.
double triangle_to_polygon_form_factor(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                       const glm::vec3& n, std::span<const glm::vec3> polygon,
                                       int splits = 0);

}  // namespace luz
