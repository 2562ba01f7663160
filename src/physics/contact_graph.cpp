// contact_graph.cpp — levels of contacts that share no dynamic body (see contact_graph.h).
#include "contact_graph.h"

#include <algorithm>

namespace mb {

void sideByMedianX(const std::vector<PhysicsBody>& bodies, std::vector<BodyX>& byX,
                   std::vector<char>& side) {
    const size_t n = bodies.size() - 1;  // the static body, last, joins no side
    const bool fresh = byX.size() != n;
    if (fresh) {
        byX.resize(n);
        for (size_t i = 0; i < n; ++i) byX[i].body = int(i);
    }
    for (BodyX& e : byX) e.x = bodies[size_t(e.body)].pos.x;
    // Bodies move little between steps: the last order, re-sorted by insertion, is near linear,
    // where a selection (nth_element) guessed wrong at most of its comparisons.
    auto less = [](const BodyX& a, const BodyX& b) { return a.x < b.x; };
    if (fresh) std::sort(byX.begin(), byX.end(), less);
    for (size_t i = 1; i < n; ++i) {
        const BodyX e = byX[i];
        size_t j = i;
        for (; j > 0 && less(e, byX[j - 1]); --j) byX[j] = byX[j - 1];
        byX[j] = e;
    }
    const double middle = n > 0 ? byX[n / 2].x : 0.0;  // as nth_element would find it
    side.resize(n);
    for (size_t i = 0; i < n; ++i) side[i] = bodies[i].pos.x < middle ? 0 : 1;
}

void buildContactGraph(const std::vector<Contact>& contacts, const int split[2], int staticBody,
                       ContactGraph& graph, std::vector<int>& scratch) {
    const int n = int(contacts.size());
    // scratch: per body, one past the level of its last contact so far; per contact, its level k
    // and whether it bore load last step, as 2k + 1 or 2k; per such value (two a level, at most
    // one a contact), the next place in its level.
    scratch.assign(size_t(staticBody) + 1 + 3 * size_t(n), 0);
    int* above = scratch.data();
    int* level = above + staticBody + 1;
    int* next = level + n;
    int levels = 0;
    const int runEnd[3] = {split[0], split[1], n};
    for (int run = 0, i = 0; run < 3; ++run) {
        const int floor = levels;  // a run's levels start above the runs before it
        for (; i < runEnd[run]; ++i) {
            const Contact& c = contacts[size_t(i)];
            const int k = std::max({floor, c.a == staticBody ? 0 : above[c.a], above[c.b]});
            level[i] = k << 1 | (c.normalImpulse > 0.0 ? 1 : 0);
            above[c.a] = above[c.b] = k + 1;  // the static body's entry is never read
            levels = std::max(levels, k + 1);
        }
        if (run < 2) graph.runEnd[run] = levels;
    }
    // Counting sort by level, keeping the solve order within each; each level padded to whole
    // batches. Within a level the order is free: contacts that bore load last step go first, so
    // that the open speculative ones fill batches of their own, whose friction rows the solver
    // skips. A level's loaded ones count from its start, its open ones from after them: one pass
    // places both, with no branch on which a contact is (it would be guessed wrong often).
    for (int i = 0; i < n; ++i) ++next[level[i]];
    std::vector<int>& begin = graph.levelBegin;
    begin.assign(size_t(levels) + 1, 0);
    for (int k = 0; k < levels; ++k) {
        const int loaded = next[2 * k + 1], open = next[2 * k];
        begin[size_t(k) + 1] = begin[size_t(k)] + (loaded + open + kLanes - 1) / kLanes;
        next[2 * k + 1] = 0;
        next[2 * k] = loaded;
    }
    graph.slots.assign(size_t(begin.back()) * kLanes, -1);
    graph.slotOf.resize(size_t(n));
    for (int i = 0; i < n; ++i) {
        const int slot = begin[size_t(level[i] >> 1)] * kLanes + next[level[i]]++;
        graph.slots[size_t(slot)] = i;
        graph.slotOf[size_t(i)] = slot;
    }
}

}  // namespace mb
