// contact_graph.h — contacts in levels that share no dynamic body, solved four at a time.
//
// Gauss-Seidel solves contacts one after another, and the result depends only on the order of
// contacts that share a body: two that share none commute. Each contact is put one level above the
// last contact before it (in the solve order) that shares a dynamic body with it (Box2D v3's graph
// colouring, with colours ordered so that each body sees its contacts in the same order):
//   level(c) = 1 + max(level of the last earlier contact on c.a, ... on c.b),
// the static body joining no level, since the solver never writes it. Solving level after level,
// the contacts within a level side by side (SIMD lanes), gives the same bytes as the sequential
// order, which shock propagation needs bottom-up.
//
// The three runs of SolverContext::split keep to levels of their own, in run order: the first two
// (which share no body) may then go to two threads, with one wait between them and the third.
#pragma once

#include "contact_solver.h"

#include <vector>

namespace mb {

constexpr int kLanes = 4;  // contacts per batch: an AVX register of doubles per field

struct ContactGraph {
    // Contacts (indices into the solve order) batch by batch, kLanes to a batch; -1 pads a batch.
    std::vector<int> slots;
    // Level k's batches are [levelBegin[k], levelBegin[k + 1]).
    std::vector<int> levelBegin;
    std::vector<int> slotOf;  // per contact: its slot, batch · kLanes + lane
    int runEnd[2] = {
        0, 0};  // the levels of the first run end at runEnd[0], of the second at runEnd[1]

    int batches() const { return int(slots.size()) / kLanes; }
    int levels() const { return int(levelBegin.size()) - 1; }
};

struct BodyX {  // a body and its x, for sideByMedianX
    double x;
    int body;
};
// The halves two threads may solve at once (SolverContext::split): the dynamic bodies left of
// the median x are side 0, the rest side 1. The cut depends on the bodies alone, never on the
// thread count. `byX`: the bodies in x order, kept by the caller from the last call.
void sideByMedianX(const std::vector<PhysicsBody>& bodies, std::vector<BodyX>& byX,
                   std::vector<char>& side);
// A contact of bodies a and b within one side (or between one side and the static body) goes to
// that side's run; one across the cut to the joining run, 2, solved after both: no body is in
// both halves.
inline int runOf(int a, int b, const std::vector<char>& side, int staticBody) {
    const int sb = side[size_t(b)];
    return a == staticBody || side[size_t(a)] == sb ? sb : 2;
}

// Levels for `contacts` in their solve order, in the runs split[] gives (SolverContext::split);
// `staticBody` is the index of the static body. `scratch` is kept by the caller so that a step
// allocates nothing.
void buildContactGraph(const std::vector<Contact>& contacts, const int split[2], int staticBody,
                       ContactGraph& graph, std::vector<int>& scratch);

}  // namespace mb
