// panels_edit.cpp — Edit > Objects, Materials, Lights: lists with add, duplicate, delete and
// clear, the active item's every field, and the viewport's right-click popup. Objects is an
// outliner: groups open and close, rows drag into, out of and along groups.
//
// Fields edit a copy of the item; a changed copy goes back through the editor as one undo
// step, keyed by the widget so that one drag is one step, and with several objects or groups
// selected the fields that changed go to each of them.
#include "ui.h"
#include "widgets.h"

#include "marchbox/editor/carved.h"
#include "marchbox/editor/events.h"
#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

static constexpr auto kShapeNames = shapeColumn<&ShapeRow::name>();
static const char* const kOpNames[] = {"union", "subtract", "intersect"};
static const char* const kLightKinds[] = {"point", "directional"};
static const char* kObjectPopup = "object popup";

static ImVec4 swatchColour(const Material& m) {
    return ImVec4(m.color.r, m.color.g, m.color.b, 1.0f);
}

static void swatch(const Material& m, float size = 0.0f) {
    ImGui::ColorButton("##swatch", swatchColour(m), ImGuiColorEditFlags_NoTooltip,
                       ImVec2(size, size));
}

// Whether a top-level record moves, as its row says it; a member moves with its group.
template <class R>
static std::string motionWord(const R& r, int parent) {
    if (parent >= 0) return "";
    return r.dynamic() ? ", dynamic" : ", static";
}

static std::string itemName(const Scene& s, ItemKind k, int i) {
    std::string n = std::to_string(i) + " ";
    switch (k) {
        case ItemKind::Object: {  // "3 lid: box, subtract, static"; a member's without a motion
            const Object& o = s.objects[size_t(i)];
            if (!o.name.empty()) n += o.name + ": ";
            return n + shapeTypeName(o.type) + ", " + csgOpName(o.op) + motionWord(o, o.group);
        }
        case ItemKind::Group: {  // "cup: group, union, dynamic": names are unique
            const Group& g = s.groups[size_t(i)];
            return g.name + ": group, " + csgOpName(g.op) + motionWord(g, g.parent);
        }
        case ItemKind::Material:
            return n + s.materials[size_t(i)].name;
        case ItemKind::Light:
            return n + (s.lights[size_t(i)].directional ? "directional" : "point");
    }
    return n;
}

//-----------------------------------------------------------------------------
// Fields of one item
//-----------------------------------------------------------------------------
static void materialCombo(const Scene& s, int* material, FieldEdit& e) {
    const int m = *material;
    std::string preview = m < int(s.materials.size()) ? s.materials[size_t(m)].name : "?";
    const bool open = ImGui::BeginCombo("material", preview.c_str());
    markItem(itemPath("material"));
    itemTooltip(itemPath("material"), "The object's material, by index in the file.");
    if (!open) return;
    for (int i = 0; i < int(s.materials.size()); ++i) {
        ImGui::PushID(i);
        swatch(s.materials[size_t(i)]);
        ImGui::SameLine();
        if (ImGui::Selectable(s.materials[size_t(i)].name.c_str(), i == m) && i != m) {
            *material = i;
            e.changed = true;
            e.key = 0;  // a choice, not a drag: its own undo step
        }
        ImGui::PopID();
    }
    ImGui::EndCombo();
}

