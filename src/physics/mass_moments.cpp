// mass_moments.cpp — closed-form and integrated moments of solids, and the principal frame.
#include "mass_moments.h"

#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <mutex>
#include <numbers>

namespace mb {

using glm::dmat3;
using glm::dvec3;

namespace {

constexpr double kPi = std::numbers::pi;

dmat3 diagonal(double x, double y, double z) { return dmat3(x, 0, 0, 0, y, 0, 0, 0, z); }

Moments centred(double volume, const dmat3& second) { return {volume, dvec3(0.0), second}; }

// A frustum along y from y0 (radius r0) to y1 (radius r1), r linear in y. Every integrand is a
// polynomial in y of degree at most 4 (π·r², π·r²·y, π·r²·y², and π·r⁴/4 for ∫x² over each
// disc), so three Gauss–Legendre points (exact to degree 5) give them exactly.
Moments frustum(double y0, double y1, double r0, double r1) {
    Moments m;
    if (y1 <= y0) return m;
    const double node = std::sqrt(0.6), half = 0.5 * (y1 - y0), mid = 0.5 * (y0 + y1);
    const double nodes[3] = {-node, 0.0, node}, weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double across = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double y = mid + half * nodes[k], u = (y - y0) / (y1 - y0);
        const double r = r0 + (r1 - r0) * u, w = weights[k] * half;
        const double disc = kPi * r * r;
        m.volume += w * disc;
        m.first.y += w * disc * y;
        m.second[1][1] += w * disc * y * y;
        across += w * disc * r * r / 4.0;
    }
    m.second[0][0] = m.second[2][2] = across;
    return m;
}

Moments sphere(double r) {
    const double v = 4.0 / 3.0 * kPi * r * r * r;
    return centred(v, diagonal(v * r * r / 5.0, v * r * r / 5.0, v * r * r / 5.0));
}

Moments box(const dvec3& half) {
    const double v = 8.0 * half.x * half.y * half.z;
    const dvec3 s = v / 3.0 * half * half;
    return centred(v, diagonal(s.x, s.y, s.z));
}

// Ring R in the x-z plane, tube a: ∫y² = V·a²/4, ∫x² = ∫z² = V·(R²/2 + 3a²/8).
Moments torus(double ring, double tube) {
    const double v = 2.0 * kPi * kPi * ring * tube * tube;
    const double across = v * (0.5 * ring * ring + 0.375 * tube * tube);
    return centred(v, diagonal(across, v * tube * tube / 4.0, across));
}

Moments cylinder(double r, double h) {
    const double v = kPi * r * r * h;
    return centred(v, diagonal(v * r * r / 4.0, v * h * h / 12.0, v * r * r / 4.0));
}

// The cylinder and its two caps, a sphere split at y = ±h/2: each cap of V_s/2 has ∫u = 3r/8 of
// it along its axis and ∫u² = r²/5, so the caps give V_s·(h²/4 + 3hr/8 + r²/5) along y.
Moments capsule(double r, double h) {
    const double vc = kPi * r * r * h, vs = 4.0 / 3.0 * kPi * r * r * r;
    const double across = vc * r * r / 4.0 + vs * r * r / 5.0;
    const double along = vc * h * h / 12.0 + vs * (h * h / 4.0 + 0.375 * h * r + r * r / 5.0);
    return centred(vc + vs, diagonal(across, along, across));
}

Moments ellipsoid(const dvec3& a) {
    const double v = 4.0 / 3.0 * kPi * a.x * a.y * a.z;
    const dvec3 s = v / 5.0 * a * a;
    return centred(v, diagonal(s.x, s.y, s.z));
}

Moments cone(double h, double r1, double r2) { return frustum(-0.5 * h, 0.5 * h, r1, r2); }

// The solid inside the cone's surface moved t inwards: each face of its profile (base, top,
// slant) moves in by t, the slant by t·√(1 + k²) along the radius (k = (r1 − r2)/h); where the
// slant reaches the axis below the top, it ends there in a point.
Moments coneInside(double h, double r1, double r2, double t) {
    const double k = (r1 - r2) / h, in = t * std::sqrt(1.0 + k * k);
    const double y0 = -0.5 * h + t, rho0 = r1 - k * t - in;
    double y1 = 0.5 * h - t, rho1 = r2 + k * t - in;
    if (rho0 <= 0.0) return {};
    if (rho1 < 0.0) {
        y1 = y0 + rho0 / k;
        rho1 = 0.0;
    }
    return frustum(y0, y1, rho0, rho1);
}

Moments solidOf(const SdfObject& o) {
    const double r = o.radius, h = o.height;
    switch (o.type) {
        case ShapeType::Sphere:
            return sphere(r);
        case ShapeType::Box:
            return box(dvec3(o.size));
        case ShapeType::Torus:
            return torus(r, o.minor);
        case ShapeType::Capsule:
            return capsule(r, h);
        case ShapeType::Cylinder:
            return cylinder(r, h);
        case ShapeType::Cone:
            return cone(h, r, o.top);
        case ShapeType::Ellipsoid:
            return ellipsoid(dvec3(o.size));
    }
    return {};
}

// The level set at −t of an exact SDF: the same kind of shape, each face moved in by t.
Moments insideOf(const SdfObject& o, double t) {
    const double r = o.radius, h = o.height;
    switch (o.type) {
        case ShapeType::Sphere:
            return r > t ? sphere(r - t) : Moments{};
        case ShapeType::Box: {
            const dvec3 in = dvec3(o.size) - t;
            return glm::all(glm::greaterThan(in, dvec3(0.0))) ? box(in) : Moments{};
        }
        case ShapeType::Torus:
            return o.minor > t ? torus(r, o.minor - t) : Moments{};
        case ShapeType::Capsule:
            return r > t ? capsule(r - t, h) : Moments{};
        case ShapeType::Cylinder:
            return r > t && h > 2.0 * t ? cylinder(r - t, h - 2.0 * t) : Moments{};
        case ShapeType::Cone:
            return coneInside(h, r, o.top, t);
        case ShapeType::Ellipsoid:  // a bound (closedFormMoments does not ask)
            break;
    }
    return {};
}

dmat3 outer(const dvec3& a, const dvec3& b) {
    dmat3 m;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = a[r] * b[c];
    return m;
}

// A cube of half side h about c, wholly inside: V = 8h³, s = V·c, S = V·(c·cᵀ + h²/3·1).
Moments cube(const dvec3& c, double h, double weight) {
    const double v = weight * 8.0 * h * h * h;
    return {v, v * c, v * (outer(c, c) + dmat3(h * h / 3.0))};
}

// What a straddling cube can be off by: its whole moments, of |x| at the far corner.
Moments cubeBound(const dvec3& c, double h) {
    const double v = 8.0 * h * h * h;
    const dvec3 far = glm::abs(c) + h;
    return {v, v * far, v * outer(far, far)};
}

struct Integrator {
    const SolidFunction& f;
    int depth;
    double margin;  // the float evaluation's rounding, kept off the certificate
    SolidIntegral out;

