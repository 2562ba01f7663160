// carved.cpp — finding objects that a subtraction after them swallows.
#include "marchbox/editor/carved.h"

#include "marchbox/scene/sdf.h"

namespace mb {

// Whether a subtraction in group `cut`'s chain (-1: the top level) carves what stands in group
// `group`: when `cut` is that group or one holding it.
static bool chainHolds(const Scene& s, int cut, int group) {
    for (; group != cut && group >= 0; group = s.groups[size_t(group)].parent) {}
    return group == cut;
}

std::vector<int> carvedAway(const Scene& s) {
    const SceneSdf sdf = makeSceneSdf(s);
    std::vector<int> carver(s.objects.size(), -1);
    for (size_t j = 0; j < s.objects.size(); ++j) {
        const SdfObject& cut = sdf.objects[j];
        if (cut.op != CsgOp::Subtract) continue;
        // A subtraction carves what comes before it in its chain, groups and all: |f| never
        // exceeds the true distance, so f <= -bound at the centre puts the whole ball inside.
        for (size_t i = 0; i < j; ++i) {
            const SdfObject& o = sdf.objects[i];
            if (carver[i] < 0 && o.op != CsgOp::Subtract &&
                chainHolds(s, s.objects[j].group, s.objects[i].group) &&
                sdObject(cut, o.pos) <= -o.bound)
                carver[i] = int(j);
        }
    }
    return carver;
}

}  // namespace mb
