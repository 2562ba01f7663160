// tetra_gradient.h — a distance's gradient from four samples at the corners k of a tetrahedron
// (Quilez): Σ k·f(p + h·k) = 4h·∇f + O(h²). Four samples where central differences take six.
// The corners' odd moment Σ kx·ky·kz leaves a term h times the Hessian's off-diagonal, so the
// direction bends by about h·curvature: h/d at d from an edge.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>

namespace mb {

// The bodies' tetrahedron: h is this fraction of the shape's bound.
constexpr double kTetraStep = 1e-3;

// Whether a gradient of length `length` taken at step h (4h·∇f) straddled a crease of the shape,
// an edge or a corner: there the samples on either side disagree and the length falls short of
// 4h (by 6 % at a right-angled edge), where a smooth surface changes it by (h/R)² and the float
// SDF's rounding by ~3e-5.
inline bool isCreased(double length, double h) { return std::abs(length / (4.0 * h) - 1.0) > 1e-3; }

// How far from a crease the samples clear it: twice the tetrahedron's reach, h·√3, in bounds.
constexpr double kBesideCrease = 2.0 * 1.7320508075688772 * kTetraStep;

// 4h·∇f at p, unnormalised; f takes a float point and returns its distance.
template <typename Distance>
glm::dvec3 tetraGradient(const Distance& f, const glm::vec3& p, float h) {
    const glm::vec3 k[4] = {{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}};
    glm::dvec3 n(0.0);
    for (const glm::vec3& c : k) n += glm::dvec3(c) * double(f(p + c * h));
    return n;
}

}  // namespace mb
