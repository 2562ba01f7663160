// physics_world.cpp — the fixed step: collide, soft substeps, restitution, sweep, sleep.
#include "marchbox/physics/physics.h"

#include "branchless.h"
#include "broadphase.h"
#include "contact_batches.h"
#include "contact_solver.h"
#include "group_body.h"
#include "impacts.h"
#include "island.h"
#include "rigid_bodies.h"
#include "static_collider.h"
#include "worker.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

struct Found {  // a contact as collide() finds it, before its place in the solve order
    int a, b, feature;
    bool curved;
    dvec3 normal;
    double separation;
    double height;  // of the contact point, on b's surface: the bottom-up order's
};

// Found with its height taken from b while collide() has b at hand, where the sort would read
// the bodies out of order.
Found found(int a, int b, const PhysicsBody& onB, int feature, bool curved, const dvec3& normal,
            double separation) {
    return {a, b, feature, curved, normal, separation, onB.pos.y - onB.radius * normal.y};
}

// The largest restitution any contact can have (surface.h takes the larger of a pair's): where it
// is 0 the impacts and the bounce passes have nothing to do.
double largestRestitution(const Scene& scene) {
    double e = scene.world.restitution;
    for (const Object& o : scene.objects) e = std::max(e, double(o.restitution.value_or(0.0f)));
    for (const Group& g : scene.groups) e = std::max(e, double(g.restitution.value_or(0.0f)));
    return e;
}

}  // namespace

struct PhysicsWorld::Impl {
    Impl(const Scene& scene, const PhysicsSettings& settings)
        : statics(withoutBodyMembers(scene)),  // a dynamic group's members move with it
          rigid(scene, settings),
          gravity(scene.world.gravity),
          maxRestitution(largestRestitution(scene)),
          rolling(scene.world.rolling) {}

    struct Order {
        std::uint64_t height;  // orderedBits(contact height): compares as the double does
        std::uint64_t key;
        int index;  // in found
        int run;    // SolverContext::split: 0 or 1, one half; 2, both
        int warm;   // last step's impulses in kept, or -1
        bool operator<(const Order& o) const {
            return height < o.height || (height == o.height && key < o.key);
        }
    };
    struct Impulses {  // a contact's, kept for the next step's warm start
        double normal;
        dvec3 tangent, roll;
    };
    struct Warm {  // last step's contact of this key
        std::uint64_t key;
        int rank;  // its place in the step's bottom-up order (Order)
        int slot;  // its impulses in kept
    };
    struct Keyed {  // where in previous a key is: 16 bytes, so the search stays in cache
        std::uint64_t key;
        int found;
    };

    StaticCollider statics;
    RigidBodies rigid;  // the dynamic bodies of every other shape
    Broadphase broadphase;
    Impacts impacts;
    ContactBatches batches;  // the solver's state during the substeps
    double gravity, maxRestitution, rolling;
    std::vector<Found> found;
    std::vector<Contact> contacts;  // in solve order
    std::vector<int> curved;        // contacts on curved static surfaces, followed every substep
    std::vector<Order> order, fresh, merged;
    std::vector<Order> byRank;  // persisting contacts at last step's rank; index -1 where none is
    std::vector<int> rank;      // per contact, in solve order: its rank in the bottom-up order
    std::vector<BodyX> byX;     // bodies in x order, for sideByMedianX
    std::vector<char> side;     // per body: the half it is in, by x
    int split[2] = {0, 0};
    std::unique_ptr<Worker> worker;  // started with the first step that splits
    std::vector<Warm> previous;      // last step's contacts, in the order collide() found them
    std::vector<Impulses> kept;      // last step's impulses, in its solve order
    // previous grouped by first dynamic body (the key's top bits): body i's are
    // grouped[warmBegin[i] .. warmBegin[i + 1]), a handful, searched linearly.
    std::vector<Keyed> grouped;
    std::vector<int> warmBegin;