// A name, taken on Return when validateName() allows it and `taken` does not refuse it (a
// group's name is its own); `optional`: an empty one clears it.
template <typename Taken>
static void nameField(std::string* name, bool optional, FieldEdit& e, const char* tooltip,
                      Taken taken) {
    std::string typed = *name, why;
    if (ImGui::InputText("name", &typed, ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (typed != *name && taken(typed)) why = "another group is named '" + typed + "'";
        if (why.empty() && ((optional && typed.empty()) || validateName(typed, &why))) {
            *name = typed;
            e.changed = true;
            e.key = 0;  // a name typed is its own undo step
            e.error->clear();
        } else {
            *e.error = why + ": '" + typed + "' refused, '" + *name + "' kept";
            emitEvent("refuse " + *e.error);
        }
    }
    markItem(itemPath("name"));
    markTyping(itemPath("name"));
    itemTooltip(itemPath("name"), tooltip);
}

static void nameField(std::string* name, bool optional, FieldEdit& e, const char* tooltip) {
    nameField(name, optional, e, tooltip, [](const std::string&) { return false; });
}

// pos, rot, op and blend: what objects and groups share. A member's pos and rot are in its
// group's frame (memberNote says so).
template <class R>
static void posField(R& r, FieldEdit& e) {
    fieldVec3("pos", Field::Position, &r.pos, e);
}

template <class R>
static void turnFields(R& r, FieldEdit& e) {
    const glm::vec3 rot = r.rot;
    fieldVec3("rot", Field::Rotation, &r.rot, e);
    if (r.rot != rot) r.orient.reset();  // typed angles replace the exact turn
    int op = int(r.op);
    fieldCombo("op", &op, kOpNames, kCsgOpCount, e,
               "How it joins what comes before it in its chain (its group's, or the top level's):\n"
               "union, subtract (carve it out) or intersect (keep only the overlap).");
    r.op = CsgOp(op);
    fieldFloat("blend", Field::Blend, &r.blend, e);
}

static void sizeFields(Object& o, FieldEdit& e) {
    const ShapeType t = o.type;
    if (reads(t, kSizeKey)) fieldVec3("size", Field::HalfExtent, &o.size, e);
    if (reads(t, kRadiusKey)) fieldFloat("radius", Field::Radius, &o.radius, e);
    if (reads(t, kMinorKey)) fieldFloat("minor", Field::Minor, &o.minor, e);
    if (reads(t, kHeightKey)) fieldFloat("height", Field::Height, &o.height, e);
    if (reads(t, kTopKey)) fieldFloat("top", Field::Top, &o.top, e);
    if (hasEdges(t)) fieldFloat("round", Field::Round, &o.round, e);
    fieldFloat("shell", Field::Shell, &o.shell, e);
    fitShape(o);  // a cone's top below its radius, rounds and walls within the shape
}

static void shapeFields(const Scene& s, int i, Object& o, FieldEdit& e) {
    int type = int(o.type);
    fieldCombo("type", &type, kShapeNames.data(), kShapeTypeCount, e,
               "The shape; its size fields follow.");
    if (ShapeType(type) != o.type) o = retypedIn(s, i, ShapeType(type));  // resting where it stood
    posField(o, e);
    sizeFields(o, e);
    turnFields(o, e);
}

// Friction and restitution show the world's value until the object is given its own.
static void ownFloat(const char* label, Field f, std::optional<float>* own, float world,
                     FieldEdit& e) {
    float value = own->value_or(world);
    fieldFloat(label, f, &value, e);
    if (value != own->value_or(world)) *own = value;
}

// A top-level object's or group's motion; a member has none (it moves with its group).
template <class R>
static void motionFields(R& r, const char* what, const World& w, FieldEdit& e) {
    bool dynamic = !r.isStatic;
    fieldFlag("dynamic", &dynamic, e,
              "Dynamic (with a mass): falls, tumbles and collides as one rigid body of its\n"
              "shape, a group's as its members make it; static: never moves.");
    r.isStatic = !dynamic;
    fieldFloat("mass", Field::Mass, &r.mass, e);
    ownFloat("friction", Field::Friction, &r.friction, w.friction, e);
    ownFloat("restitution", Field::Restitution, &r.restitution, w.restitution, e);
    fieldVec3("vel", Field::Velocity, &r.vel, e);
    fieldVec3("spin", Field::Spin, &r.spin, e);
    if (!r.dynamic())
        hintLine(std::string("static ") + what + ": tick dynamic, with a mass, to move it");
}

static void memberNote(const Scene& s, int group) {
    hintLine("in group " + s.groups[size_t(group)].name +
             ": moves with it; pos and rot are in its frame");
}

// With more than the active item selected, a field edited goes to each of them.
static void selectionNote(UiContext& c) {
    const size_t n = treeItems(c.editor.selection()).size();
    if (n > 1) hintLine(std::to_string(n) + " selected: a field edited is set on each");
}

// place: the Objects panel or the object popup, whichever shows the fields.
static void objectFields(UiContext& c, int i, Place place) {
    const Scene& s = c.editor.scene();
    const Object before = s.objects[size_t(i)];
    Object o = before;
    FieldEdit e{false, 0, c.ui.messages.at(place)};
    ImGui::PushID(i);
    nameField(&o.name, true, e,
              "The object's name in the list and the file: letters, digits, '_', '.' or '-';\n"
              "empty for none. Return takes it.");
    shapeFields(s, i, o, e);
    materialCombo(s, &o.material, e);
    if (o.group < 0) motionFields(o, "collider", s.world, e);
    else memberNote(s, o.group);
    ImGui::PopID();
    if (e.changed) c.editor.editObjects(before, o, e.key);
}

// A group's mirror planes and copies: the file's `mirror`, `repeat` and `spacing`.
static void copiesFields(Group& g, FieldEdit& e) {
    for (int i = 0; i < 3; ++i) {
        const char* labels[] = {"mirror x", "y##mirror", "z##mirror"};
        bool on = g.mirror[i];
        fieldFlag(labels[i], &on, e,
                  "Keep the half on the positive side of the group's own plane across this axis,\n"
                  "and its reflection on the other side.");
        g.mirror[i] = on;
        if (i < 2) ImGui::SameLine();
    }
    glm::vec3 counts(g.repeat);
    fieldVec3("repeat", Field::Repeat, &counts, e);
    const glm::ivec3 wanted(counts);
    const int copies = wanted.x * wanted.y * wanted.z;
    if (copies <= kMaxRepeatCopies) {
        g.repeat = wanted;
    } else {  // each count in range, their product not: the fields' checks cannot see it
        *e.error = "repeat makes at most " + std::to_string(kMaxRepeatCopies) + " copies: " +
                   std::to_string(copies) + " refused";
        emitEvent("refuse " + *e.error);
        e.changed = false;
    }
    if (g.repeat != glm::ivec3(1)) fieldVec3("spacing", Field::Spacing, &g.spacing, e);
}

static void groupFields(UiContext& c, int g) {
    const Scene& s = c.editor.scene();
    const Group before = s.groups[size_t(g)];
    Group r = before;
    FieldEdit e{false, 0, c.ui.messages.at(Place::Objects)};
    ImGui::PushID(g);
    nameField(&r.name, false, e,
              "The group's name, its own among groups: letters, digits, '_', '.' or '-'.\n"
              "Return takes it.",
              [&](const std::string& name) {
                  for (const Group& other : s.groups)
                      if (other.name == name) return true;
                  return false;
              });
    posField(r, e);
    turnFields(r, e);
    copiesFields(r, e);
    if (r.parent < 0) motionFields(r, "group", s.world, e);
    else memberNote(s, r.parent);
    ImGui::PopID();
    if (e.changed) c.editor.editGroups(before, r, e.key);
}

static void materialFields(UiContext& c, int i) {
    Material m = c.editor.scene().materials[size_t(i)];
    FieldEdit e{false, 0, c.ui.messages.at(Place::Materials)};
    ImGui::PushID(i);
    swatch(m, 48.0f);
    nameField(&m.name, false, e, "Letters, digits, '_', '.' or '-'. Return takes it.");
    fieldColor("colour", Field::ColorChannel, &m.color, e);
    fieldFloat("Ka ambient", Field::Ka, &m.Ka, e);
    fieldFloat("Kd diffuse", Field::Kd, &m.Kd, e);
    fieldFloat("Ks specular", Field::Ks, &m.Ks, e);
    fieldFloat("C shininess", Field::Shininess, &m.C, e);
    fieldFloat("Kr mirror", Field::Reflectivity, &m.Kr, e);
    ImGui::PopID();
    if (e.changed)
        c.editor.edit(
            "Edit material", [&](Scene& s) { s.materials[size_t(i)] = m; }, e.key);
}

static void lightFields(UiContext& c, int i) {
    Light l = c.editor.scene().lights[size_t(i)];
    FieldEdit e{false, 0, c.ui.messages.at(Place::Lights)};
    ImGui::PushID(i);
    int kind = l.directional ? 1 : 0;
    fieldCombo("kind", &kind, kLightKinds, 2, e,
               "A point light shines from a position; a directional one along a direction,\n"
               "like the sun.");
    if (bool directional = kind == 1; directional != l.directional) {
        l.directional = directional;
        if (directional) l.vec = {-0.3f, -1.0f, 0.2f};  // a position makes a poor direction
    }
    if (l.directional) fieldVec3("dir", Field::LightDirection, &l.vec, e);
    else fieldVec3("pos", Field::LightPosition, &l.vec, e);
    fieldColor("colour", Field::LightColor, &l.color, e);
    fieldFloat("intensity", Field::Intensity, &l.intensity, e);
    ImGui::PopID();
    if (e.changed)
        c.editor.edit(
            "Edit light", [&](Scene& s) { s.lights[size_t(i)] = l; }, e.key);
}

static void itemFields(UiContext& c, ItemKind k, int i) {
    switch (k) {
        case ItemKind::Object:
            selectionNote(c);
            return objectFields(c, i, Place::Objects);
        case ItemKind::Group:
            selectionNote(c);
            return groupFields(c, i);
        case ItemKind::Material:
            return materialFields(c, i);
        case ItemKind::Light:
            return lightFields(c, i);
    }
}

//-----------------------------------------------------------------------------
// Lists
//-----------------------------------------------------------------------------
// The active object or group, for the arrows; -1 for none.
static Item activeTreeItem(const Selection& sel) {
    const bool tree = sel.kind == ItemKind::Object || sel.kind == ItemKind::Group;
    return {sel.kind, tree ? sel.index : -1};
}

// Up and down among its siblings: a chain joins its objects and groups in list order.
static void moveButtons(UiContext& c, Item chosen, std::string* why) {
    ImGui::BeginDisabled(chosen.index < 0);
    for (int by : {-1, 1}) {
        const char* name = by < 0 ? "up" : "down";
        ImGui::SameLine();
        if (ImGui::ArrowButton(name, by < 0 ? ImGuiDir_Up : ImGuiDir_Down))
            c.editor.reorder(chosen, by, why);
        markItem(itemPath(name));
        itemTooltip(itemPath(name), std::string("Moves the selected object or group ") + name +
                                        " among its group's:\nthe CSG chain joins them in list "
                                        "order.");
    }
    ImGui::EndDisabled();
}

// Objects: Duplicate and Delete act on the whole selection.
static void objectButtons(UiContext& c) {
    Editor& e = c.editor;
    std::string* why = c.ui.messages.at(Place::Objects);
    if (ImGui::Button("Add")) e.add(ItemKind::Object, why, ShapeType::Sphere, viewWindow(c.ui));
    markItem(itemPath("Add"));
    ImGui::SameLine();
    ImGui::BeginDisabled(treeItems(e.selection()).empty());
    if (ImGui::Button("Duplicate")) e.duplicateSelected(why);
    ImGui::SameLine();
    if (ImGui::Button("Delete")) e.removeSelected(why);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(e.scene().objects.empty() && e.scene().groups.empty());
    if (ImGui::Button("Clear")) e.clear(ItemKind::Object);
    ImGui::EndDisabled();
    moveButtons(c, activeTreeItem(e.selection()), why);  // Group and Ungroup: Edit and Ctrl+G
}

// The material the Materials panel shows and its buttons act on: the selection's where it is a
// material (Add, Duplicate), else the panel's own choice. Choosing one in the list while objects
// are selected makes it the panel's, so the objects stay selected with their fields.
static int shownMaterial(UiContext& c) {
    const Selection& sel = c.editor.selection();
    const int i = sel.kind == ItemKind::Material ? sel.index : c.ui.material;
    return i < int(c.editor.scene().materials.size()) ? i : -1;
}

static void chooseMaterial(UiContext& c, int i) {
    if (c.editor.selection().kind == ItemKind::Material || c.editor.selection().empty()) {
        c.editor.select(ItemKind::Material, i);
        return;
    }
    c.ui.material = i;
    emitEvent("select material " + std::to_string(i) + ", objects kept");
}

static void listButtons(UiContext& c, ItemKind k) {
    if (k == ItemKind::Object) return objectButtons(c);
    Editor& e = c.editor;
    const Selection& sel = e.selection();
    const int chosen = k == ItemKind::Material ? shownMaterial(c) : sel.kind == k ? sel.index : -1;
    std::string* why = c.ui.messages.at(itemPlace(k));
    if (ImGui::Button("Add")) e.add(k, why);
    markItem(itemPath("Add"));
    ImGui::SameLine();
    ImGui::BeginDisabled(chosen < 0);
    if (ImGui::Button("Duplicate")) e.duplicate(k, chosen, why);
    ImGui::SameLine();
    if (ImGui::Button("Delete")) e.remove(k, chosen, why);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(itemCount(e.scene(), k) == 0);
    if (ImGui::Button("Clear")) e.clear(k);
    ImGui::EndDisabled();
}

//-----------------------------------------------------------------------------
// The outliner
//-----------------------------------------------------------------------------
static const char* kRowPayload = "tree row";

// Where a row dropped on `target` goes: onto a sibling it takes that row's place (the ones
// between close up behind it, as Move up and down do); onto a row of another group, just
// before it; onto a group's row, last inside it, but for the row's top quarter, before it.
static TreeSpot dropSpot(const Scene& s, Item dragged, Item target, bool upperQuarter) {
    const TreeSpot at = spotOf(s, target);
    if (target.kind == ItemKind::Group && !upperQuarter) return {target.index, -1};
    const TreeSpot from = spotOf(s, dragged);
    const bool later = from.parent == at.parent && from.at < at.at;
    return {at.parent, at.at + (later ? 1 : 0)};
}

static void dragRow(UiContext& c, Item row, const std::string& name) {
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kRowPayload, &row, sizeof row);
        ImGui::TextUnformatted(name.c_str());
        ImGui::EndDragDropSource();
    }
    if (!ImGui::BeginDragDropTarget()) return;
    if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(kRowPayload)) {
        const Item from = *static_cast<const Item*>(p->Data);
        const float top = ImGui::GetItemRectMin().y, height = ImGui::GetItemRectSize().y;
        const bool upper = ImGui::GetIO().MousePos.y < top + 0.25f * height;
        const TreeSpot spot = dropSpot(c.editor.scene(), from, row, upper);
        if (from != row) c.editor.moveTo(from, spot, c.ui.messages.at(Place::Objects));
    }
    ImGui::EndDragDropTarget();
}

