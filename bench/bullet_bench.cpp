// bullet_bench.cpp — Marchbox and Bullet side by side on the same scenes, as markdown.
//
// Both step at dt = 1/120 s. Bullet runs its defaults (sequential impulse, 10 iterations, split
// impulse) with each scene's friction and restitution; Marchbox its defaults (4 substeps, 1
// iteration). Overlap is measured the same way for both (mb::deepestOverlap).
#include "marchbox/physics.h"
#include "marchbox/physics_scenes.h"

#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace {

using mb::Scene;
constexpr double kDt = 1.0 / 120;
constexpr double kG = double(9.81f);

// A Bullet world holding a Marchbox scene: dynamic spheres, static boxes, the ground plane.
class BulletScene {
public:
    explicit BulletScene(const Scene& scene)
        : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_) {
        world_.setGravity(btVector3(0, -scene.world.gravity, 0));
        if (scene.world.ground) addStatic(new btStaticPlaneShape(btVector3(0, 1, 0), scene.world.floor), {0, 0, 0}, scene);
        for (const mb::Object& o : scene.objects) {
            if (o.type == mb::ShapeType::Box && !o.dynamic())
                addStatic(new btBoxShape(btVector3(o.size.x, o.size.y, o.size.z)), o.pos, scene);
            if (o.dynamic()) addSphere(o, scene);
        }
    }
    ~BulletScene() {
        for (int i = world_.getNumCollisionObjects() - 1; i >= 0; --i) {
            btCollisionObject* obj = world_.getCollisionObjectArray()[i];
            world_.removeCollisionObject(obj);
            delete obj;
        }
    }
    void step() { world_.stepSimulation(btScalar(kDt), 0); }
    int count() const { return int(spheres_.size()); }
    glm::dvec3 pos(int i) const {
        const btVector3 p = spheres_[size_t(i)]->getWorldTransform().getOrigin();
        return {p.x(), p.y(), p.z()};
    }
    double vy(int i) const { return spheres_[size_t(i)]->getLinearVelocity().y(); }
    double radius(int i) const { return radii_[size_t(i)]; }

private:
    void addStatic(btCollisionShape* shape, glm::vec3 pos, const Scene& scene) {
        shapes_.emplace_back(shape);
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape);
        info.m_startWorldTransform.setOrigin(btVector3(pos.x, pos.y, pos.z));
        info.m_friction = 1.0;  // Bullet multiplies the two bodies' coefficients
        info.m_restitution = 1.0;
        (void)scene;
        world_.addRigidBody(new btRigidBody(info));
    }
    void addSphere(const mb::Object& o, const Scene& scene) {
        auto* shape = new btSphereShape(o.radius);
        shapes_.emplace_back(shape);
        btVector3 inertia;
        shape->calculateLocalInertia(o.mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(o.mass, nullptr, shape, inertia);
        info.m_startWorldTransform.setOrigin(btVector3(o.pos.x, o.pos.y, o.pos.z));
        info.m_friction = scene.world.friction;
        info.m_restitution = scene.world.restitution;
        auto* body = new btRigidBody(info);
        body->setLinearVelocity(btVector3(o.vel.x, o.vel.y, o.vel.z));
        world_.addRigidBody(body);
        spheres_.push_back(body);
        radii_.push_back(o.radius);
    }

    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<btRigidBody*> spheres_;
    std::vector<double> radii_;
};

// The same three probes on either engine, through a tiny adapter.
struct Engine {
    std::function<void()> step;
    std::function<glm::dvec3(int)> pos;
    std::function<double(int)> vy;
};

struct MarchboxEngine {
    explicit MarchboxEngine(const Scene& s) : world(s) {}
    mb::PhysicsWorld world;
    Engine engine() {
        return {[this] { world.step(); }, [this](int i) { return world.body(i).pos; },
                [this](int i) { return world.body(i).vel.y; }};
    }
};

struct BulletEngine {
    explicit BulletEngine(const Scene& s) : world(s) {}
    BulletScene world;
    Engine engine() {
        return {[this] { world.step(); }, [this](int i) { return world.pos(i); },
                [this](int i) { return world.vy(i); }};
    }
};

template <class E>
double freeFallError() {
    E e(mb::freeFallScene(100.0f));
    Engine g = e.engine();
    for (int i = 0; i < 240; ++i) g.step();
    return std::abs(g.pos(0).y - (100.0 - 0.5 * kG * 4.0));
}

template <class E>
double bounceError() {
    E e(mb::bounceScene(1.0f, 0.8f));
    Engine g = e.engine();
    const double r = 0.1, e6 = std::pow(double(0.8f), 6.0);
    double apex = 0.0, previousVy = 0.0;
    for (int i = 0, bounces = 0; i < 600 && !(bounces == 3 && previousVy > 0.0 && g.vy(0) <= 0.0); ++i) {
        previousVy = g.vy(0);
        g.step();
        if (previousVy < 0.0 && g.vy(0) > 0.0) ++bounces;
        if (bounces == 3) apex = std::max(apex, g.pos(0).y - r);
    }
    return std::abs(apex - e6);
}

struct PileResult {
    double msPerStep, deepest;
};

template <class E>
PileResult pile(int count, double seconds) {
    const Scene scene = mb::pileScene(count, 7);
    E e(scene);
    Engine g = e.engine();
    std::vector<double> radii;
    for (const mb::Object& o : scene.objects)
        if (o.dynamic()) radii.push_back(o.radius);
    const int steps = int(std::llround(seconds / kDt));
    double busy = 0.0, deepest = 0.0;
    for (int i = 0; i < steps; ++i) {
        const auto start = std::chrono::steady_clock::now();
        g.step();
        busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (i % 10 != 9) continue;
        std::vector<glm::dvec3> centres;
        for (int k = 0; k < count; ++k) centres.push_back(g.pos(k));
        deepest = std::max(deepest, mb::deepestOverlap(scene, centres, radii));
    }
    return {1e3 * busy / steps, deepest};
}

}  // namespace

int main() {
    std::printf("Bullet %d (btDiscreteDynamicsWorld, sequential impulse, 10 iterations) against Marchbox "
                "defaults, both at dt = 1/120 s on one core. Overlap sampled every 10 steps.\n\n",
                btGetVersion());
    std::printf("| case | Marchbox | Bullet |\n| --- | ---: | ---: |\n");
    std::printf("| free fall, \\|y − exact\\| after 2 s | %.3g m | %.3g m |\n", freeFallError<MarchboxEngine>(),
                freeFallError<BulletEngine>());
    std::printf("| bounce, \\|third apex − e⁶·h\\| | %.3g m | %.3g m |\n", bounceError<MarchboxEngine>(),
                bounceError<BulletEngine>());
    for (int count : {1000, 10000}) {
        const double seconds = 1.5;
        const PileResult m = pile<MarchboxEngine>(count, seconds), b = pile<BulletEngine>(count, seconds);
        std::printf("| pile of %d, first %.1f s: time per step | %.3g ms | %.3g ms |\n", count, seconds,
                    m.msPerStep, b.msPerStep);
        std::printf("| pile of %d, first %.1f s: deepest overlap | %.3g m | %.3g m |\n", count, seconds,
                    m.deepest, b.deepest);
    }
    return 0;
}