    // Last step's contact of this key, or null. Until the pair list is rebuilt, collide() finds
    // the contacts in last step's order less those that ended: the one after the last found
    // (`next`) is nearly always it, and the group search, whose exit is hard to predict, is
    // left for the contacts that begin or follow one that ended.
    const Warm* findWarm(std::uint64_t key, size_t& next) const {
        if (next < previous.size() && previous[next].key == key) return &previous[next++];
        const auto first = size_t(key >> 40);
        if (first + 1 >= warmBegin.size()) return nullptr;
        for (int i = warmBegin[first]; i < warmBegin[first + 1]; ++i)
            if (grouped[size_t(i)].key == key) {
                next = size_t(grouped[size_t(i)].found) + 1;
                return &previous[next - 1];
            }
        return nullptr;
    }
    std::vector<dvec3> centres;
    std::vector<double> extents, margins;
    std::vector<std::pair<int, int>> pairs;
    std::vector<StaticHit> hits;
    std::vector<int> islands, scratch;
};

namespace {

// Overlap a contact may keep: small against the sphere, so millimetre spheres do not sink.
double slopFor(double radius, const PhysicsSettings& s) {
    return std::min(s.linearSlop, 0.05 * radius);
}

// Warm-start key: first dynamic body, other body, feature + 1, in 24, 24 and 16 bits.
std::uint64_t contactKey(int a, int b, int feature, int staticBody) {
    const bool onStatic = a == staticBody;
    const std::uint64_t first = std::uint64_t(onStatic ? b : a),
                        second = std::uint64_t(onStatic ? a : b);
    return first << 40 | second << 16 | std::uint64_t(feature + 1);
}

// The contact's arms, lever of rolling resistance, slop and approach speed before the impacts
// (Impacts::resolve), from its bodies (a may be static); the rest as a new Contact has them.
// Written in place, as sortBottomUp writes its Orders.
void makeContact(Contact& c, const Found& f, const std::vector<PhysicsBody>& bodies, int staticBody,
                 const StaticCollider& statics, const PhysicsSettings& settings) {
    c = Contact{};
    c.a = f.a;
    c.b = f.b;
    c.feature = f.feature;
    c.curved = f.curved;
    c.normal = f.normal;
    c.separation = f.separation;
    c.armB = bodies[size_t(f.b)].radius;
    c.armA = f.a == staticBody ? 0.0 : bodies[size_t(f.a)].radius;
    c.rollRadius = f.a == staticBody ? c.armB : std::min(c.armA, c.armB);
    c.slop = slopFor(c.rollRadius, settings);
    c.relativeVelocity = glm::dot(bodies[size_t(f.b)].vel - bodies[size_t(f.a)].vel, f.normal);
    const PhysicsBody &a = bodies[size_t(f.a)], &b = bodies[size_t(f.b)];
    const Surface pair =
        combine(f.a == staticBody ? statics.surface(f.feature) : Surface{a.friction, a.restitution},
                {b.friction, b.restitution});
    c.friction = pair.friction;
    c.restitution = pair.restitution;
}

// The bits of a double as an unsigned integer in the double's order (negatives reversed below
// the positives), so that the sort compares integers; −0 and +0 both map to +0's bits.
std::uint64_t orderedBits(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x + 0.0);
    return bits >> 63 ? ~bits : bits | std::uint64_t(1) << 63;
}

}  // namespace

PhysicsWorld::PhysicsWorld(const Scene& scene, const PhysicsSettings& settings)
    : settings_(settings), impl_(std::make_unique<Impl>(scene, settings_)) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        // The others, and hollow spheres: RigidBodies.
        if (!o.dynamic() || o.type != ShapeType::Sphere || o.shell > 0.0f) continue;
        PhysicsBody b;
        b.pos = dvec3(o.pos);
        b.vel = dvec3(o.vel);
        b.spin = dvec3(o.spin);
        b.radius = o.radius;
        b.invMass = 1.0 / o.mass;
        b.invInertia = 1.0 / (0.4 * o.mass * b.radius * b.radius);  // solid sphere: I = 2/5·m·r²
        b.object = int(i);
        const Surface own = surfaceOf(o, scene.world);
        b.friction = own.friction;
        b.restitution = own.restitution;
        bodies_.push_back(b);
    }
    bodies_.push_back(PhysicsBody{});  // the static body: zero inverse mass, never moves
    bodies_.back().invMass = 0.0;
}

PhysicsWorld::~PhysicsWorld() = default;

