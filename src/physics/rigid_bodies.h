// rigid_bodies.h — the dynamic bodies that are not spheres: boxes, capsules, cylinders, tori,
// cones, ellipsoids, hollow spheres and top-level groups, turned by unit quaternions, touching
// through manifolds found on their SDFs.
//
// A body's frame is its centre of mass in its principal axes. For most shapes that is the
// shape's own frame; a cone's centre lies towards its base, and a group's centre and axes are
// wherever its solid puts them (group_body.h). The body keeps the offset (`centre`, `axes`) and
// turns it back into the scene's own origin and turn when it writes the scene.
//
// A body's probes (rigid_probes.h) are tested against the SDF of whatever it may touch: the
// static scene and the ground, another body (both ways: each one's probes against the other's
// shape), or a sphere. Boxes and capsules meet each other in closed form instead (box_box.h,
// capsule_contacts.h). Each pair keeps at most four of its points, the deepest and then those
// that span the largest area, so a box rests flat on four corners; points keep their probe's
// key across steps and start from last step's impulses.
//
// The rows are solved with the spheres' soft step (Box2D v3) in the same substeps: the normal
// row soft with bias in the solve pass and rigid in the relax pass, Coulomb friction on the
// tangent plane (a disc: |λ_t| ≤ μ·Σλ_n), rolling resistance (|τ| ≤ rolling · r · Σλ_n), and
// restitution after the substeps. Spheres touching a body take part through their own
// PhysicsBody. Between substeps a body's orientation turns by the free rigid body's exact
// sub-flows (rotateFree), which keep its angular momentum and energy.
#pragma once

#include "broadphase.h"
#include "contact_solver.h"
#include "group_body.h"
#include "manifold_batches.h"
#include "near_parts.h"
#include "oriented_box.h"
#include "pair_cache.h"
#include "rigid_body.h"
#include "rigid_probes.h"
#include "rigid_rows.h"
#include "static_collider.h"
#include "warm_starts.h"

