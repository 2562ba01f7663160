// contact_batches.h — the contact solver's rows, four contacts at a time.
//
// The solver's state lives here from load() to the end of the substeps, structure of
// arrays: a batch holds kLanes contacts of one level (contact_graph.h), each field a row
// of kLanes doubles, so that one pass reads each contact's ~200 bytes once, in memory order, and
// computes its rows with SIMD instructions. The lanes compute what the rows of one contact
// computed one at a time, operation for operation, so the result is the same to the bit (but
// for the sign of a zero, where a lane applies a change of 0 that one contact would have skipped).
// Bodies are gathered into the lanes and scattered back; a level shares no dynamic body, so the
// lanes never write the same body.
#pragma once

#include "contact_graph.h"

#include <glm/vec3.hpp>
#include <vector>

namespace mb {

// kLanes doubles side by side (GCC's vector extension): one AVX register where the CPU has AVX2 or
// AVX-512; on baseline x86-64 the passes take it in halves, an SSE2 register each
// (contact_batches.cpp compiles its passes for each). Aligned to its size even where the baseline
// would align it less: the AVX code loads it whole.
using Lanes =
    double __attribute__((vector_size(kLanes * sizeof(double)), aligned(kLanes * sizeof(double))));

// A row set: effective masses (RowMasses) and the inverse masses the impulses are applied with.
struct LaneRows {
    Lanes normal, tangent, roll;
    Lanes massA, inertiaA, massB, inertiaB;
};

struct ContactBatch {
    PhysicsBody* a[kLanes];  // bodies (in SolverContext::bodies); a padding lane has
    PhysicsBody* b[kLanes];  // the static body for both
    int count = 0;           // lanes in use
    Lanes nx, ny, nz;        // normal
    Lanes separation, armA, armB, slop, curve, rollRadius, friction;
    LaneRows solve, relax;  // relax: the lower body held fixed under shock propagation
    Lanes normalImpulse, maxNormalImpulse;
    Lanes tx, ty, tz, rx, ry, rz;  // tangent and rolling impulses
};

class Worker;

class ContactBatches {
public:
    // Levels and batches for ctx.contacts, in their solve order, each contact prepared for this
    // step on the way (prepareContact); half the batches on ctx.worker where there is one.
    void load(const SolverContext& ctx);
    void warmStart(SolverContext& ctx);
    // The solve pass (useBias) also sets PhysicsBody::supported: pushed by a contact after it.
    void solve(SolverContext& ctx, bool useBias);      // useBias false: the relax pass
    void store(std::vector<Contact>& contacts) const;  // impulses back into the contacts
    // A curved contact, followed substep by substep: its bend for the solve pass; its normal and
    // separation where the body is now, its friction impulse turned into the new tangent plane.
    void setCurve(int contact, double curve);
    void follow(int contact, const glm::dvec3& normal, double separation);

    int levels() const { return graph_.levels(); }

private:
    void loadBatches(const SolverContext& ctx, int begin, int end);
    ContactBatch& batchOf(int contact, int& lane);

    ContactGraph graph_;
    std::vector<ContactBatch> batches_;
    std::vector<int> scratch_;
};

}  // namespace mb