void PhysicsWorld::writeBack(Scene& scene) const {
    for (int i = 0; i < bodyCount(); ++i) {
        Object& o = scene.objects[size_t(bodies_[i].object)];
        o.pos = glm::vec3(bodies_[i].pos);
        o.vel = glm::vec3(bodies_[i].vel);
        o.spin = glm::vec3(bodies_[i].spin);
    }
    impl_->rigid.writeBack(scene);
}

int PhysicsWorld::rigidCount() const { return impl_->rigid.count(); }

RigidState PhysicsWorld::rigid(int i) const {
    const RigidBody& b = impl_->rigid.body(i);
    return {b.origin(), b.vel, b.spin, b.shapeOrient(), b.awake, b.object, b.group, b.pos};
}

double PhysicsWorld::kineticEnergy() const {
    double e = 0.0;
    for (int i = 0; i < bodyCount(); ++i) {
        const PhysicsBody& b = bodies_[i];
        e += 0.5 * glm::dot(b.vel, b.vel) / b.invMass +
             0.5 * glm::dot(b.spin, b.spin) / b.invInertia;
    }
    return e + impl_->rigid.kineticEnergy();
}

double PhysicsWorld::potentialEnergy() const {
    double e = 0.0;
    for (int i = 0; i < bodyCount(); ++i)
        e += impl_->gravity * bodies_[i].pos.y / bodies_[i].invMass;
    return e + impl_->rigid.potentialEnergy(impl_->gravity);
}

}  // namespace mb

