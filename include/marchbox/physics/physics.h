// marchbox/physics/physics.h — the rigid-body simulator.
//
// [SECTION] Settings
// [SECTION] Bodies and statistics
// [SECTION] PhysicsWorld: one fixed step at a time
// [SECTION] Driving it: simulate() and the frame accumulator
//
// The scene's World gives gravity, restitution, friction and rolling resistance; PhysicsSettings
// holds how the method runs. Dynamic objects (Object::dynamic()) move: solid spheres through the
// solver below, every other shape as a turning rigid body (rigid_bodies.h, in the same
// substeps), and so does each dynamic top-level group (Group::dynamic()), as one rigid body of
// its combined solid. Every other object, and the ground plane, is a static collider seen
// through its SDF (marchbox/scene/sdf.h). The state is double precision so that a sphere 1e5 m
// from the origin still resolves millimetres; the scene keeps floats.
//
// One step of dt is split into `substeps` soft steps (Box2D v3's "soft step"), more where a
// rigid contact joins masses over 100 times apart (a soft row is as stiff as its lighter body):
//   collide once (speculative contacts, warm started from the last step); resolve the step's
//   impacts at their times of impact, one after another (impacts.h); then per substep
//   integrate velocities → warm start → solve (soft, with bias) → integrate positions → relax
//   (rigid, no bias); then restitution for what the impacts left, the impacts' position
//   corrections, a continuous sweep for fast spheres, and sleep. A contact with a curved static
//   surface is followed every substep, RATTLE's way: the solve pass aims the substep's path at
//   the surface, and the relax pass works along the normal where the path ended.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Settings
//-----------------------------------------------------------------------------
enum class Integrator : int {
    SymplecticEuler = 0,  // v += g·h; x += v·h (Box2D): first order, free-fall error g·t·h/2
    ExactGravity = 1,     // x += v·h − ½·g·h² while no contact pushes: exact for free flight
};

struct PhysicsSettings {
    double dt = 1.0 / 120;   // fixed step, s
    int substeps = 4;        // soft steps per step; more across a mass ratio over 100
                             // and under a stack over 19 bodies deep
    int iterations = 1;      // solve and relax passes per substep
    double maxFrame = 0.25;  // a longer frame is clamped to this (StepAccumulator)
    Integrator integrator = Integrator::ExactGravity;
    double contactHertz = 30;         // contact stiffness, capped at a quarter of the substep rate
    double contactDampingRatio = 10;  // heavily over-damped: pushes out, never bounces
    double maxPushSpeed = 3;          // m/s, fastest overlap recovery
    double linearSlop = 0.005;        // m, allowed overlap; at most 5 % of the smaller radius
    double restitutionThreshold = 0.5;  // m/s: slower impacts do not bounce (no jitter at rest);
                                        // without gravity nothing rests, and every impact bounces
    bool impacts = true;                // bounce at the time of impact, in order (impacts.h)
    int impactsPerContact = 16;         // at most, per step; the restitution pass takes the rest
    bool followCurves = true;           // curved static surfaces followed every substep (RATTLE)
    int restitutionIterations = 4;      // bounce passes: simultaneous impacts tend to Newton's law
    int relaxSweeps = 4;                // at most, over a rigid manifold's rows in a relax
                                        // pass until they settle: one leaves a face's first
                                        // corner pushing hardest
    int bounceSweeps = 16;              // over a rigid manifold's rows at restitution, so
                                        // that a face bounces whole
    bool continuous = true;             // sweep fast spheres against static surfaces
    bool sleep = true;
    double sleepSpeed = 0.05;  // m/s (and rad/s · radius) below which a body may sleep
    double timeToSleep = 0.5;  // s an island must stay slow before it sleeps
    double maxSpeed = 1e4;     // m/s, a guard against runaway input
    int threads = 1;           // 1 or 2: a second thread loads and solves half the
                               // contacts where they are many; the same result either way
    bool twoLanes = false;     // the solver's baseline x86-64 code (a batch in halves)
                               // whatever the CPU has: tests compare the two, which
                               // give the same bytes
};

//-----------------------------------------------------------------------------
// [SECTION] Bodies and statistics
//-----------------------------------------------------------------------------
// The fields the contact solver reads and writes come first, together: it visits bodies in
// contact order, not memory order, so each visit should touch as few cache lines as it can.
struct PhysicsBody {
    glm::dvec3 vel{0.0}, spin{0.0};  // m/s, rad/s
    glm::dvec3 delta{0.0};           // displacement during the current step
    double invMass = 0.0;            // 0 for the static body
    double invInertia = 0.0;         // 1 / (2/5·m·r²)
    glm::dvec3 pos{0.0};             // m
    double radius = 0.5;
    double sleepTime = 0.0;  // s spent slow
    bool awake = true;
    bool supported = false;                    // a contact pushed it this substep (solve pass)
    int island = -1;                           // sleeping island, for waking it whole
    int object = -1;                           // index in Scene::objects; -1 for the static body
    double friction = 0.0, restitution = 0.0;  // its own, or the world's
};