// A click selects the row alone; Shift+click or Ctrl+click adds or removes it.
static void clickRow(UiContext& c, Item row) {
    if (!ImGui::IsItemClicked() || ImGui::IsItemToggledOpen()) return;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.KeyShift || io.KeyCtrl) c.editor.toggle(row);
    else c.editor.select(row.kind, row.index);
}

// A sphere listed before a subtraction vanished inside the carve, and nothing said why: such
// a row is drawn in the warning colour, "(hidden)" after its name, and its tooltip names the
// subtraction. -1 for an object that shows.
static int carvedBy(UiContext& c, int object) {
    if (c.ui.carvedAt != c.editor.document().version()) {
        c.ui.carved = carvedAway(c.editor.scene());
        c.ui.carvedAt = c.editor.document().version();
    }
    return object < int(c.ui.carved.size()) ? c.ui.carved[size_t(object)] : -1;
}

static void carvedTooltip(const Scene& s, const std::string& row, int cut) {
    itemTooltip(row, "Hidden: wholly inside " + itemName(s, ItemKind::Object, cut) +
                         ",\nwhich comes after it and carves it away. Move one of\n"
                         "them, or list the subtraction before it.");
}

// The eye and the lock before an object's row, drawn as small glyphs, faint while off. A click
// toggles them for this session (Editor::setHidden, setLocked).
static bool glyphButton(const char* id, const std::string& mark, const char* tooltip) {
    const float side = ImGui::GetFrameHeight();
    const bool clicked = ImGui::InvisibleButton(id, ImVec2(side, side));
    markItem(mark);
    itemTooltip(mark, tooltip);
    ImGui::SameLine();
    return clicked;
}