namespace mb {

namespace {

// A soft contact's stiffness is set by the lighter of its bodies: one r times heavier resting on
// it presses it in by 2·(r + 1)·g/ω² (ω = 2π·0.125/h, the rigid rows' stiffness), and at r = 1000
// and 4 substeps that crushes a light box into the ground. Gravity stronger than 9.81 m/s²
// presses the same way, as a ratio that many times larger: at 4 substeps a box sank 7 cm into
// the ground under 10,000 m/s², and through it under 30,000. Across a load (r + 1)·g/9.81 above
// 101 the step takes n ≥ n₀·√(load/101) substeps, which keeps the sag at ratio 100's (15 mm at
// the defaults).
int substepsForLoad(int n0, double massRatio, double gravity) {
    constexpr double kLoad = 101.0, kGravity = 9.81;
    const double load = (massRatio + 1.0) * std::max(gravity / kGravity, 1.0);
    if (load <= kLoad) return n0;
    return int(std::min(std::ceil(n0 * std::sqrt(load / kLoad)), 1e9));
}

// A column of bodies on soft contacts is a rod whose joints bend: under its own weight it
// buckles once g·D³ outgrows ω² (Greenhill's self-weight column, the contacts' turning
// stiffness for the rod's; the bodies' size drops out). At 4 substeps of 1/120 s a column of 30
// unit boxes leaned from the start and fell at 14 s; at 6 it leaned 15 cm and held; at 8 it
// leans 1 to 2.5 cm.
// A stack D bodies deep takes n ≥ 480/s·dt·√(g/9.81)·(D/19)^1.5 substeps: 8 for the column of
// 30, the defaults' 4 up to 19.
int substepsForDepth(double dt, double gravity, int depth) {
    constexpr double kRate = 480.0, kDepth = 19.0, kGravity = 9.81;
    const double n =
        kRate * dt * std::sqrt(std::max(gravity, 0.0) / kGravity) * std::pow(depth / kDepth, 1.5);
    return int(std::min(std::ceil(n), 1e9));
}

// The substeps this step takes: the settings' n₀ or what the rules above ask, at most 16·n₀
// so that a ratio of 10⁹ does not freeze the step.
int substepsFor(const PhysicsSettings& settings, double massRatio, int depth, double gravity) {
    constexpr int kMostTimes = 16;
    const int n0 = std::max(1, settings.substeps);
    const int n = std::max(substepsForLoad(n0, massRatio, gravity),
                           substepsForDepth(settings.dt, gravity, depth));
    return std::min(n, kMostTimes * n0);
}

}  // namespace

void PhysicsWorld::step() {
    Impl& w = *impl_;
    collide();
    w.rigid.collide(bodies_, w.gravity);
    const int substeps =
        substepsFor(settings_, w.rigid.massRatio(), w.rigid.stackDepth(), w.gravity);
    const int iterations = std::max(1, settings_.iterations);
    const double h = settings_.dt / substeps;
    SolverContext ctx{
        bodies_,
        w.contacts,
        settings_,
        w.gravity,
        w.maxRestitution,
        w.rolling,
        h,
        makeSoftness(std::min(settings_.contactHertz, 0.25 / h), settings_.contactDampingRatio, h)};
    ctx.split[0] = w.split[0];
    ctx.split[1] = w.split[1];
    if (settings_.threads > 1 && w.split[1] > 0) {
        if (!w.worker) w.worker = std::make_unique<Worker>();
        ctx.worker = w.worker.get();
    }
    // Bodies of other shapes rest on faces, under the weight of whole stacks: their contacts are
    // stiffer than the spheres' 30 Hz, at an eighth of the substep rate (60 Hz at the default
    // step; Box2D's 30 Hz at 240 substeps a second is the same ratio). At 30 Hz a stack of ten
    // unit boxes sinks 1.7 cm into itself, here 1.2 cm. A quarter of the substep rate (the most
    // Box2D allows) sinks it 7.7 mm but rings: one sweep a substep cannot settle contacts that
    // stiff under a 20-row pyramid's weight, whose boxes then rock and never sleep.
    const Softness rigidSoft = makeSoftness(0.125 / h, settings_.contactDampingRatio, h);
    if (settings_.impacts) w.impacts.resolve(ctx);
    w.batches.load(ctx);
    for (PhysicsBody& b : bodies_) b.delta = dvec3(0.0);
    for (int k = 0; k < substeps; ++k) {
        integrateVelocities(h);
        w.rigid.integrateVelocities(h, w.gravity);
        bendCurved(h);
        w.batches.warmStart(ctx);
        w.rigid.warmStart();
        for (int i = 0; i < iterations; ++i) {
            w.batches.solve(ctx, true);
            w.rigid.solve(rigidSoft, h, true);
        }
        integratePositions(h);
        w.rigid.integratePositions(h, w.gravity);
        followCurved();
        for (int i = 0; i < iterations; ++i) {
            w.batches.solve(ctx, false);
            w.rigid.solve(rigidSoft, h, false);
        }
    }
    w.batches.store(w.contacts);
    applyRestitution(ctx, settings_.restitutionIterations, w.scratch);
    w.rigid.restitute(bounceThreshold(ctx), w.gravity);
    if (settings_.impacts) w.impacts.correctPositions(bodies_, w.contacts);
    keepImpulses();
    if (settings_.continuous) sweepFast();
    updateSleep(bodies_, w.contacts, settings_, w.scratch);
    w.rigid.finishStep();
    updateStats();
    stats_.substeps = substeps;
    ++steps_;
}

// Speculative margin: a contact is made for anything the sphere could reach this step, moving
// at its current speed plus what gravity adds, |v|·dt + g·dt², and a few slops besides.
void PhysicsWorld::collide() {
    Impl& w = *impl_;
    const int n = bodyCount();
    const double dt = settings_.dt;
    w.found.clear();
    w.centres.resize(n);
    w.extents.resize(n);
    w.margins.resize(n);
    for (int i = 0; i < n; ++i) {
        const PhysicsBody& b = bodies_[i];
        w.margins[i] =
            4.0 * slopFor(b.radius, settings_) + glm::length(b.vel) * dt + w.gravity * dt * dt;
        w.centres[i] = b.pos;
        w.extents[i] = b.radius + w.margins[i];
    }
    w.broadphase.findPairs(w.centres, w.extents, w.pairs);
    for (auto [a, b] : w.pairs)  // an awake body near a sleeping one wakes its island
        if (bodies_[a].awake != bodies_[b].awake)
            w.islands.push_back(bodies_[a].awake ? bodies_[b].island : bodies_[a].island);
    wakeIslands(bodies_, w.islands);
    for (auto [a, b] : w.pairs) {
        const PhysicsBody &A = bodies_[a], &B = bodies_[b];
        if (!A.awake && !B.awake) continue;
        const dvec3 d = B.pos - A.pos;
        const double len = glm::length(d);
        w.found.push_back(found(a, b, B, -1, false, len > 0.0 ? d / len : dvec3(0, 1, 0),
                                len - A.radius - B.radius));
    }
    for (int i = 0; i < n; ++i)
        if (bodies_[i].awake) collideStatic(i);
    orderAndWarmStart();
}

// Bottom-up, for shock propagation; ties by key, so the order is deterministic. Contacts that
// persist from the last step start from its impulses.
void PhysicsWorld::orderAndWarmStart() {
    Impl& w = *impl_;
    sortBottomUp();
    splitInHalves();
    // Each run keeps the bottom-up order: a stable partition, by counting.
    int next[3] = {0, w.split[0], w.split[1]};
    w.contacts.resize(w.found.size());
    w.rank.resize(w.found.size());
    for (size_t i = 0; i < w.order.size(); ++i) {
        const Impl::Order& o = w.order[i];
        const int to = next[o.run]++;
        Contact& c = w.contacts[size_t(to)];
        makeContact(c, w.found[size_t(o.index)], bodies_, bodyCount(), w.statics, settings_);
        w.rank[size_t(to)] = int(i);
        if (o.warm < 0) continue;
        const Impl::Impulses& old = w.kept[size_t(o.warm)];
        c.normalImpulse = old.normal;
        c.tangentImpulse = old.tangent;
        c.rollImpulse = old.roll;
    }
    w.curved.clear();
    for (size_t i = 0; i < w.contacts.size(); ++i)
        if (w.contacts[i].curved) w.curved.push_back(int(i));
}

// The contacts that persist from the last step, taken in its order, are nearly in order already:
// an insertion sort puts right the few that moved past each other, in about linear time. The new
// ones are sorted apart and merged in. Keys are unique, so the order is total: the one a sort of
// all of them gives.
void PhysicsWorld::sortBottomUp() {
    Impl& w = *impl_;
    const int staticBody = bodyCount();
    w.byRank.assign(w.previous.size(), Impl::Order{0, 0, -1, 2, -1});
    w.fresh.clear();
    size_t next = 0;
    for (size_t i = 0; i < w.found.size(); ++i) {
        const Found& f = w.found[i];
        const std::uint64_t key = contactKey(f.a, f.b, f.feature, staticBody);
        const Impl::Warm* old = w.findWarm(key, next);
        // Field by field into its place: a whole Order built aside and copied would be read back
        // in halves that straddle the writes just made, and wait for them to reach the cache.
        Impl::Order& o = old ? w.byRank[size_t(old->rank)] : w.fresh.emplace_back();
        o.height = orderedBits(f.height);
        o.key = key;
        o.index = int(i);
        o.run = 2;
        o.warm = old ? old->slot : -1;
    }
    w.order.resize(w.byRank.size());
    size_t placed = 0;
    for (const Impl::Order& o : w.byRank) {  // in last step's order, each put in place as it comes
        if (o.index < 0) continue;
        size_t j = placed++;
        for (; j > 0 && o < w.order[j - 1]; --j) w.order[j] = w.order[j - 1];
        w.order[j] = o;
    }
    w.order.resize(placed);
    std::sort(w.fresh.begin(), w.fresh.end());
    w.merged.resize(w.found.size());
    std::merge(w.order.begin(), w.order.end(), w.fresh.begin(), w.fresh.end(), w.merged.begin());
    w.order.swap(w.merged);
}

// Few contacts are not worth a second thread: they all go to the joining run, in order.
void PhysicsWorld::splitInHalves() {
    constexpr size_t kMinContacts = 512;
    Impl& w = *impl_;
    w.split[0] = w.split[1] = 0;
    if (w.order.size() < kMinContacts) return;
    sideByMedianX(bodies_, w.byX, w.side);
    int count[3] = {0, 0, 0};
    for (Impl::Order& o : w.order) {
        // The bodies from the key (contactKey), not from the contact, which would be a read
        // out of order: the second, or the static body, as a (runOf gives the same either way).
        o.run = runOf(int(o.key >> 16 & 0xffffff), int(o.key >> 40), w.side, bodyCount());
        ++count[o.run];
    }
    w.split[0] = count[0];
    w.split[1] = count[0] + count[1];
}

// The bend of each curved surface along the move the body would make this substep at its
// velocity now, for the solve pass (ContactBatches::setCurve). Where the impacts moved a body, its
// true position is its substep position plus the impacts' correction.
void PhysicsWorld::bendCurved(double h) {
    Impl& w = *impl_;
    for (int i : w.curved) {
        const Contact& c = w.contacts[size_t(i)];
        const PhysicsBody& b = bodies_[c.b];
        w.batches.setCurve(
            i, w.statics.bend(c.feature, b.pos + w.impacts.offset(c.b), c.normal, b.vel * h));
    }
}

// Each curved surface's normal and separation where the body is now, for the relax pass and the
// next substep. Friction carried over turns into the new tangent plane.
void PhysicsWorld::followCurved() {
    Impl& w = *impl_;
    for (int i : w.curved) {
        Contact& c = w.contacts[size_t(i)];
        const PhysicsBody& b = bodies_[c.b];
        const dvec3 offset = w.impacts.offset(c.b);
        const StaticHit hit = w.statics.hit(c.feature, b.pos + offset, b.radius);
        c.normal = hit.normal;
        c.separation = hit.separation - glm::dot(c.normal, b.delta);
        c.shift = glm::dot(c.normal, offset);
        w.batches.follow(i, c.normal, c.separation);
    }
}

// Last step's contacts for findWarm: in the order collide() found them, for its walk, and grouped
// by first body for its search, by a counting sort (linear, where a sort by key was O(n log n)
// with cache misses).
void PhysicsWorld::keepImpulses() {
    Impl& w = *impl_;
    const int n = bodyCount();
    w.previous.resize(w.contacts.size());
    w.kept.resize(w.contacts.size());
    for (size_t i = 0; i < w.contacts.size(); ++i) {
        const Contact& c = w.contacts[i];
        const Impl::Order& o = w.order[size_t(w.rank[i])];
        w.previous[size_t(o.index)] = {o.key, w.rank[i], int(i)};
        w.kept[i] = {c.normalImpulse, c.tangentImpulse, c.rollImpulse};
    }
    w.warmBegin.assign(size_t(n) + 2, 0);
    for (const Impl::Warm& p : w.previous) ++w.warmBegin[size_t(p.key >> 40) + 2];
    for (int i = 2; i <= n + 1; ++i) w.warmBegin[i] += w.warmBegin[i - 1];
    w.grouped.resize(w.previous.size());
    // warmBegin[f + 1] is the next free slot of body f's group; once filled it is group f + 1's
    // start.
    for (size_t i = 0; i < w.previous.size(); ++i)
        w.grouped[size_t(w.warmBegin[size_t(w.previous[i].key >> 40) + 1]++)] = {w.previous[i].key,
                                                                                 int(i)};
}

void PhysicsWorld::collideStatic(int body) {
    Impl& w = *impl_;
    const PhysicsBody& b = bodies_[body];
    w.statics.query(body, b.pos, b.radius, w.margins[body], w.hits);
    for (const StaticHit& hit : w.hits) {
        // A surface that bends by more than its SDF's noise over this step's move is followed
        // substep by substep (bendCurved, followCurved); flat faces and the ground keep the
        // normal of the step's start, as a plane does.
        const dvec3 move = b.vel * settings_.dt;
        const bool curved = settings_.followCurves && hit.feature > 0 &&
                            std::abs(w.statics.bend(hit.feature, b.pos, hit.normal, move)) >
                                w.statics.bendNoise(hit.feature, glm::length(move));
        w.found.push_back(
            found(bodyCount(), body, b, hit.feature, curved, hit.normal, hit.separation));
    }
}

// The guard seldom acts: |v|² against a bound just below maxSpeed² leaves the root to the few
// near it (a speed whose rounded root exceeds maxSpeed has a square above the bound).
void PhysicsWorld::integrateVelocities(double h) {
    const double near = (1.0 - 1e-12) * settings_.maxSpeed * settings_.maxSpeed;
    for (int i = 0; i < bodyCount(); ++i) {
        PhysicsBody& b = bodies_[i];
        if (!b.awake) continue;
        b.vel.y -= impl_->gravity * h;
        if (glm::dot(b.vel, b.vel) <= near) continue;
        const double speed = glm::length(b.vel);
        if (speed > settings_.maxSpeed) b.vel *= settings_.maxSpeed / speed;
    }
}

// Symplectic Euler moves by v_new·h, which trails the exact free flight x + v·h + ½·a·h² by
// ½·g·h² each substep. ExactGravity adds that back, but only while no contact pushed the body:
// a resting sphere must not be nudged into its support every substep. The solve pass just before
// marked the bodies a contact pushes (PhysicsBody::supported).
void PhysicsWorld::integratePositions(double h) {
    const bool exact = settings_.integrator == Integrator::ExactGravity;
    const double fall = 0.5 * impl_->gravity * h * h;
    for (int i = 0; i < bodyCount(); ++i) {
        PhysicsBody& b = bodies_[i];
        if (!b.awake) continue;
        dvec3 dx = b.vel * h;
        dx.y = pick(exact & !b.supported, dx.y + fall, dx.y);  // which are pushed varies
        b.pos += dx;
        b.delta += dx;
    }
}

// Speculative contacts hold along the normal they were made with; a fast sphere moving across it
// (past an edge, into a thin plate at a slant) could still pass through. Sweep each sphere that
// moved more than half its radius: if its centre came within r/2 of a static surface, pull it
// back to where the whole sphere first touched. Its velocity is kept; next step's contact
// bounces it.
void PhysicsWorld::sweepFast() {
    Impl& w = *impl_;
    for (int i = 0; i < bodyCount(); ++i) {
        PhysicsBody& b = bodies_[i];
        const double travel = glm::length(b.delta);
        if (!b.awake || travel <= 0.5 * b.radius) continue;
        const dvec3 from = b.pos - b.delta, dir = b.delta / travel;
        const double core = w.statics.cast(from, dir, travel, 0.5 * b.radius);
        if (core >= travel) continue;
        const double t = w.statics.cast(from, dir, core, b.radius - slopFor(b.radius, settings_));
        b.delta = dir * t;
        b.pos = from + b.delta;
    }
}

void PhysicsWorld::updateStats() {
    stats_ = PhysicsStats{};
    stats_.contacts = int(impl_->contacts.size()) + impl_->rigid.contactCount();
    stats_.halves = impl_->split[1];
    stats_.levels = impl_->batches.levels();
    for (const Contact& c : impl_->contacts)
        stats_.maxPenetration = std::max(stats_.maxPenetration, -contactSeparation(c, bodies_));
    stats_.maxPenetration = std::max(stats_.maxPenetration, impl_->rigid.deepestOverlap());
    for (int i = 0; i < bodyCount(); ++i) stats_.awake += bodies_[i].awake ? 1 : 0;
    for (int i = 0; i < rigidCount(); ++i) stats_.awake += impl_->rigid.body(i).awake ? 1 : 0;
}

int stepsFor(double seconds, const PhysicsSettings& settings) {
    return int(std::llround(seconds / settings.dt));
}

int simulate(Scene& scene, double seconds, const PhysicsSettings& settings,
             SimulateProgress progress) {
    // No step moves nothing: the world, whose building takes seconds for a large group, is not
    // built, and the scene stays as it was (writing back an unstepped world changed nothing).
    const int steps = stepsFor(seconds, settings);
    if (steps == 0) return 0;
    PhysicsWorld world(scene, settings);
    for (long long i = 1; i <= steps; ++i) {
        world.step();
        if (progress && i * 100 / steps != (i - 1) * 100 / steps) progress(double(i) / steps);
    }
    world.writeBack(scene);
    return steps;
}

int StepAccumulator::advance(double frameSeconds, const PhysicsSettings& settings) {
    acc += std::clamp(frameSeconds, 0.0, settings.maxFrame);
    // Frame times that add up to a whole number of steps (144 frames of 1/144 s) must give that
    // number, not one less for a rounding error: allow a billionth of a step.
    const int steps = int(std::floor(acc / settings.dt + 1e-9));
    acc = std::max(0.0, acc - steps * settings.dt);
    return steps;
}

}  // namespace mb
