// test_contact_graph.cpp — levels share no dynamic body and keep each body's contact order.
#include "contact_graph.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cstdint>
#include <set>

using namespace mb;

namespace {

constexpr int kBodies = 40, kStatic = kBodies;  // the static body's index comes last

std::vector<Contact> randomContacts(int count) {
    std::uint32_t state = 777;
    auto next = [&](int n) { return int((state = state * 1664525u + 1013904223u) >> 8) % n; };
    std::vector<Contact> contacts;
    for (int i = 0; i < count; ++i) {
        Contact c;
        c.a = i % 5 == 0 ? kStatic : next(kBodies);  // every fifth on the static body
        c.b = next(kBodies);
        if (c.b == c.a) c.b = (c.b + 1) % kBodies;
        c.normalImpulse = next(2) ? 1.0 : 0.0;  // loaded ones go first within a level
        contacts.push_back(c);
    }
    return contacts;
}

// The level of each contact, from the slots.
std::vector<int> levelsOf(const ContactGraph& g, int contacts) {
    std::vector<int> level(size_t(contacts), -1);
    for (int k = 0; k < g.levels(); ++k)
        for (int s = g.levelBegin[size_t(k)] * kLanes; s < g.levelBegin[size_t(k) + 1] * kLanes;
             ++s)
            if (g.slots[size_t(s)] >= 0) level[size_t(g.slots[size_t(s)])] = k;
    return level;
}

ContactGraph graphOf(const std::vector<Contact>& contacts, const int split[2]) {
    ContactGraph g;
    std::vector<int> scratch;
    buildContactGraph(contacts, split, kStatic, g, scratch);
    return g;
}

}  // namespace

TEST(ContactGraph, LevelsShareNoDynamicBodyAndKeepEachBodysOrder) {
    const std::vector<Contact> contacts = randomContacts(300);
    const int split[2] = {100,
                          180};  // the first two runs share bodies here: the graph must not care
    const ContactGraph g = graphOf(contacts, split);
    const std::vector<int> level = levelsOf(g, 300);
    for (int i = 0; i < 300; ++i) {
        ASSERT_GE(level[size_t(i)], 0) << "contact " << i << " has no slot";
        EXPECT_EQ(g.slots[size_t(g.slotOf[size_t(i)])], i);
    }
    for (int k = 0; k < g.levels(); ++k) {
        std::set<int> bodies;
        for (int i = 0; i < 300; ++i) {
            if (level[size_t(i)] != k) continue;
            for (int body : {contacts[size_t(i)].a, contacts[size_t(i)].b})
                EXPECT_TRUE(body == kStatic || bodies.insert(body).second)
                    << "level " << k << " body " << body;
        }
    }
    // A later contact on the same dynamic body is solved in a later level, as in the one-at-a-time
    // order.
    for (int i = 0; i < 300; ++i)
        for (int j = i + 1; j < 300; ++j) {
            const Contact &ci = contacts[size_t(i)], &cj = contacts[size_t(j)];
            const bool shared =
                ci.b == cj.a || ci.b == cj.b || (ci.a != kStatic && (ci.a == cj.a || ci.a == cj.b));
            EXPECT_TRUE(!shared || level[size_t(i)] < level[size_t(j)]) << i << " before " << j;
        }
}

TEST(ContactGraph, EachRunKeepsToLevelsOfItsOwnInRunOrder) {
    const std::vector<Contact> contacts = randomContacts(300);
    const int split[2] = {100, 180};
    const ContactGraph g = graphOf(contacts, split);
    const std::vector<int> level = levelsOf(g, 300);
    const int runEnd[3] = {g.runEnd[0], g.runEnd[1], g.levels()};
    for (int i = 0; i < 300; ++i) {
        const int run = i < split[0] ? 0 : i < split[1] ? 1 : 2;
        EXPECT_LT(level[size_t(i)], runEnd[run]) << "contact " << i;
        EXPECT_GE(level[size_t(i)], run > 0 ? runEnd[run - 1] : 0) << "contact " << i;
    }
}

