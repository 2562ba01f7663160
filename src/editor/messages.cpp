// messages.cpp — each message in its place, while its context lasts (see messages.h).
#include "marchbox/editor/messages.h"

namespace mb {

Place itemPlace(ItemKind k) {
    switch (k) {
        case ItemKind::Object:
        case ItemKind::Group:  // groups are listed with the objects
            return Place::Objects;
        case ItemKind::Material:
            return Place::Materials;
        case ItemKind::Light:
            return Place::Lights;
    }
    return Place::Objects;
}

static bool aboutSelection(Place p) { return p <= Place::ObjectPopup; }

void Messages::shown(Place p) { entries_[size_t(p)].shown = true; }

void Messages::say(Place p, const std::string& text) {
    entries_[size_t(p)].text = text;
    entries_[size_t(p)].said = true;
}

bool Messages::isNew(Place p) const {
    const Entry& e = entries_[size_t(p)];
    return !e.text.empty() && (e.text != e.before || e.said);
}

void Messages::endFrame(const Selection& selection, double seconds) {
    const bool reselected =
        !(selection.kind == selection_.kind && selection.index == selection_.index);
    selection_ = selection;
    for (int i = 0; i < kPlaceCount; ++i) {
        Entry& e = entries_[size_t(i)];
        const Place p = Place(i);
        if (isNew(p)) {
            e.since = seconds;
        } else if (p == Place::Status ? seconds - e.since >= kStatusSeconds
                                      : !e.shown || (reselected && aboutSelection(p))) {
            e.text.clear();
        }
        e.before = e.text;
        e.said = false;
        e.wasShown = e.shown;
        e.shown = false;
    }
}

}  // namespace mb
