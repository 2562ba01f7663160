// broadphase.cpp — a sorted uniform grid for sphere pairs.
#include "marchbox/broadphase.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tuple>

namespace mb {

namespace {

bool overlaps(const std::vector<glm::dvec3>& c, const std::vector<double>& e, int i, int j) {
    glm::dvec3 d = c[j] - c[i];
    double reach = e[i] + e[j];
    return glm::dot(d, d) < reach * reach;
}

void addPair(std::vector<std::pair<int, int>>& pairs, int i, int j) {
    pairs.emplace_back(std::min(i, j), std::max(i, j));
}

}  // namespace

void Broadphase::findPairs(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents,
                           std::vector<std::pair<int, int>>& pairs) {
    pairs.clear();
    if (centres.empty()) return;
    buildCells(centres, extents);
    pairCells(centres, extents, pairs);
    pairLarge(centres, extents, pairs);
}

void Broadphase::buildCells(const std::vector<glm::dvec3>& centres,
                            const std::vector<double>& extents) {
    const int n = int(centres.size());
    scratch_ = extents;
    auto p95 = scratch_.begin() + (n - 1) * 95 / 100;
    std::nth_element(scratch_.begin(), p95, scratch_.end());
    // A sphere of extent <= cell/2 overlaps only spheres whose centres are within one cell.
    const double cell = 2.0 * *p95;
    const bool fresh = int(cells_.size()) != n;
    if (fresh) {
        cells_.assign(n, Entry{0, 0, 0, 0});
        for (int i = 0; i < n; ++i) cells_[i].body = i;
    }
    large_.clear();
    isLarge_.assign(n, 0);
    for (Entry& e : cells_) {
        const glm::dvec3& c = centres[e.body];
        e.x = std::int64_t(std::floor(c.x / cell));
        e.y = std::int64_t(std::floor(c.y / cell));
        e.z = std::int64_t(std::floor(c.z / cell));
        if (extents[e.body] > 0.5 * cell) isLarge_[e.body] = 1;
    }
    for (int i = 0; i < n; ++i)
        if (isLarge_[i]) large_.push_back(i);
    // (x, y, z, body) is a total order, so the sorted list does not depend on the previous one
    // and determinism holds. Between steps few bodies change cell: insertion sort is then linear.
    auto less = [](const Entry& a, const Entry& b) {
        return std::tie(a.x, a.y, a.z, a.body) < std::tie(b.x, b.y, b.z, b.body);
    };
    if (fresh) {
        std::sort(cells_.begin(), cells_.end(), less);
        return;
    }
    for (int i = 1; i < n; ++i) {
        Entry e = cells_[i];
        int j = i;
        for (; j > 0 && less(e, cells_[j - 1]); --j) cells_[j] = cells_[j - 1];
        cells_[j] = e;
    }
}

int Broadphase::cellEnd(int begin) const {
    const Entry& c = cells_[begin];
    int end = begin + 1;
    while (end < int(cells_.size()) && cells_[end].x == c.x && cells_[end].y == c.y &&
           cells_[end].z == c.z)
        ++end;
    return end;
}

int Broadphase::findCell(std::int64_t x, std::int64_t y, std::int64_t z) const {
    auto it = std::lower_bound(cells_.begin(), cells_.end(), std::make_tuple(x, y, z),
                               [](const Entry& a, const std::tuple<std::int64_t, std::int64_t,
                                                                   std::int64_t>& b) {
                                   return std::tie(a.x, a.y, a.z) < b;
                               });
    if (it == cells_.end() || it->x != x || it->y != y || it->z != z) return -1;
    return int(it - cells_.begin());
}

// Each cell pairs with itself and with the 13 neighbours that come after it in (x, y, z) order,
// so every adjacent pair of cells is visited once.
void Broadphase::pairCells(const std::vector<glm::dvec3>& centres,
                           const std::vector<double>& extents,
                           std::vector<std::pair<int, int>>& pairs) const {
    const int n = int(cells_.size());
    for (int begin = 0, end; begin < n; begin = end) {
        end = cellEnd(begin);
        const Entry& c = cells_[begin];
        for (int dx = 0; dx <= 1; ++dx)
            for (int dy = dx ? -1 : 0; dy <= 1; ++dy)
                for (int dz = (dx || dy) ? -1 : 0; dz <= 1; ++dz) {
                    const bool self = !dx && !dy && !dz;
                    const int other = self ? begin : findCell(c.x + dx, c.y + dy, c.z + dz);
                    if (other < 0) continue;
                    const int otherEnd = self ? end : cellEnd(other);
                    for (int i = begin; i < end; ++i)
                        for (int j = self ? i + 1 : other; j < otherEnd; ++j) {
                            const int a = cells_[i].body, b = cells_[j].body;
                            if (!isLarge_[a] && !isLarge_[b] && overlaps(centres, extents, a, b))
                                addPair(pairs, a, b);
                        }
                }
    }
}

void Broadphase::pairLarge(const std::vector<glm::dvec3>& centres, const std::vector<double>& extents,
                           std::vector<std::pair<int, int>>& pairs) const {
    const int n = int(centres.size());
    for (int big : large_)
        for (int j = 0; j < n; ++j) {
            // Large–large pairs once: from the lower index only.
            if (j == big || (isLarge_[j] && j < big)) continue;
            if (overlaps(centres, extents, big, j)) addPair(pairs, big, j);
        }
}

}  // namespace mb