    void cell(const dvec3& c, double h, int level) {
        const double d = double(f(glm::vec3(c)));
        ++out.evaluations;
        const double reach = h * std::sqrt(3.0) + margin;
        if (d <= -reach) {
            out.value += cube(c, h, 1.0);
            return;
        }
        if (d >= reach) return;
        if (level == depth) {
            // The fraction inside, from f at the centre: exact for a face along the grid.
            const double inside = std::clamp(0.5 - d / (2.0 * h), 0.0, 1.0);
            if (inside > 0.0) out.value += cube(c, h, inside);
            out.bound += cubeBound(c, h);
            ++out.straddling;
            return;
        }
        const double q = 0.5 * h;
        for (int k = 0; k < 8; ++k)
            cell(c + q * dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1), q, level + 1);
    }
};

}  // namespace

Moments& Moments::operator+=(const Moments& o) {
    volume += o.volume;
    first += o.first;
    second += o.second;
    return *this;
}

Moments& Moments::operator-=(const Moments& o) {
    volume -= o.volume;
    first -= o.first;
    second -= o.second;
    return *this;
}

// x' = R·x + t: ∫x' = R·s + V·t, ∫x'·x'ᵀ = R·S·Rᵀ + R·s·tᵀ + t·(R·s)ᵀ + V·t·tᵀ.
Moments moved(const Moments& m, const dmat3& turn, const dvec3& move) {
    const dvec3 s = turn * m.first;
    return {m.volume, s + m.volume * move,
            turn * m.second * glm::transpose(turn) + outer(s, move) + outer(move, s) +
                m.volume * outer(move, move)};
}

