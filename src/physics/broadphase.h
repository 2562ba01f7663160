// broadphase.h — candidate sphere pairs in near O(N): a uniform grid kept sorted.
//
// Each sphere, grown by its speculative margin, has an extent e (a radius). The cell size is twice
// the 99th-percentile extent, so a typical sphere fits in one cell and two that overlap lie in the
// same or adjacent cells. The few larger ones (fast spheres, a boulder among pebbles) look up the
// block of cells their reach covers, and each other by sweep and prune along x. The cell list
// stays sorted between steps, so re-sorting is near linear, and neighbour cells are found by
// cursors that only move forward through it, so pairing is linear too: no per-cell searches.
//
// The grid runs with each extent grown by a skin, and its pairs are kept (a Verlet list): while no
// sphere has moved (beside the spheres' mean move) and grown by more than its skin since, every
// pair that overlaps now is among them, and a step only tests those. A sphere past its skin is
// refreshed, with those near theirs: it takes its place now (in the grid's frame) and a new skin,
// its pairs are found again and the rest are kept; many at once rebuild the whole list.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

namespace mb {

class Broadphase {
public:
    // Pairs (i < j) with |ci − cj| < ei + ej, in a deterministic order.
    void findPairs(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents,
                   std::vector<std::pair<int, int>>& pairs);

private:
    // True where the kept list still covers this step once the spheres it lists in moved_ are
    // refreshed (none: it covers the step as it is); false where it must be built anew.
    bool listStillCovers(const std::vector<glm::dvec3>& centres,
                         const std::vector<double>& extents);
    void buildList(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents);
    void refresh();  // the spheres in moved_, from their refs_ and listExtents_

    struct Entry {
        std::int64_t x, y, z;  // cell
        int body;
    };
    struct Sphere {  // a body's centre and extent, stored in cell order for locality
        glm::dvec3 centre;
        double extent;
        bool large;
        int body;
    };
    using Pairs = std::vector<std::pair<int, int>>;
    void buildCells();
    void pairCells(Pairs& pairs) const;
    struct Run {  // entries [begin, end): a cell, or a neighbour column's cells
        int begin, end;
    };
    // Entry i against the runs of its cell and its neighbours, its own cell first (the entries
    // after i there, so each pair once); `candidates` bounds what it may add at pairs[kept].
    void pairSphere(int i, const Run* runs, int count, size_t candidates, Pairs& pairs,
                    size_t& kept) const;
    int cellEnd(int begin) const;  // one past the run of entries_[begin]
    // First entry at or after cell (x, y, z), searching [from, end).
    int lowerBound(int from, std::int64_t x, std::int64_t y, std::int64_t z) const;
    void pairLarge(Pairs& pairs) const;
    void pairBlock(int entry, Pairs& pairs) const;  // a large sphere against the small
    // A refreshed entry's pairs, at pairs[kept] on; its neighbour columns found from cursor[] on
    // (pairCells' way).
    void pairMoved(int entry, int (&cursor)[9], Pairs& pairs, size_t& kept) const;

    std::vector<Entry> entries_;   // each sphere's cell, sorted by (x, y, z, body)
    std::vector<Sphere> spheres_;  // spheres_[i] is body entries_[i].body
    std::vector<int>
        large_;  // entries of bodies too big for the grid, by the low end of their reach in x
    std::vector<double> scratch_;
    double cell_ = 1.0;                      // edge of a grid cell, since the list was last built
    std::vector<std::pair<int, int>> list_;  // pairs of the grown spheres
    std::vector<glm::dvec3>
        refs_;  // each centre when last placed, less the mean move from the build to then
    std::vector<double> listExtents_;  // grown extents then
    std::vector<int> moved_,
        entryOf_;  // bodies (then entries) to refresh; each body's entry in entries_
    std::vector<char> isMoved_;
};

}  // namespace mb