// Within a level, the contacts that bore load come first and the open ones after, each group in
// solve order, with only the level's last batch padded: batches of open contacts skip their rows.
TEST(ContactGraph, LoadedContactsLeadEachLevel) {
    const std::vector<Contact> contacts = randomContacts(300);
    const int split[2] = {100, 180};
    const ContactGraph g = graphOf(contacts, split);
    for (int k = 0; k < g.levels(); ++k) {
        int last[2] = {-1, -1};  // the last open and loaded contact seen in the level
        bool openSeen = false, padSeen = false;
        for (int s = g.levelBegin[size_t(k)] * kLanes; s < g.levelBegin[size_t(k) + 1] * kLanes;
             ++s) {
            const int i = g.slots[size_t(s)];
            if (i < 0) {
                padSeen = true;
                continue;
            }
            EXPECT_FALSE(padSeen) << "level " << k << ": a contact after padding";
            const bool loaded = contacts[size_t(i)].normalImpulse > 0.0;
            EXPECT_FALSE(loaded && openSeen)
                << "level " << k << ": loaded contact " << i << " after an open one";
            openSeen = openSeen || !loaded;
            EXPECT_GT(i, last[loaded]) << "level " << k << ": out of solve order";
            last[loaded] = i;
        }
    }
}

// sideByMedianX keeps the bodies in x order from one call to the next and re-sorts it: after the
// bodies move (some across the median), the cut must be the one a fresh order gives.
TEST(ContactGraph, TheKeptXOrderFollowsTheBodies) {
    std::vector<PhysicsBody> bodies(size_t(kBodies) + 1);  // the static body last
    std::uint32_t state = 99;
    auto next = [&] {
        return double((state = state * 1664525u + 1013904223u) >> 8) / double(1u << 24);
    };
    for (int i = 0; i < kBodies; ++i) bodies[size_t(i)].pos.x = next();
    std::vector<BodyX> kept;
    std::vector<char> side, fresh;
    sideByMedianX(bodies, kept, side);
    for (int round = 0; round < 3; ++round) {
        for (int i = 0; i < kBodies; ++i) bodies[size_t(i)].pos.x += 0.3 * (next() - 0.5);
        std::vector<BodyX> none;
        sideByMedianX(bodies, kept, side);
        sideByMedianX(bodies, none, fresh);
        EXPECT_EQ(side, fresh) << "round " << round;
        EXPECT_EQ(std::count(side.begin(), side.end(), 0), kBodies / 2) << "round " << round;
    }
}

// What two threads solve at once shares no body: the levels of the first run (the worker's) and
// of the second (this thread's) never hold the same dynamic body, whatever the contacts, and a
// contact across the cut waits for both, in the joining run. (A race on a shared body would show
// in the two-thread determinism test only when the threads happened to collide; this cannot miss.)
TEST(ContactGraph, HalvesShareNoBody) {
    std::vector<PhysicsBody> bodies(size_t(kBodies) + 1);  // the static body last
    std::uint32_t state = 4242;
    for (int i = 0; i < kBodies; ++i)
        bodies[size_t(i)].pos.x = double((state = state * 1664525u + 1013904223u) >> 8);
    std::vector<BodyX> byX;
    std::vector<char> side;
    sideByMedianX(bodies, byX, side);
    EXPECT_EQ(std::count(side.begin(), side.end(), 0), kBodies / 2) << "the cut is at the median";
    // The contacts in runs, each run keeping the solve order (as PhysicsWorld::splitInHalves does).
    const std::vector<Contact> contacts = randomContacts(300);
    std::vector<Contact> byRun;
    int split[2] = {0, 0}, across = 0;
    for (int run = 0; run < 3; ++run) {
        for (const Contact& c : contacts) {
            const bool crosses = c.a != kStatic && side[size_t(c.a)] != side[size_t(c.b)];
            if (runOf(c.a, c.b, side, kStatic) != run) continue;
            EXPECT_EQ(run == 2, crosses) << "bodies " << c.a << " and " << c.b;
            across += crosses ? 1 : 0;
            byRun.push_back(c);
        }
        if (run < 2) split[run] = int(byRun.size());
    }
    ASSERT_GT(across, 0) << "no contact crosses the cut: the test would not see one";
    ASSERT_GT(split[0], 0);
    ASSERT_GT(split[1], split[0]);
    const ContactGraph g = graphOf(byRun, split);
    std::set<int> touched[2];  // dynamic bodies in the worker's levels, and in this thread's
    for (int half = 0; half < 2; ++half)
        for (int k = half == 0 ? 0 : g.runEnd[0]; k < g.runEnd[half]; ++k)
            for (int s = g.levelBegin[size_t(k)] * kLanes; s < g.levelBegin[size_t(k) + 1] * kLanes;
                 ++s) {
                if (g.slots[size_t(s)] < 0) continue;
                const Contact& c = byRun[size_t(g.slots[size_t(s)])];
                for (int body : {c.a, c.b})
                    if (body != kStatic) touched[half].insert(body);
            }
    EXPECT_FALSE(touched[0].empty());
    EXPECT_FALSE(touched[1].empty());
    for (int body : touched[0])
        EXPECT_EQ(touched[1].count(body), 0u) << "body " << body << " is in both halves";
}
