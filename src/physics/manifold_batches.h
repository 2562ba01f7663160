// manifold_batches.h — the rigid bodies' manifolds solved four at a time, as contact_batches.h
// solves the spheres' contacts.
//
// A manifold's rows move its two bodies alone, so two manifolds that share no moving body
// commute. Each goes one level above the last manifold before it, in the bottom-up solve order,
// that moves a body it moves (contact_graph.h); solving level after level gives the same bytes as
// solving one manifold after another. A body moves in all of its manifolds of a step or in none
// (its rows are made before anything wakes), so a body that none moves is only read, by any
// level. The manifolds of a level are solved side by side, one to a lane: the lanes sweep their
// rows together until each has settled or spent its sweeps, and a settled lane is held as it is.
//
// The rows live here, structure of arrays, from load() to store(): a batch holds a level's
// kLanes manifolds and its rows, one row of each lane's manifold to a RowLanes, the batch's most
// rows of them; a lane with fewer rows holds its last ones empty.
#pragma once

#include "contact_batches.h"
#include "rigid_rows.h"

#include <glm/gtc/quaternion.hpp>
#include <vector>

namespace mb {

struct LaneVec {
    Lanes x, y, z;
};

// Where a side's point of each lane's row has gone (AnchorPath).
struct AnchorLanes {
    LaneVec anchor, local, offset;
};

// The normal rows of each lane's manifold that share a place in it.
struct RowLanes {
    LaneVec normal, armA, armB, turnA, turnB;
    Lanes mass, impulse, maxImpulse;
    Lanes separation;  // at this pass
};

// And where their points have gone, which each pass reads once: apart from the rows, which the
// warm start and the sweeps read again and again.
struct PathLanes {
    Lanes start;  // the separation at the step's start
    AnchorLanes a, b;
};

struct ManifoldBatch {
    // Each lane's bodies: a's and b's velocity, then its spin (three doubles after it); null for
    // a static a, and for both of a padding lane.
    double* a[kLanes];
    double* b[kLanes];
    bool* supportedA[kLanes];
    bool* supportedB[kLanes];
    // And their displacements and turns since the step began (AnchorPath's), null where none.
    const glm::dvec3* deltaA[kLanes];
    const glm::dvec3* deltaB[kLanes];
    const glm::dquat* orientA[kLanes];
    const glm::dquat* orientB[kLanes];
    int count = 0;     // lanes in use
    int rows = 0;      // RowLanes from firstRow: the most rows of its lanes' manifolds
    int firstRow = 0;  // in the batches' rows
    Lanes rowCount, solveSweeps, relaxSweeps;  // per lane
    Lanes relaxed;                             // the sweeps each took in the last relax pass
    Lanes hasA, invMassA, invMassB;            // hasA: 1 where a is not static
    // The friction and rolling rows (FrictionRows), lane by lane.
    LaneVec normal, tangent[2], armA[2], armB[2], turnA[2], turnB[2];
    LaneVec twistA, twistB, rollA[2], rollB[2];
    Lanes friction, twistMass, twistArm, rollLimit;
    Lanes tangentMass[3], rollMass[3];  // PairMass's m00, m01, m11
    Lanes tangentImpulse[2], twistImpulse, rollImpulse[2];
};

// What a pass solves with: the soft step's constants (Softness) and the sweeps' bounds.
struct ManifoldPass {
    double h = 0.0;  // the substep, s
    double biasRate = 0.0, massScale = 1.0, impulseScale = 0.0;
    double maxPushSpeed = 0.0;    // m/s
    double slop = 0.0;            // m: the overlap that the solve pass leaves unpushed
    double sweepTolerance = 0.0;  // m/s: a sweep that changed no row more has settled
    bool rolling = false;         // rolling resistance is on
};

class ManifoldBatches {
public:
    // Levels and batches for the manifolds in their solve order, from their rows and the rows'
    // contacts; `bodies`: one more than the largest RigidManifold::movesA or movesB. A manifold
    // sweeps at most `sweeps` times in the relax pass, once in the solve pass, and an impact
    // `impactSweeps` times in both.
    void load(const std::vector<NormalRow>& rows, const std::vector<RigidContact>& contacts,
              const std::vector<RigidManifold>& manifolds, int bodies, int sweeps,
              int impactSweeps);
    // Every point's push, then every manifold's friction and rolling: the impulses so far.
    void warmStart(bool twoLanes);
    // Each pass finds its rows' separations from where the bodies are now; the solve pass
    // (useBias) also sets the bodies' `supported` where a row pushed.
    void solve(const ManifoldPass& pass, bool useBias, bool twoLanes);

    // A row's, or a manifold's friction rows', turns and masses, made again (followTurns).
    void setTurns(int row, const NormalRow& r);
    void setTurns(int manifold, const FrictionRows& r);
    // The impulses back into the rows, and the sweeps the last relax pass took.
    void store(std::vector<NormalRow>& rows, std::vector<RigidManifold>& manifolds) const;

private:
    void place(ManifoldBatch& batch, int lane, const std::vector<NormalRow>& rows,
               const std::vector<RigidContact>& contacts, const RigidManifold& m, int sweeps,
               int impactSweeps);

    std::vector<ManifoldBatch> batches_;
    std::vector<RowLanes> rows_;
    std::vector<PathLanes> paths_;   // rows_'s
    std::vector<int> rowSlot_;       // per row: its RowLanes · kLanes + lane
    std::vector<int> manifoldSlot_;  // per manifold: its batch · kLanes + lane
    std::vector<int> laneOf_;        // and back: per slot, its manifold; −1 for a padding lane
    std::vector<int> scratch_, next_, levelBegin_;  // load()'s, kept for their room
};

}  // namespace mb
