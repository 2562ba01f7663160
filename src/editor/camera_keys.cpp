// camera_keys.cpp — keyframes kept in order of t.
#include "marchbox/editor/camera_keys.h"

#include <algorithm>
#include <cmath>

namespace mb {

int setCameraKey(Scene& s, float t, const Camera& view) {
    auto at = std::lower_bound(s.keyframes.begin(), s.keyframes.end(), t,
                               [](const Keyframe& k, float v) { return k.t < v; });
    if (at == s.keyframes.end() || at->t != t) at = s.keyframes.insert(at, Keyframe{t});
    at->pos = view.pos;
    at->target = view.target;
    at->fov = view.fov;
    return int(at - s.keyframes.begin());
}

int moveCameraKey(Scene& s, int index, float t) {
    std::vector<Keyframe>& keys = s.keyframes;
    if (index < 0 || index >= int(keys.size()) || !(t >= 0.0f)) return -1;
    for (const Keyframe& k : keys)
        if (k.t == t) return &k == &keys[size_t(index)] ? index : -1;
    Keyframe moved = keys[size_t(index)];
    keys.erase(keys.begin() + index);
    moved.t = t;
    auto at = std::lower_bound(keys.begin(), keys.end(), t,
                               [](const Keyframe& k, float v) { return k.t < v; });
    return int(keys.insert(at, moved) - keys.begin());
}

int nearestCameraKey(const Scene& s, double t) {
    int best = -1;
    for (size_t i = 0; i < s.keyframes.size(); ++i)
        if (best < 0 || std::abs(s.keyframes[i].t - t) < std::abs(s.keyframes[size_t(best)].t - t))
            best = int(i);
    return best;
}

}  // namespace mb
