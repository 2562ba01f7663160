// tetra_gradient.h — a distance's gradient from four samples at the corners k of a tetrahedron
// (Quilez): Σ k·f(p + h·k) = 4h·∇f + O(h²). Four samples where central differences take six.
// The corners' odd moment Σ kx·ky·kz leaves a term h times the Hessian's off-diagonal, so the
// direction bends by about h·curvature: h/d at d from an edge.
#pragma once

#include <glm/vec3.hpp>

namespace mb {

// 4h·∇f at p, unnormalised; f takes a float point and returns its distance.
template <typename Distance>
glm::dvec3 tetraGradient(const Distance& f, const glm::vec3& p, float h) {
    const glm::vec3 k[4] = {{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}};
    glm::dvec3 n(0.0);
    for (const glm::vec3& c : k) n += glm::dvec3(c) * double(f(p + c * h));
    return n;
}

}  // namespace mb
