// selection.cpp — keeping the selection on its item while lists change.
#include "marchbox/editor/selection.h"

namespace mb {

void selectionAfterDelete(Selection& sel, ItemKind kind, int deleted) {
    if (sel.empty() || sel.kind != kind) return;
    if (sel.index == deleted) sel.clear();
    else if (sel.index > deleted) --sel.index;
}

void selectionClamp(Selection& sel, const Scene& scene) {
    if (sel.index >= itemCount(scene, sel.kind)) sel.clear();
}

}  // namespace mb
