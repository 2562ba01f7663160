// marchbox/broadphase.h — candidate sphere pairs in near O(N): a uniform grid kept sorted.
//
// Each sphere, grown by its speculative margin, has an extent e (a radius). The cell size is twice
// the 95th-percentile extent, so a typical sphere fits in one cell and two that overlap lie in the
// same or adjacent cells. The few larger ones (fast spheres, a boulder among pebbles) are tested
// against everyone. The cell list stays sorted between steps, so re-sorting is near linear.
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
    struct Entry {
        std::int64_t x, y, z;  // cell
        int body;
    };
    void buildCells(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents);
    void pairCells(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents,
                   std::vector<std::pair<int, int>>& pairs) const;
    int cellEnd(int begin) const;                           // one past the run of cells_[begin]
    int findCell(std::int64_t x, std::int64_t y, std::int64_t z) const;  // first entry, or -1
    void pairLarge(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents,
                   std::vector<std::pair<int, int>>& pairs) const;

    std::vector<Entry> cells_;  // sorted by (x, y, z, body)
    std::vector<int> large_;    // bodies too big for the grid, ascending
    std::vector<char> isLarge_;
    std::vector<double> scratch_;
};

}  // namespace mb
