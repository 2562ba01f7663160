// reference_trace.cpp — the geometry of the CPU reference (docs/shading-model.md §2, §3, §5,
// §6): where a ray first meets the scene, the normal there, shadow rays and occlusion.
//
// The ground is a plane, so rays meet it in closed form: the picture a march converges to,
// however grazing the ray. Only the objects are marched, with the SDF mirror.
#include "reference_model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace mb::reference {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxMarchSteps = 4096;
constexpr int kMaxShadowSteps = 20000;  // tenth steps near surfaces take many; see softShadow
constexpr double kHitTolerance = 1e-5;  // × max(1, |p|): a few float ulps of the mirror's input
constexpr int kBisections = 40;
constexpr double kCreaseCosine = 0.999;  // 2.6 degrees

double objectField(const Model& m, dvec3 p) { return mapObjects(m.sdf, glm::vec3(p)).d; }
int objectAt(const Model& m, dvec3 p) { return mapObjects(m.sdf, glm::vec3(p)).object; }

double groundField(const Model& m, dvec3 p) {
    return m.sdf.ground ? p.y - double(m.sdf.floor) : kInfinity;
}

double tolerance(dvec3 p) { return kHitTolerance * std::max(1.0, glm::length(p)); }

// The zero of the object field between a (outside) and b (inside).
double bisect(const Model& m, dvec3 o, dvec3 d, double a, double b) {
    for (int i = 0; i < kBisections && b - a > 1e-12 * std::max(1.0, b); ++i) {
        double mid = 0.5 * (a + b);
        (objectField(m, o + d * mid) > 0.0 ? a : b) = mid;
    }
    return 0.5 * (a + b);
}

// Sphere tracing down to a tolerance far below the scene's epsilon, then bisection across the
// surface once the march has it bracketed: the hit is the field's zero, not a point near it.
Hit marchObjects(const Model& m, dvec3 o, dvec3 d, double tLimit) {
    double tEnd = std::min(tLimit, beyondEverything(m, o));
    double t = 0.0, tPrev = 0.0;
    for (int i = 0; i < kMaxMarchSteps && t <= tEnd; ++i) {
        dvec3 p = o + d * t;
        double f = objectField(m, p), tol = tolerance(p);
        if (f < tol) {
            if (f < 0.0) {
                t = bisect(m, o, d, tPrev, t);  // stepped over a bound that was not exact
            } else if (double probe = t + 2.0 * tol; objectField(m, o + d * probe) < 0.0) {
                t = bisect(m, o, d, t, probe);
            }
            return t <= tLimit ? Hit{true, t, objectAt(m, o + d * t)} : Hit{};
        }
        tPrev = t;
        t += f;
    }
    return {};
}

}  // namespace

// A top-level group's bound holds its members' mirrors and copies, which its objects' own
// bounds (about the modelled copy) do not.
double beyondEverything(const Model& m, dvec3 origin) {
    double far = 0.0;
    for (const SdfObject& o : m.sdf.objects)
        far = std::max(far, glm::length(dvec3(o.pos) - origin) + double(o.bound));
    for (const SdfGroup& g : m.sdf.groups)
        if (g.parent < 0)
            far = std::max(far, glm::length(dvec3(g.pos) - origin) + double(g.bound + g.blend));
    return far;
}

double field(const Model& m, dvec3 p) { return std::min(objectField(m, p), groundField(m, p)); }

Hit firstHit(const Model& m, dvec3 o, dvec3 d) {
    // A ray that starts inside the solid stops where it is, on the deeper of the two.
    double inObjects = objectField(m, o), inGround = groundField(m, o);
    if (std::min(inObjects, inGround) <= 0.0)
        return {true, 0.0, inObjects <= inGround ? objectAt(m, o) : kHitGround};
    Hit ground;
    if (m.sdf.ground && d.y < 0.0) ground = {true, inGround / -d.y, kHitGround};
    Hit objects =
        m.sdf.objects.empty() ? Hit{} : marchObjects(m, o, d, ground.hit ? ground.t : kInfinity);
    return objects.hit ? objects : ground;
}

