// group_mass_bench.cpp — a group's integrated mass properties against their closed form, as
// markdown for the physics report: a box with a hole through it (holedBoxScene).
//
// A group takes the mass its file gives; the integral of its solid says where that mass lies:
// its volume (so its density), its centre of mass and its inertia. Each is printed with its
// error against the closed form and the bound that the integral's certificate on the moments
// (mass_moments.h) carries through to it, by interval arithmetic. The integral and its bound are
// the physics layer's own (src/physics/), read here as the physics tests read them.
#include "group_body.h"
#include "mass_moments.h"

#include "marchbox/report/median.h"
#include "marchbox/report/physics_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

// The values a quantity may take, given those its operands may: [lo, hi].
struct Interval {
    double lo, hi;
    Interval(double v) : lo(v), hi(v) {}  // a number: an interval of one
    Interval(double l, double h) : lo(l), hi(h) {}
};
Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
Interval operator*(Interval a, Interval b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Interval operator/(Interval a, Interval b) {  // b > 0 here: a volume
    return a * Interval(1.0 / b.hi, 1.0 / b.lo);
}

// What the simulator makes of moments (massFromMoments, before it finds the principal axes):
// the centre s/V, and the inertia about it of `mass` spread over V, m/V·(tr(S_c)·1 − S_c) with
// S_c = S − s·sᵀ/V. T is double for a value, Interval for the values it may take.
template <class T>
struct Properties {
    T volume = 0.0, centre[3] = {0.0, 0.0, 0.0};
    T inertia[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
};

template <class T>
Properties<T> properties(const T& volume, const T (&first)[3], const T (&second)[3][3],
                         double mass) {
    Properties<T> p;
    p.volume = volume;
    T about[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    for (int i = 0; i < 3; ++i) {
        p.centre[i] = first[i] / volume;
        for (int j = 0; j < 3; ++j) about[i][j] = second[i][j] - first[i] * first[j] / volume;
    }
    const T trace = about[0][0] + about[1][1] + about[2][2];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            p.inertia[i][j] = T(mass) * ((i == j ? trace : T(0.0)) - about[i][j]) / volume;
    return p;
}

Properties<double> propertiesOf(double volume, const glm::dvec3& s, const glm::dmat3& S,
                                double mass) {
    double first[3], second[3][3];
    for (int i = 0; i < 3; ++i) {
        first[i] = s[i];
        for (int j = 0; j < 3; ++j) second[i][j] = S[i][j];
    }
    return properties(volume, first, second, mass);
}

Properties<Interval> possibleProperties(const mb::SolidIntegral& integral, double mass) {
    const mb::Moments &v = integral.value, &b = integral.bound;
    const auto around = [](double x, double bound) { return Interval(x - bound, x + bound); };
    Interval first[3] = {0.0, 0.0, 0.0},
             second[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    for (int i = 0; i < 3; ++i) {
        first[i] = around(v.first[i], b.first[i]);
        for (int j = 0; j < 3; ++j) second[i][j] = around(v.second[i][j], b.second[i][j]);
    }
    return properties(around(v.volume, b.volume), first, second, mass);
}

// One row: the integral's value, the closed form's, the error and how far the certificate lets
// the value be from the truth.
void row(const char* name, double value, double exact, Interval possible) {
    const double bound = std::max(possible.hi - value, value - possible.lo);
    std::printf("| %s | %.7g | %.7g | %.2g | %.2g |\n", name, value, exact, value - exact, bound);
}

double msToIntegrate(const mb::GroupShape& shape) {
    constexpr int kRuns = 5;  // a median of five: each run is a tenth of a second
    std::vector<double> ms;
    for (int k = 0; k < kRuns; ++k) {
        const auto start = std::chrono::steady_clock::now();
        mb::groupMoments(shape);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    return mb::median(ms);
}

}  // namespace

int main() {
    const mb::HoledBox holed;
    const mb::GroupShape shape = mb::groupShapeOf(mb::holedBoxScene(holed), 0);
    const mb::GroupMoments found = mb::groupMoments(shape);
    if (found.closedForm) {
        std::printf("The holed box was not integrated: its members were taken as disjoint.\n");
        return 1;
    }
    const double mass = holed.mass;
    const mb::Moments& m = found.moments;
    const mb::SolidMoments closed = mb::holedBoxMoments(holed);
    const Properties<double> value = propertiesOf(m.volume, m.first, m.second, mass);
    const Properties<double> exact = propertiesOf(closed.volume, closed.first, closed.second, mass);
    const Properties<Interval> possible = possibleProperties(found.integral, mass);
    std::printf(
        "| %.0f kg box, half extents %g × %g × %g m, less a hole of r = %g m %g m off its middle "
        "| integral | closed form | error | certified bound |\n| --- | ---: | ---: | ---: | ---: "
        "|\n",
        double(mass), holed.half.x, holed.half.y, holed.half.z, holed.radius, holed.offset);
    row("volume (m³)", value.volume, exact.volume, possible.volume);
    const char* axes = "xyz";
    char name[64];
    for (int i = 0; i < 3; ++i) {
        std::snprintf(name, sizeof name, "centre of mass %c (m)", axes[i]);
        row(name, value.centre[i], exact.centre[i], possible.centre[i]);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            std::snprintf(name, sizeof name, "inertia I%c%c about the centre (kg·m²)", axes[i],
                          axes[j]);
            row(name, value.inertia[i][j], exact.inertia[i][j], possible.inertia[i][j]);
        }
    std::printf(
        "\nIntegrated to depth %d (%d cells across its bounding cube at the last level): %ld "
        "evaluations of its SDF, %ld cells left straddling the surface, **%.0f ms** (median of "
        "5). The mass itself is the file's, exactly.\n",
        mb::kIntegrationDepth, 1 << mb::kIntegrationDepth, found.integral.evaluations,
        found.integral.straddling, msToIntegrate(shape));
    return 0;
}