static void drawEye(ImVec2 at, float side, bool open) {
    ImDrawList* d = ImGui::GetWindowDrawList();
    const ImU32 ink = ImGui::GetColorU32(open ? ImGuiCol_Text : ImGuiCol_TextDisabled);
    const ImVec2 c(at.x + 0.5f * side, at.y + 0.5f * side);
    const float w = 0.38f * side, h = 0.22f * side;
    d->AddBezierQuadratic({c.x - w, c.y}, {c.x, c.y - 2 * h}, {c.x + w, c.y}, ink, 1.2f);
    d->AddBezierQuadratic({c.x - w, c.y}, {c.x, c.y + 2 * h}, {c.x + w, c.y}, ink, 1.2f);
    if (open) d->AddCircleFilled(c, 0.12f * side, ink);
    else d->AddLine({c.x - w, c.y + h}, {c.x + w, c.y - h}, ink, 1.2f);
}

static void drawLock(ImVec2 at, float side, bool locked) {
    ImDrawList* d = ImGui::GetWindowDrawList();
    const ImU32 ink = ImGui::GetColorU32(locked ? ImGuiCol_Text : ImGuiCol_TextDisabled);
    const float x0 = at.x + 0.28f * side, x1 = at.x + 0.72f * side, y = at.y + 0.48f * side;
    d->AddRectFilled({x0, y}, {x1, at.y + 0.8f * side}, ink, 1.0f);
    const float r = 0.5f * (x1 - x0) - 1.5f, cx = 0.5f * (x0 + x1) + (locked ? 0.0f : r);
    d->PathArcTo({cx, y}, r, 3.1416f, 2.0f * 3.1416f);
    d->PathStroke(ink, 0, 1.5f);
}

