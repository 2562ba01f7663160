// broadphase.cpp — sphere pairs from a kept list over a sorted uniform grid: rebuilt whole, or
// refreshed for the spheres that moved past their skin.
#include "broadphase.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tuple>

namespace mb {

namespace {

// The 13 neighbours that follow a cell (x, y, z) in (x, y, z) order, as runs of one column
// (constant x, y) each: its own column at z + 1, then the columns (x, y+1), (x+1, y−1), (x+1, y)
// and (x+1, y+1) from z − 1 to z + 1. Pairing each cell with itself and these visits every
// adjacent pair of cells once.
struct Column {
    int dx, dy, dz;  // offset of the column, and the first z in it
};
constexpr Column kColumns[5] = {{0, 0, 1}, {0, 1, -1}, {1, -1, -1}, {1, 0, -1}, {1, 1, -1}};

template <class Entry>
bool cellLess(const Entry& e, std::int64_t x, std::int64_t y, std::int64_t z) {
    return std::tie(e.x, e.y, e.z) < std::tie(x, y, z);
}

bool overlaps(const glm::dvec3& ci, double ei, const glm::dvec3& cj, double ej) {
    const glm::dvec3 d = cj - ci;
    const double reach = ei + ej;
    return glm::dot(d, d) < reach * reach;
}

// (min, max) by arithmetic: std::minmax branches, on what is here anyone's guess.
std::pair<int, int> ordered(int i, int j) {
    const int below = (j - i) & ((j - i) >> 31);  // j − i where j < i, else 0
    return {i + below, j - below};
}

void addPair(std::vector<std::pair<int, int>>& pairs, int i, int j) {
    pairs.emplace_back(std::min(i, j), std::max(i, j));
}

}  // namespace

// The skin, as a fraction of the extent: larger keeps the list longer, smaller tests fewer pairs.
constexpr double kSkin = 0.5;
// A refresh takes the spheres past this share of their grown extent too, so that those close to
// their skin do not each call for another the next steps. More than kRebuild of them at once
// (a pile on its way down) are cheaper found all anew.
constexpr double kRefreshAt = 1.0 - 0.5 * kSkin / (1.0 + kSkin);
constexpr double kRebuild = 0.25;

void Broadphase::findPairs(const std::vector<glm::dvec3>& centres,
                           const std::vector<double>& extents,
                           std::vector<std::pair<int, int>>& pairs) {
    pairs.clear();
    if (centres.empty()) return;
    if (!listStillCovers(centres, extents)) buildList(centres, extents);
    else if (!moved_.empty()) refresh();
    // Every listed pair is written and the count moves on where it overlaps: which do is
    // anyone's guess, so a branch on it would be guessed wrong often.
    pairs.resize(list_.size());
    size_t kept = 0;
    for (auto [i, j] : list_) {
        pairs[kept] = {i, j};
        kept +=
            overlaps(centres[size_t(i)], extents[size_t(i)], centres[size_t(j)], extents[size_t(j)])
                ? 1
                : 0;
    }
    pairs.resize(kept);
}

// A pair left out of the list was at least E_i + E_j apart (grown extents, at the places refs_
// holds); it overlaps now only if e_i + e_j + how far the two moved apart since exceeds that.
// Moved apart: |d_i − d_j|, at most |d_i − o| + |d_j − o| for any common move o, here the mean
// (a pile falling together keeps its pairs): refs_ are kept in one frame, each moved by the
// mean move up to its last refresh, so one o serves all. So the list holds every overlapping
// pair while each sphere's extent plus its move beside the mean stays within its grown extent;
// the factor keeps that true through the rounding of the distance tests.
bool Broadphase::listStillCovers(const std::vector<glm::dvec3>& centres,
                                 const std::vector<double>& extents) {
    const size_t n = centres.size();
    if (refs_.size() != n) return false;
    glm::dvec3 shift(0.0);
    for (size_t i = 0; i < n; ++i) shift += centres[i] - refs_[i];
    shift /= double(n);
    moved_.clear();
    auto used = [&](size_t i) { return extents[i] + glm::length(centres[i] - refs_[i] - shift); };
    size_t i = 0;
    while (i < n && used(i) <= (1.0 - 1e-9) * listExtents_[i]) ++i;  // most steps: all within
    if (i == n) return true;
    for (i = 0; i < n; ++i)
        if (used(i) > kRefreshAt * listExtents_[i]) moved_.push_back(int(i));
    if (double(moved_.size()) > kRebuild * double(n)) return false;
    for (int m : moved_) {
        refs_[size_t(m)] = centres[size_t(m)] - shift;
        listExtents_[size_t(m)] = (1.0 + kSkin) * extents[size_t(m)];
    }
    return true;
}

void Broadphase::buildList(const std::vector<glm::dvec3>& centres,
                           const std::vector<double>& extents) {
    const int n = int(centres.size());
    refs_ = centres;
    listExtents_.resize(extents.size());
    for (size_t i = 0; i < extents.size(); ++i) listExtents_[i] = (1.0 + kSkin) * extents[i];
    // The 99th percentile: each sphere left large costs a block search (pairBlock) at every
    // rebuild, more than the slightly larger cells cost the rest (a settling pile of 1000: 95th
    // 18.4e6 cycles of list building in 180 steps, 99th 16.7e6).
    scratch_ = listExtents_;
    auto p99 = scratch_.begin() + (n - 1) * 99 / 100;
    std::nth_element(scratch_.begin(), p99, scratch_.end());
    // A sphere of extent <= cell/2 overlaps only spheres whose centres are within one cell.
    cell_ = 2.0 * *p99;
    list_.clear();
    buildCells();
    pairCells(list_);
    pairLarge(list_);
}

// The moved spheres' pairs go, and each finds its pairs anew, against the others where refs_
// holds them (one pair of two moved ones is found from its first body). The grid keeps its cell
// size: a sphere grown past it is large, and tested against all. Taken in cell order, as
// pairCells takes the cells, so that the neighbour columns' cursors only move forward.
void Broadphase::refresh() {
    buildCells();
    isMoved_.assign(refs_.size(), 0);
    for (int& i : moved_) {
        isMoved_[size_t(i)] = 1;
        i = entryOf_[size_t(i)];
    }
    size_t kept = 0;
    for (auto [i, j] :
         list_) {  // each written, kept where neither moved (without a branch, as findPairs)
        list_[kept] = {i, j};
        kept += size_t(!(isMoved_[size_t(i)] | isMoved_[size_t(j)]));
    }
    std::sort(moved_.begin(), moved_.end());
    int cursor[9] = {};
    for (int entry : moved_) pairMoved(entry, cursor, list_, kept);
    list_.resize(kept);
}

// The 3 × 3 columns around a small sphere's cell, z − 1 to z + 1, and the large spheres; a
// large one against all. Branch-free, as pairSphere: each candidate is written, and kept where
// it is another sphere, not a moved one that finds the pair itself, and overlaps.
void Broadphase::pairMoved(int entry, int (&cursor)[9], Pairs& pairs, size_t& kept) const {
    const Sphere& a = spheres_[entry];
    const int n = int(entries_.size());
    auto test = [&](int j, bool wanted) {
        const Sphere& b = spheres_[j];
        pairs[kept] = ordered(a.body, b.body);
        const bool mine = !(isMoved_[size_t(b.body)] && b.body < a.body);
        kept += size_t(wanted & (j != entry) & mine) &
                size_t(overlaps(a.centre, a.extent, b.centre, b.extent));
    };
    auto room = [&](size_t candidates) {
        if (pairs.size() < kept + candidates)
            pairs.resize(std::max(kept + candidates, 2 * pairs.size()));
    };
    if (a.large) {
        room(size_t(n));
        for (int j = 0; j < n; ++j) test(j, true);
        return;
    }
    Run runs[9];
    size_t candidates = large_.size();
    const Entry& c = entries_[entry];
    for (int k = 0; k < 9; ++k) {
        const std::int64_t x = c.x + k / 3 - 1, y = c.y + k % 3 - 1;
        int& from = cursor[k];
        while (from < n && cellLess(entries_[from], x, y, c.z - 1)) ++from;
        int last = from;
        while (last < n && entries_[last].x == x && entries_[last].y == y &&
               entries_[last].z <= c.z + 1)
            ++last;
        runs[k] = {from, last};
        candidates += size_t(last - from);
    }
    room(candidates);
    for (int j : large_) test(j, true);
    for (const Run& r : runs)
        for (int j = r.begin; j < r.end; ++j) test(j, !spheres_[j].large);
}

// The cells of refs_, sorted, and the spheres in their order.
void Broadphase::buildCells() {
    const int n = int(refs_.size());
    const bool fresh = int(entries_.size()) != n;
    if (fresh) {
        entries_.assign(n, Entry{0, 0, 0, 0});
        for (int i = 0; i < n; ++i) entries_[i].body = i;
    }
    for (Entry& e : entries_) {
        const glm::dvec3& c = refs_[e.body];
        e.x = std::int64_t(std::floor(c.x / cell_));
        e.y = std::int64_t(std::floor(c.y / cell_));
        e.z = std::int64_t(std::floor(c.z / cell_));
    }
    // (x, y, z, body) is a total order, so the sorted list does not depend on the previous one
    // and determinism holds. Between steps few bodies change cell: insertion sort is then linear.
    auto less = [](const Entry& a, const Entry& b) {
        return std::tie(a.x, a.y, a.z, a.body) < std::tie(b.x, b.y, b.z, b.body);
    };
    if (fresh) {
        std::sort(entries_.begin(), entries_.end(), less);
    } else {
        for (int i = 1; i < n; ++i) {
            Entry e = entries_[i];
            int j = i;
            for (; j > 0 && less(e, entries_[j - 1]); --j) entries_[j] = entries_[j - 1];
            entries_[j] = e;
        }
    }
    spheres_.resize(n);
    entryOf_.resize(size_t(n));
    large_.clear();
    for (int i = 0; i < n; ++i) {
        const int body = entries_[i].body;
        const double extent = listExtents_[size_t(body)];
        spheres_[i] = {refs_[size_t(body)], extent, extent > 0.5 * cell_, body};
        entryOf_[size_t(body)] = i;
        if (spheres_[i].large) large_.push_back(i);
    }
    // By the low end of their reach along x, for the sweep in pairLarge (ties by entry: a total
    // order).
    auto low = [&](int i) { return spheres_[i].centre.x - spheres_[i].extent; };
    std::sort(large_.begin(), large_.end(),
              [&](int a, int b) { return std::pair(low(a), a) < std::pair(low(b), b); });
}

int Broadphase::cellEnd(int begin) const {
    const Entry& c = entries_[begin];
    int end = begin + 1;
    while (end < int(entries_.size()) && entries_[end].x == c.x && entries_[end].y == c.y &&
           entries_[end].z == c.z)
        ++end;
    return end;
}

int Broadphase::lowerBound(int from, std::int64_t x, std::int64_t y, std::int64_t z) const {
    auto it = std::lower_bound(entries_.begin() + from, entries_.end(), 0,
                               [&](const Entry& e, int) { return cellLess(e, x, y, z); });
    return int(it - entries_.begin());
}

// Branch-free, as in findPairs: every candidate is written, and kept where it overlaps. Room is
// made one sphere at a time, so a crowded cell never asks for the square of its crowd, and in
// doublings, so that a rebuild seldom grows the list.
void Broadphase::pairSphere(int i, const Run* runs, int count, size_t candidates, Pairs& pairs,
                            size_t& kept) const {
    const Sphere& a = spheres_[i];
    if (a.large) return;
    if (pairs.size() < kept + candidates)
        pairs.resize(std::max(kept + candidates, 2 * pairs.size()));
    for (int r = 0; r < count; ++r)
        for (int j = r == 0 ? i + 1 : runs[r].begin; j < runs[r].end; ++j) {  // run 0: its own cell
            const Sphere& b = spheres_[j];
            pairs[kept] = ordered(a.body, b.body);
            kept += size_t(!b.large) & size_t(overlaps(a.centre, a.extent, b.centre, b.extent));
        }
}

// Cells are visited in increasing (x, y, z) order, and so, the order being translation
// invariant, is the start of each neighbour column: one cursor per column only moves forward.
void Broadphase::pairCells(Pairs& pairs) const {
    const int n = int(entries_.size());
    int cursor[5] = {0, 0, 0, 0, 0};
    Run runs[6];
    size_t kept = pairs.size();
    for (int begin = 0, end; begin < n; begin = end) {
        end = cellEnd(begin);
        const Entry& c = entries_[begin];
        int count = 0;
        runs[count++] = {begin, end};
        size_t candidates = size_t(end - begin);
        for (int k = 0; k < 5; ++k) {
            const std::int64_t x = c.x + kColumns[k].dx, y = c.y + kColumns[k].dy;
            int& j = cursor[k];
            while (j < n && cellLess(entries_[j], x, y, c.z + kColumns[k].dz)) ++j;
            int last = j;
            while (last < n && entries_[last].x == x && entries_[last].y == y &&
                   entries_[last].z <= c.z + 1)
                ++last;
            if (last == j) continue;
            runs[count++] = {j, last};
            candidates += size_t(last - j);
        }
        for (int i = begin; i < end; ++i) pairSphere(i, runs, count, candidates, pairs, kept);
    }
    pairs.resize(kept);
}

// Large against large by sweep and prune along x (at most 1 % by the cell size's choice, but 100
// in a pile of 10,000: all pairs of them would grow as the square), large against small through
// the grid.
void Broadphase::pairLarge(Pairs& pairs) const {
    for (size_t a = 0; a < large_.size(); ++a) {
        const Sphere& big = spheres_[large_[a]];
        const double high = big.centre.x + big.extent;
        for (size_t b = a + 1; b < large_.size(); ++b) {
            const Sphere& other = spheres_[large_[b]];
            if (other.centre.x - other.extent >= high)
                break;  // it and every later one are clear in x
            if (overlaps(big.centre, big.extent, other.centre, other.extent))
                addPair(pairs, entries_[large_[a]].body, entries_[large_[b]].body);
        }
        pairBlock(large_[a], pairs);
    }
}

// A small sphere's extent is at most cell/2, so one that overlaps `big` has its centre within
// e_big + cell/2 of big's on every axis: a block of cells, scanned column by column in the sorted
// order. A block with more columns than there are spheres (a boulder among pebbles) is cheaper
// tested sphere by sphere.
void Broadphase::pairBlock(int entry, Pairs& pairs) const {
    const Sphere& big = spheres_[entry];
    const int n = int(entries_.size());
    const double reach = big.extent + 0.5 * cell_;
    const glm::dvec3 lo = glm::floor((big.centre - reach) / cell_);
    const glm::dvec3 hi = glm::floor((big.centre + reach) / cell_);
    auto test = [&](int j) {
        const Sphere& s = spheres_[j];
        if (!s.large && overlaps(big.centre, big.extent, s.centre, s.extent))
            addPair(pairs, entries_[entry].body, entries_[j].body);
    };
    if ((hi.x - lo.x + 1) * (hi.y - lo.y + 1) > double(n)) {
        for (int j = 0; j < n; ++j) test(j);
        return;
    }
    const std::int64_t z0 = std::int64_t(lo.z), z1 = std::int64_t(hi.z);
    int from = 0;
    for (auto x = std::int64_t(lo.x); x <= std::int64_t(hi.x); ++x)
        for (auto y = std::int64_t(lo.y); y <= std::int64_t(hi.y); ++y) {
            int j = from = lowerBound(from, x, y, z0);
            for (; j < n && entries_[j].x == x && entries_[j].y == y && entries_[j].z <= z1; ++j)
                test(j);
        }
}

}  // namespace mb
