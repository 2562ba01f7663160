// mass_moments.h — a solid's volume, first and second moments: in closed form for each shape,
// by certified integration over any SDF, and turned into a body's mass, centre and principal
// axes.
//
// Moments are about the frame the solid is given in: V = ∫dV, s = ∫x dV, S = ∫x·xᵀ dV. They add
// for disjoint parts and subtract for a part carved from inside another, and move with the part
// (moved()), so a body made of pieces is the sum of its pieces' moments where the pieces do not
// overlap. Everything else is integrated (integrateSolid).
#pragma once

#include "marchbox/scene/sdf.h"

#include <functional>
#include <string>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace mb {

struct Moments {
    double volume = 0.0;     // m³
    glm::dvec3 first{0.0};   // ∫x dV, m⁴
    glm::dmat3 second{0.0};  // ∫x·xᵀ dV, m⁵
    Moments& operator+=(const Moments& o);
    Moments& operator-=(const Moments& o);
};

// The same solid turned by `turn` (its frame to the new one) and then moved by `move`.
Moments moved(const Moments& m, const glm::dmat3& turn, const glm::dvec3& move);

// The closed form of a solid shape at the origin, as sdObjectLocal draws it: every type, and
// `shell` for the types whose inner surface is the same kind of shape (all but the ellipsoid,
// whose SDF is a bound). False where there is none: `round`, or an ellipsoid's shell.
bool closedFormMoments(const SdfObject& o, Moments* out);

// The certified integral of the solid f < 0 over the cube of half side `half` about the origin.
// A cell whose |f(centre)| is at least its half-diagonal lies wholly inside or outside (f is an
// SDF or a bound of one: it never exceeds the distance to its surface), so only the cells that
// straddle the surface are split, `depth` times. The straddling cells left at the last level
// count by the fraction of them that f says is inside (½ − f/side: exact for a face along the
// grid), and their whole moments are the bound on the error: the estimate is within `bound` of
// the true moments, component by component (|V − V̂| ≤ bound.volume, and so on). The bound is
// the price of the certificate; the estimate itself is far closer (group_body.h, the tests).
struct SolidIntegral {
    Moments value;
    Moments bound;         // |error| ≤ these, each component
    long straddling = 0;   // cells at the last level that the surface may cross
    long evaluations = 0;  // of f
};
using SolidFunction = std::function<float(const glm::vec3&)>;
SolidIntegral integrateSolid(const SolidFunction& f, double half, int depth);
// 256 cells across the cube at the last level. On a box with a hole through it (the tests):
// depth 8 takes 0.1 s, its volume within 1.5e-4 and second moments 4e-4 of the closed form
// (the bound: 8 %, 9 %); depth 9 takes four times as long for errors of 1e-5 (bound 4 %, 6 %).
constexpr int kIntegrationDepth = 8;

// The moments `find` gives for a shape, found once in the process for each `key` (the bytes
// that make the shape): an integral costs a tenth of a second, and a scene's groups are often
// of one shape, run again and again. Thread-safe; the result is the same either way.
Moments rememberedMoments(const std::string& key, const std::function<Moments()>& find);

// A body of `mass` spread uniformly over the solid: density mass / V, centre s / V, and the
// inertia tensor about the centre diagonalised (Jacobi): the body's frame is its centre of mass
// in its principal axes. `axes` turns the principal frame into the solid's; `inertia` holds
// the principal moments in that order.
struct MassProperties {
    double mass;             // kg
    glm::dvec3 inertia;      // principal moments about the body's local x, y, z axes, kg·m²
    glm::dvec3 centre{0.0};  // centre of mass, in the shape's own frame
    glm::dquat axes{1.0, 0.0, 0.0, 0.0};  // principal frame → the shape's frame
};
MassProperties massFromMoments(const Moments& m, double mass);

// Eigenvalues and unit eigenvectors (the columns of `vectors`, a rotation) of a symmetric
// matrix, by cyclic Jacobi rotations.
void symmetricEigen(const glm::dmat3& a, glm::dvec3* values, glm::dmat3* vectors);

}  // namespace mb