static void viewToggles(UiContext& c, int object) {
    const Object& o = c.editor.scene().objects[size_t(object)];
    const float side = ImGui::GetFrameHeight();
    const std::string row = "Objects/" + std::to_string(object);
    ImVec2 at = ImGui::GetCursorScreenPos();
    if (glyphButton("eye", row + " eye",
                    "Shown in the view; a click hides it there, for this session."))
        c.editor.setHidden(object, !o.hidden);
    drawEye(at, side, !o.hidden);
    at = ImGui::GetCursorScreenPos();
    if (glyphButton("lock", row + " lock",
                    "Locked: a click in the view or a box passes it by. A click frees it."))
        c.editor.setLocked(object, !o.locked);
    drawLock(at, side, o.locked);
}

// One row; for a group, whether it is open (its members' rows follow, pushed one level in).
static bool treeRow(UiContext& c, Item row) {
    const Scene& s = c.editor.scene();
    ImGui::PushID(row.kind == ItemKind::Group ? -1 - row.index : row.index);
    const float swatchSide = ImGui::GetFrameHeight();
    if (row.kind == ItemKind::Object) viewToggles(c, row.index);
    else ImGui::Dummy(ImVec2(2.0f * swatchSide + ImGui::GetStyle().ItemSpacing.x, swatchSide));
    if (row.kind != ItemKind::Object) ImGui::SameLine();
    if (row.kind == ItemKind::Object &&
        s.objects[size_t(row.index)].material < int(s.materials.size()))
        swatch(s.materials[size_t(s.objects[size_t(row.index)].material)]);
    else ImGui::Dummy(ImVec2(swatchSide, swatchSide));
    ImGui::SameLine();
    const std::string name = itemName(s, row.kind, row.index);
    const int cut = row.kind == ItemKind::Object ? carvedBy(c, row.index) : -1;
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_SpanAvailWidth;
    if (c.editor.selection().has(row.kind, row.index)) flags |= ImGuiTreeNodeFlags_Selected;
    if (row.kind == ItemKind::Object)
        flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    else flags |= ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen;
    if (cut >= 0) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
    const bool open =
        ImGui::TreeNodeEx("##row", flags, "%s%s", name.c_str(), cut >= 0 ? " (hidden)" : "");
    if (cut >= 0) ImGui::PopStyleColor();
    markItem("Objects/" + name);
    if (cut >= 0) carvedTooltip(s, "Objects/" + name, cut);
    clickRow(c, row);
    dragRow(c, row, name);
    ImGui::PopID();
    return row.kind == ItemKind::Group && open;
}