#include "marchbox/physics/physics.h"
#include "marchbox/scene/sdf.h"

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace mb {

// What the sweeps touch comes first, in the body's first cache line: a pile's rows reach their
// bodies in height order, at random in memory, and a pile of 4,000 bodies does not fit in cache.
struct alignas(64) RigidBody {
    glm::dvec3 vel{0.0}, spin{0.0};  // m/s, rad/s (world)
    bool supported = false;          // a contact pushed it this substep
    bool awake = true;
    bool turned = false;                       // rowInertia was made again this substep
    glm::dvec3 pos{0.0};                       // m (world)
    glm::dquat orient{1.0, 0.0, 0.0, 0.0};     // body to world
    glm::dvec3 delta{0.0};                     // displacement during the current step
    glm::dvec3 startPos{0.0};                  // where the step began, for holdIfOverflowed
    glm::dvec3 startVel{0.0}, startSpin{0.0};  // and how it moved then, for keepEnergy
    glm::dquat startOrient{1.0, 0.0, 0.0, 0.0};
    double invMass = 0.0;
    glm::dvec3 inertia{0.0};     // principal moments about the local axes
    glm::dmat3 invInertia{0.0};  // world, for the orientation now
    glm::dmat3 rowInertia{0.0};  // world, as this step's rows were made with (followTurns)
    double bound = 0.0;          // radius about pos that holds the shape
    Surface surface;             // the body's own, or the world's
    double sleepTime = 0.0;
    int object = -1;                               // index in Scene::objects; -1 for a group
    int group = -1;                                // index in Scene::groups, for a group
    SdfObject shape;                               // at the origin, unturned (an object's)
    std::shared_ptr<const GroupShape> groupShape;  // a group's, in the group's frame
    // The body's frame in the shape's: x_shape = centre + axes·x_body. `framed` where that is
    // not the identity (a cone, a group), so every other body computes as it always has.
    glm::dvec3 centre{0.0};
    glm::dquat axes{1.0, 0.0, 0.0, 0.0};
    bool framed = false;
    bool exact = true;       // its SDF is exact: no projection onto the surface needed
    bool ellipsoid = false;  // probed at its support point along each surface's normal
    // A solid of revolution about its frame's y axis. Its turn about that axis moves no point of
    // its surface: its contacts' points follow `untwisted`, its orientation less that turn since
    // the step began, and their speeds along the normal leave the spin about it out (normalArm).
    bool revolved = false;
    glm::dquat untwisted{1.0, 0.0, 0.0, 0.0};
    int staticIds = 0;          // its first StaticCollider id (probes, rims, body, side)
    std::vector<Probe> probes;  // in the body's frame
    std::vector<Rim> rims;      // in the body's frame
    std::vector<Side> sides;    // in the body's frame: a cylinder's or a cone's, its members
    // Boxes in the body's frame that no point is nearer than its shape (an exact object's own
    // box, a sharp union's members', unionParts), and the box about them all, which holds its
    // probes. No parts where its distance is a bound that may lie nearer.
    std::vector<OrientedBox> parts;
    OrientedBox hull;

    glm::dquat shapeOrient() const;  // the shape's turn in the world (the scene's orient)
    glm::dvec3 origin() const;       // the shape's origin in the world (the scene's pos)
};

class RigidBodies {
public:
    RigidBodies(const Scene& scene, const PhysicsSettings& settings);

    int count() const { return int(bodies_.size()); }
    const RigidBody& body(int i) const { return bodies_[size_t(i)]; }
    int contactCount() const { return int(contacts_.size()); }
    // The largest ratio of two moving bodies' masses across one of this step's contacts; 1 if none.
    double massRatio() const { return massRatio_; }
    // The most bodies of this step's contacts that rest one on another, counted from the ground
    // or a sleeping body (a box on the ground: 1); 0 if none.
    int stackDepth() const { return stackDepth_; }

    // This step's contacts against the statics, each other and the spheres (waking those hit).
    void collide(std::vector<PhysicsBody>& spheres, double gravity);
    void integrateVelocities(double h, double gravity);
    void warmStart();
    void solve(const Softness& soft, double h, bool useBias);  // useBias false: the relax pass
    void integratePositions(double h, double gravity);         // and the rows follow the turns
    void restitute(double threshold, double gravity);
    void finishStep();                   // keeps the impulses; sleep
    void writeBack(Scene& scene) const;  // pos, orient, vel, spin (objects' and groups')
    double kineticEnergy() const;
    double potentialEnergy(double gravity) const;
    double deepestOverlap() const;  // m, at the last step's start

private:
    using Candidate = PairCandidate;
    void followTurns();
    void collideStatics(int i);
    void collidePair(int i, int j);
    void collideSphere(int i, PhysicsBody& sphere, int sphereIndex);
    void probeStatics(int i, std::vector<std::vector<Candidate>>& byFeature);
    void addStaticCandidate(const RigidBody& b, const StaticHit& hit, const glm::dvec3& at,
                            double radius, int probe, const glm::dvec3& centre,
                            std::vector<std::vector<Candidate>>& byFeature);
    void probeStaticRing(const RigidBody& b, int r, int feature, int id, double reach,
                         std::vector<std::vector<Candidate>>& byFeature);
    void probeStaticSide(const RigidBody& b, int k, double reach,
                         std::vector<std::vector<Candidate>>& byFeature);
    void probeStaticProbes(const RigidBody& b, double reach,
                           std::vector<std::vector<Candidate>>& byFeature);
    void meetStaticProbe(const RigidBody& b, const StaticProbe& p, int index, double reach,
                         std::vector<std::vector<Candidate>>& byFeature);
    void probeShape(int prober, int shape, bool flip, int offset);
    struct Probing {  // one body's probes against another's shape, this step
        const RigidBody &prober, &shape;
        bool flip;      // the prober is the pair's a: normals turn to point from a to b
        int offset;     // added to each probe's key
        double reach;   // reachOf the two
        bool partwise;  // part by part, against nearParts_
    };
    struct WallRetry {    // a rim's support point that meets a wall across its face (rimInset)
        glm::dvec3 face;  // the shape's normal at the rim's centre
        glm::dvec3 move;  // to the point inside the rim probed instead
    };
    void probePoint(const Probing& q, const glm::dvec3& at, double radius, int key,
                    const glm::dvec3& centre, std::span<const int> near, bool partial = false,
                    const WallRetry* retry = nullptr);
    const StaticHit* faceOf(int feature) const;  // in faces_, null where that surface is not near
    const StaticHit* hitOn(int feature, int id, const glm::dvec3& at, double radius, double reach,
                           double size);
    void lookInside(const RigidBody& b, int id, double reach, const glm::dvec3& face,
                    const glm::dvec3& centre, StaticHit* hit, glm::dvec3* at);
    glm::dvec3 normalBesideCrease(const Probing& q, const glm::dvec3& at, double radius, int part,
                                  const glm::dvec3& normal);
    glm::dvec3 staticNormalBesideCrease(const RigidBody& b, const StaticHit& hit,
                                        const glm::dvec3& at, double radius);
    glm::dvec3 normalBesideStaticProbe(const RigidBody& b, const StaticProbe& p,
                                       const glm::dvec3& normal);
    void probeRim(const Probing& q, int r, std::span<const int> near);
    void probeSide(const Probing& q, int k, std::span<const int> near);
    bool collideAnalytic(const RigidBody& a, const RigidBody& b);
    void dropUnreachable(const RigidBody& a, const RigidBody& b);
    double reachOf(const RigidBody& a, const RigidBody& b) const;
    bool boxesApart(int i, int j, double pairReach);
    void sortBottomUp();
    void measureStacks(int spheres);
    static RigidContact contactFrom(const Candidate& c, double height, std::uint64_t pair);
    // `centre`: the probe's, where b holds it; else the point itself, a point of b's surface.
    ContactSide sideOf(RigidBody& b, const glm::dvec3& point, const glm::dvec3& centre);
    void makeRows();
    void wake(std::vector<PhysicsBody>& spheres);
    void updateSleep();

    const PhysicsSettings& settings_;
    double rolling_, dt_;
    std::vector<RigidBody> bodies_;
    StaticCollider statics_;
    Broadphase broadphase_;
    std::vector<RigidContact> contacts_;  // each manifold's points together, bottom-up
    std::vector<NormalRow> rows_;         // contacts_'s normal rows, in the same order
    double massRatio_ = 1.0;              // see massRatio()
    int stackDepth_ = 0;                  // see stackDepth()
    std::vector<int> depths_;             // per body, then per sphere: its depth in its stack
    void prepareFriction(RigidManifold& m);
    bool heldEarly(const RigidManifold& m, double accel) const;
    struct Bounced {  // a manifold's moving bodies and its points' pushes before its bounce
        struct Body {
            int index;
            glm::dvec3 vel, spin;
        };
        std::vector<Body> bodies;
        std::vector<double> impulses;
    };
    Bounced bouncing(const RigidManifold& m) const;
    void keepEnergy(const RigidManifold& m, const Bounced& was, double gravity);
    void undo(RigidManifold& m);
    std::vector<RigidManifold> manifolds_;
    ManifoldBatches batches_;  // rows_ and manifolds_ as the substeps solve them
    std::vector<Candidate> candidates_;
    std::vector<FreeTurn> turns_;  // integratePositions' awake bodies, turned together
    // Scratch kept from call to call for its room: collideStatics' candidates by static surface,
    // collidePair's candidates before and their bins while they are split by their normals'
    // ways, probeStatics' surfaces near a probe, a rim or an ellipsoid while each is probed.
    std::vector<std::vector<Candidate>> byFeature_;
    std::vector<Candidate> binned_;
    std::vector<int> bins_;
    std::vector<StaticHit> surfaces_;
    std::vector<StaticHit> faces_;  // probeStatics': the surfaces near the body, from its centre
    NearParts nearParts_;           // the parts of the pair being probed that come near each other
    PairCache pairCache_;           // points of pairs that have barely moved, not found again
    WarmStarts kept_;               // last step's impulses, to start this step's rows from
    // Each body's record as the scene gave it, and the state made from it. A body still in
    // that state is written back as it was read: a float turn made a double, normalised and
    // made a float again can come back an ulp apart, and each save would walk it further.
    struct Loaded {
        glm::vec3 pos, rot, vel, spin;
        std::optional<glm::quat> orient;
        glm::dvec3 statePos, stateVel, stateSpin;
        glm::dquat stateOrient;
    };
    std::vector<Loaded> loaded_;
    struct Place {  // a manifold's sort key and where its points are
        double height;
        std::uint64_t manifold;  // the points' key >> 8
        size_t begin, end;
    };
    std::vector<Place> order_;
    std::vector<RigidContact> sorted_;
    std::vector<glm::dvec3> centres_;
    std::vector<double> extents_, margins_;
    // Each body's hull and then its parts, where they are this step (appendPlacedBoxes), placed
    // the first time a pair asks: body i's from boxesFirst_[i], −1 until then.
    std::vector<OrientedBox> boxes_;
    std::vector<int> boxesFirst_;
    std::span<const OrientedBox> boxesOf(int i);
    std::vector<std::pair<int, int>> pairs_;
    std::vector<StaticHit> hits_;
    std::vector<int> touching_;  // per body: an awake mover touched it this step
};

}  // namespace mb
