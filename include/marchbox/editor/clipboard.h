// marchbox/editor/clipboard.h — the selection as scene text, for Ctrl+C and Ctrl+V: the same
// text goes between two windows, into a text editor and back.
#pragma once

#include "marchbox/editor/scene_edit.h"
#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb {

// A whole scene file holding the roots of `items` with everything inside them, each at the top
// level where it stands in the world, and the materials they use; "" for no items.
std::string copyText(const Scene& s, const std::vector<Item>& items);

// The objects and groups of scene text (a file, or records without its header, read as version
// 3) added to `s` at the top level, where the text puts them. A material is matched by name
// where `s` has one of that name, added otherwise; a name in use gets copyName's. *pasted gets
// the new top-level items. False, `s` untouched, with *why: the text's first error, or no room.
bool pasteText(Scene& s, const std::string& text, std::vector<Item>* pasted, std::string* why);

}  // namespace mb