bool closedFormMoments(const SdfObject& o, Moments* out) {
    // A bound's level set at −t is no shape moved in: only an exact SDF's wall has a closed form.
    if (o.round > 0.0f || (o.shell > 0.0f && !shapeRow(o.type).exact)) return false;
    *out = solidOf(o);
    if (o.shell > 0.0f) *out -= insideOf(o, double(o.shell));
    return true;
}

Moments rememberedMoments(const std::string& key, const std::function<Moments()>& find) {
    static std::mutex lock;
    static std::map<std::string, Moments> found;
    constexpr size_t kMostShapes = 4096;  // then start again: a few hundred kB at most
    {
        const std::lock_guard<std::mutex> hold(lock);
        if (const auto it = found.find(key); it != found.end()) return it->second;
    }
    const Moments m = find();
    const std::lock_guard<std::mutex> hold(lock);
    if (found.size() >= kMostShapes) found.clear();
    found.emplace(key, m);
    return m;
}

SolidIntegral integrateSolid(const SolidFunction& f, double half, int depth) {
    Integrator in{f, depth, 1e-6 * half, {}};
    in.cell(dvec3(0.0), half, 0);
    return in.out;
}

void symmetricEigen(const dmat3& m, dvec3* values, dmat3* vectors) {
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = 0.5 * (m[c][r] + m[r][c]);
    static constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-30 * diag) break;
        for (const auto& pq : kPairs) {
            const int p = pq[0], q = pq[1];
            if (a[p][q] == 0.0) continue;
            // The rotation in the p-q plane that zeroes a[p][q] (Numerical Recipes' Jacobi).
            const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            const double t =
                (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
            const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
            for (int k = 0; k < 3; ++k) {
                const double kp = a[k][p], kq = a[k][q];
                a[k][p] = c * kp - s * kq;
                a[k][q] = s * kp + c * kq;
            }
            for (int k = 0; k < 3; ++k) {
                const double pk = a[p][k], qk = a[q][k];
                a[p][k] = c * pk - s * qk;
                a[q][k] = s * pk + c * qk;
            }
            for (int k = 0; k < 3; ++k) {
                const double kp = v[k][p], kq = v[k][q];
                v[k][p] = c * kp - s * kq;
                v[k][q] = s * kp + c * kq;
            }
        }
    }
    *values = dvec3(a[0][0], a[1][1], a[2][2]);
    for (int c = 0; c < 3; ++c) (*vectors)[c] = dvec3(v[0][c], v[1][c], v[2][c]);
}

// About the centre c: S_c = S − V·c·cᵀ, and I = ρ·(tr S_c·1 − S_c) with ρ = m / V.
MassProperties massFromMoments(const Moments& m, double mass) {
    MassProperties mp{mass, dvec3(0.0)};
    if (m.volume <= 0.0) return mp;
    const double density = mass / m.volume;
    mp.centre = m.first / m.volume;
    const dmat3 about = m.second - m.volume * outer(mp.centre, mp.centre);
    const double trace = about[0][0] + about[1][1] + about[2][2];
    const dmat3 inertia = density * (dmat3(trace) - about);
    dmat3 axes;
    symmetricEigen(inertia, &mp.inertia, &axes);
    mp.axes = glm::normalize(glm::quat_cast(axes));
    return mp;
}

}  // namespace mb