// Below the rows: a row dropped there goes to the top level, last.
static void topLevelDrop(UiContext& c) {
    const float room = std::max(ImGui::GetContentRegionAvail().y, ImGui::GetFrameHeight());
    ImGui::InvisibleButton("##top level",
                           ImVec2(std::max(ImGui::GetContentRegionAvail().x, 1.0f), room));
    markItem("Objects/top level");
    if (!ImGui::BeginDragDropTarget()) return;
    if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(kRowPayload))
        c.editor.moveTo(*static_cast<const Item*>(p->Data), {-1, -1},
                        c.ui.messages.at(Place::Objects));
    ImGui::EndDragDropTarget();
}

// The list's height: 150 px, or for more rows (and one row's room to drop on) up to a third of
// a tall window's height; a small window keeps its room for the fields.
static float outlinerHeight(size_t rows) {
    const float row = ImGui::GetFrameHeightWithSpacing();
    const float wanted = float(rows + 1) * row + 2.0f * ImGui::GetStyle().WindowPadding.y;
    const float most = std::max(150.0f, ImGui::GetIO().DisplaySize.y / 3.0f);
    return std::clamp(wanted, 150.0f, most);
}

// Every object and group in tree order; a closed group's members are left out.
static void outliner(UiContext& c) {
    const std::vector<TreeRow> rows = treeRows(c.editor.scene());
    ImGui::BeginChild("list", ImVec2(0, outlinerHeight(rows.size())), true);
    int shown = 0, pushed = 0;  // rows deeper than `shown` are inside a closed group
    for (const TreeRow& row : rows) {
        if (row.depth > shown) continue;
        for (; pushed > row.depth; --pushed) ImGui::TreePop();
        shown = row.depth;
        if (treeRow(c, row.item)) shown = ++pushed;
    }
    for (; pushed > 0; --pushed) ImGui::TreePop();
    topLevelDrop(c);
    ImGui::EndChild();
}

