// physics_step_bench.cpp — times PhysicsWorld::step on the report's pile, for profiling.
//
//   physics_step_bench [mixed|tables] COUNT STEPS [FROM [THREADS [RADIUS]]]   (pileScene(COUNT,
//   7, RADIUS), default settings; RADIUS 0.2 unless given, the headline pile of the physics
//   report; `mixed`: mixedPileScene, `tables`: tablePileScene (RADIUS its tables' size, 0.25
//   unless given), all awake, as bullet_bench times them)
// Prints ms per step, the last step's contacts and awake bodies, and a state checksum so that
// an optimisation can be checked to leave the results bit for bit alone. Small STEPS under
// valgrind --tool=callgrind give deterministic instruction counts; with --instr-atstart=no only
// steps FROM.. are counted (the settled pile, not the free fall of the first steps).
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#endif

int main(int argc, char** argv) {
    const bool mixed = argc > 1 && std::strcmp(argv[1], "mixed") == 0;
    const bool tables = argc > 1 && std::strcmp(argv[1], "tables") == 0;
    if (mixed || tables) --argc, ++argv;
    const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 180;
    const int from = argc > 3 ? std::atoi(argv[3]) : 0;
    mb::PhysicsSettings settings;
    if (argc > 4) settings.threads = std::atoi(argv[4]);
    const float radius = argc > 5 ? float(std::atof(argv[5])) : tables ? 0.25f : 0.2f;
    settings.sleep = !mixed && !tables;
    mb::PhysicsWorld world(mixed    ? mb::mixedPileScene(count, 7, radius)
                           : tables ? mb::tablePileScene(count, 7, radius)
                                    : mb::pileScene(count, 7, radius),
                           settings);
    double busy = 0.0;
    for (int i = 0; i < steps; ++i) {
        if (i == from) CALLGRIND_START_INSTRUMENTATION;
        const auto start = std::chrono::steady_clock::now();
        world.step();
        busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    unsigned long long sum = 0;  // FNV-1a over positions and velocities (and orientations)
    const auto add = [&sum](const auto& values) {
        unsigned char bytes[sizeof values];
        std::memcpy(bytes, &values, sizeof values);
        for (unsigned char c : bytes) sum = (sum ^ c) * 1099511628211ull;
    };
    for (int i = 0; i < world.bodyCount(); ++i) {
        const mb::PhysicsBody& b = world.body(i);
        add(std::array<double, 6>{b.pos.x, b.pos.y, b.pos.z, b.vel.x, b.vel.y, b.vel.z});
    }
    for (int i = 0; i < world.rigidCount(); ++i) {
        const mb::RigidState r = world.rigid(i);
        add(std::array<double, 13>{r.pos.x, r.pos.y, r.pos.z, r.vel.x, r.vel.y, r.vel.z, r.spin.x,
                                   r.spin.y, r.spin.z, r.orient.w, r.orient.x, r.orient.y,
                                   r.orient.z});
    }
    std::printf(
        "%d %s, %d steps: %.3f ms/step, %d contacts in %d levels, %d awake, penetration %.3g, "
        "state %016llx\n",
        count,
        tables  ? "tables"
        : mixed ? "bodies"
                : "spheres",
        steps, 1e3 * busy / steps, world.stats().contacts, world.stats().levels,
        world.stats().awake, world.stats().maxPenetration, sum);
}
