// marchbox/report/median.h — the middle of a set of timings, which a burst of other work on a
// shared machine moves least: what the reports and their benchmarks quote.
#pragma once

#include <algorithm>
#include <vector>

namespace mb {

// The upper middle element for an even count; v must not be empty.
inline double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace mb