namespace {

dvec3 gradient(const Model& m, dvec3 p, double h) {
    return {field(m, p + dvec3(h, 0, 0)) - field(m, p - dvec3(h, 0, 0)),
            field(m, p + dvec3(0, h, 0)) - field(m, p - dvec3(0, h, 0)),
            field(m, p + dvec3(0, 0, h)) - field(m, p - dvec3(0, 0, h))};
}

dvec3 unitOrUp(dvec3 g) {
    double len = glm::length(g);
    return len > 1e-300 ? g / len : dvec3(0, 1, 0);
}

}  // namespace

// Central differences of the whole field. The step grows with |p| so that it always spans many
// float ulps of the mirror's input; where the gradient vanishes (a sphere's centre), +y. On a
// smooth surface a 16 times wider step gives the same normal; where it does not, p lies within
// a few steps of a crease, whose normal every renderer blends differently.
SurfaceNormal normalAt(const Model& m, dvec3 p, int object) {
    if (object == kHitGround) return {dvec3(0, 1, 0), false};
    double h = 1e-4 * std::max(1.0, glm::length(p));
    dvec3 n = unitOrUp(gradient(m, p, h)), wide = unitOrUp(gradient(m, p, 16.0 * h));
    return {n, glm::dot(n, wide) < kCreaseCosine};
}

// Secondary rays start a little off the surface, past the epsilon that would stop them at once:
// 2 epsilon, or 4e-5 |p| far out where float positions are coarser than that.
dvec3 liftOff(dvec3 p, dvec3 n, double epsilon) {
    return p + n * std::max(2.0 * epsilon, 4e-5 * glm::length(p));
}

namespace {

// Past every object only the ground is left, a plane: blocked if the ray crosses it within
// reach; else its term k·height/t falls monotonically in t, so its least value is at the reach.
double groundTail(const Model& m, dvec3 o, dvec3 l, double reach, double res, double k) {
    if (!m.sdf.ground || reach == kInfinity) return res;
    double height = groundField(m, o + l * reach);
    if (height < m.epsilon) return 0.0;
    return std::min(res, k * height / reach);
}

double hardShadow(const Model& m, dvec3 o, dvec3 l, double reach) {
    double tObjects = std::min(reach, beyondEverything(m, o)), t = 0.0;
    for (int i = 0; i < kMaxShadowSteps && t < tObjects; ++i) {
        double f = field(m, o + l * t);
        if (f < m.epsilon) return 0.0;
        t += f;
    }
    if (t >= reach) return 1.0;
    return groundTail(m, o, l, reach, 1.0, 1.0) > 0.0 ? 1.0 : 0.0;
}

// The penumbra term is the least of k·f(t)/t along the ray (Quilez), a continuous minimum.
// Steps of a tenth of the distance sample it densely enough that a fiftieth changes no pixel of
// the test images; sphere tracing's whole steps can jump past the closest approach to a box edge.
double softShadow(const Model& m, dvec3 o, dvec3 l, double reach) {
    double k = m.softness, res = 1.0, tObjects = std::min(reach, beyondEverything(m, o)), t = 0.0;
    for (int i = 0; i < kMaxShadowSteps && t < tObjects; ++i) {
        double f = field(m, o + l * t);
        if (f < m.epsilon) return 0.0;
        if (t > 0.0) res = std::min(res, k * f / t);
        if (res < 1e-4) return 0.0;  // smoothstep of it is below 3e-8
        t += 0.1 * f;
    }
    if (t < reach) res = groundTail(m, o, l, reach, res, k);
    return smoothstep(0.0, 1.0, std::clamp(res, 0.0, 1.0));
}

}  // namespace

double visibility(const Model& m, dvec3 origin, dvec3 towards, double reach) {
    switch (m.scene->render.shadows) {
        case 1:
            return hardShadow(m, origin, towards, reach);
        case 2:
            return softShadow(m, origin, towards, reach);
        default:
            return 1.0;
    }
}

// Five probes up the normal, 1 to 13 cm: wherever the field is shorter than the probe's height,
// something is that much closer than open ground would be. Nearer probes weigh more.
double occlusion(const Model& m, dvec3 p, dvec3 n) {
    double missing = 0.0, weight = 1.0;
    for (int i = 0; i < 5; ++i, weight *= 0.95) {
        double h = 0.01 + 0.03 * i;
        missing += weight * (h - field(m, p + n * h));
    }
    return std::clamp(1.0 - 3.0 * missing, 0.0, 1.0);
}

}  // namespace mb::reference