// A dynamic body of any shape but the solid sphere, or a dynamic group: what writeBack puts in
// the scene, and where its centre of mass is.
struct RigidState {
    glm::dvec3 pos, vel, spin;  // the object's or group's origin (m), its centre of mass's
                                // velocity (m/s), its angular velocity (rad/s), world
    glm::dquat orient;          // the object's or group's turn, to the world
    bool awake;
    int object;              // index in Scene::objects, or -1 for a group
    int group = -1;          // index in Scene::groups, for a group
    glm::dvec3 centre{0.0};  // its centre of mass, world: pos but for a cone or a group
};

struct PhysicsStats {
    int contacts = 0;             // contact constraints in the last step (speculative included)
    int awake = 0;                // awake dynamic bodies
    int halves = 0;               // contacts in the two halves that two threads may solve at once
    int levels = 0;               // levels of contacts that share no body (contact_graph.h)
    int substeps = 0;             // soft steps the last step took (more across a mass ratio,
                                  // under a tall stack)
    double maxPenetration = 0.0;  // m, deepest overlap at the end of the last step
};

//-----------------------------------------------------------------------------
// [SECTION] PhysicsWorld
//-----------------------------------------------------------------------------
class PhysicsWorld {
public:
    explicit PhysicsWorld(const Scene& scene, const PhysicsSettings& settings = {});
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    void step();                         // advance by one fixed step, settings().dt
    void writeBack(Scene& scene) const;  // pos, vel, spin (and orient) into the dynamic objects
                                         // and groups

    int bodyCount() const { return int(bodies_.size()) - 1; }            // dynamic spheres
    const PhysicsBody& body(int i) const { return bodies_[size_t(i)]; }  // in scene order
    int rigidCount() const;         // dynamic bodies of the other shapes, and dynamic groups
    RigidState rigid(int i) const;  // in scene order (a group where it stands, before its members)
    const PhysicsSettings& settings() const { return settings_; }
    const PhysicsStats& stats() const { return stats_; }
    double kineticEnergy() const;    // J, translation and rotation
    double potentialEnergy() const;  // J, m·g·y
    long long stepCount() const { return steps_; }

private:
    struct Impl;     // static colliders, broad phase, contacts: see src/physics/physics_world.cpp
    void collide();  // this step's contacts, warm started from the last step
    void collideStatic(int body);
    void orderAndWarmStart();  // bottom-up solve order; impulses of persisting contacts
    void sortBottomUp();       // ... the order, without the runs of splitInHalves
    void splitInHalves();      // which contacts two threads may solve at once
    void keepImpulses();       // for the next step's warm start
    void integrateVelocities(double h);
    void integratePositions(double h);
    void bendCurved(double h);  // curved static surfaces: how they bend along this substep
    void followCurved();        // ... and their normals where the bodies are now
    void sweepFast();           // continuous collision against static surfaces
    void updateStats();
    PhysicsSettings settings_;
    std::vector<PhysicsBody> bodies_;  // the dynamic spheres, then the static body
    PhysicsStats stats_;
    long long steps_ = 0;
    std::unique_ptr<Impl> impl_;
};

//-----------------------------------------------------------------------------
// [SECTION] Driving it
//-----------------------------------------------------------------------------
// Called each time another hundredth of a run's steps is done, with the fraction done.
using SimulateProgress = void (*)(double done);

// The fixed steps that make `seconds`: round(seconds / dt). Every way of playing a scene to a
// time (simulate, render --seconds, a frame of render --frames) counts its steps here, so they
// reach the same state.
int stepsFor(double seconds, const PhysicsSettings& settings);

// Exactly stepsFor(seconds) steps, then writes the state back; no step leaves the scene as it
// was. Deterministic: the same scene and settings give the same bytes. Returns the number of
// steps taken.
int simulate(Scene& scene, double seconds, const PhysicsSettings& settings = {},
             SimulateProgress progress = nullptr);

// Turns variable frame times into whole fixed steps, so the result does not depend on the frame
// rate. Frames longer than maxFrame are clamped: a hitch slows the scene, it cannot explode it.
struct StepAccumulator {
    double acc = 0.0;  // simulated time owed, s, in [0, dt)
    int advance(double frameSeconds, const PhysicsSettings& settings);  // steps to take now
};

}  // namespace mb