static void itemList(UiContext& c, ItemKind k, const char* title) {
    if (k == ItemKind::Object) return outliner(c);
    const Scene& s = c.editor.scene();
    ImGui::BeginChild("list", ImVec2(0, 150), true);
    for (int i = 0; i < itemCount(s, k); ++i) {
        ImGui::PushID(i);
        if (k == ItemKind::Material) {
            swatch(s.materials[size_t(i)]);
            ImGui::SameLine();
        }
        const std::string name = itemName(s, k, i);
        const bool material = k == ItemKind::Material;
        const bool chosen = material ? shownMaterial(c) == i : c.editor.selection().is(k, i);
        if (ImGui::Selectable(name.c_str(), chosen))
            material ? chooseMaterial(c, i) : c.editor.select(k, i);
        markItem(std::string(title) + "/" + name);
        ImGui::PopID();
    }
    ImGui::EndChild();
}

// The Objects panel shows the active object's or group's fields.
static bool shows(ItemKind panel, ItemKind active) {
    return panel == active || (panel == ItemKind::Object && active == ItemKind::Group);
}

static void itemWindow(UiContext& c, ItemKind k, Panel p, const char* title, bool* open) {
    if (!*open) return;
    if (beginPanel(c, p, title, open)) {
        listButtons(c, k);
        itemList(c, k, title);
        const Selection& sel = c.editor.selection();
        if (k == ItemKind::Material && shownMaterial(c) >= 0)
            itemFields(c, k, shownMaterial(c));
        else if (shows(k, sel.kind) && sel.index >= 0) itemFields(c, sel.kind, sel.index);
        messageLine(c, itemPlace(k));
    }
    ImGui::End();
}

static void objectPopup(UiContext& c) {
    if (c.ui.wantObjectPopup) ImGui::OpenPopup(kObjectPopup);
    c.ui.wantObjectPopup = false;
    bool open = ImGui::BeginPopup(kObjectPopup);
    markPopup(kObjectPopup, open);
    if (!open) return;
    const int i = c.editor.selection().object();
    if (i < 0) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::Text("object %d", i);
    objectFields(c, i, Place::ObjectPopup);
    std::string* why = c.ui.messages.at(Place::ObjectPopup);
    if (ImGui::Button("Duplicate")) c.editor.duplicate(ItemKind::Object, i, why);
    ImGui::SameLine();
    if (ImGui::Button("Delete")) c.editor.remove(ItemKind::Object, i, why);
    messageLine(c, Place::ObjectPopup);
    ImGui::EndPopup();
}

void drawEditWindows(UiContext& c) {
    itemWindow(c, ItemKind::Object, Panel::Objects, "Objects", &c.ui.showObjects);
    itemWindow(c, ItemKind::Material, Panel::Materials, "Materials", &c.ui.showMaterials);
    itemWindow(c, ItemKind::Light, Panel::Lights, "Lights", &c.ui.showLights);
    objectPopup(c);
}

}  // namespace mb
