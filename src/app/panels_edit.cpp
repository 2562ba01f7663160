// panels_edit.cpp — Edit > Objects, Materials, Lights: lists with add, duplicate, delete and
// clear, the selected item's every field, and the viewport's right-click popup.
//
// Fields edit a copy of the item; a changed copy goes back through Editor::edit as one undo
// step, keyed by the widget so that one drag is one step.
#include "ui.h"
#include "widgets.h"

#include "marchbox/editor/events.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

static const char* const kShapeNames[kShapeTypeCount] = {
    "sphere", "box", "torus", "capsule", "cylinder", "cone", "ellipsoid"};
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

static std::string itemName(const Scene& s, ItemKind k, int i) {
    std::string n = std::to_string(i) + " ";
    switch (k) {
        case ItemKind::Object: {  // "3 lid: box, subtract, static"
            const Object& o = s.objects[size_t(i)];
            if (!o.name.empty()) n += o.name + ": ";
            return n + shapeTypeName(o.type) + ", " + csgOpName(o.op) +
                   (o.dynamic() ? ", dynamic" : ", static");
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

// A name, taken on Return when validateName() allows it; `optional`: an empty one clears it.
static void nameField(std::string* name, bool optional, FieldEdit& e, const char* tooltip) {
    std::string typed = *name, why;
    if (ImGui::InputText("name", &typed, ImGuiInputTextFlags_EnterReturnsTrue)) {
        if ((optional && typed.empty()) || validateName(typed, &why)) {
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

static void shapeFields(Object& o, FieldEdit& e) {
    int type = int(o.type);
    fieldCombo("type", &type, kShapeNames, kShapeTypeCount, e,
               "The shape; its size fields follow.");
    if (ShapeType(type) != o.type) o = retyped(o, ShapeType(type));  // resting where it stood
    fieldVec3("pos", Field::Position, &o.pos, e);
    if (o.type == ShapeType::Box) fieldVec3("size", Field::HalfExtent, &o.size, e);
    else fieldFloat("radius", Field::Radius, &o.radius, e);
    if (o.type == ShapeType::Torus) fieldFloat("minor", Field::Minor, &o.minor, e);
    if (o.type == ShapeType::Capsule || o.type == ShapeType::Cylinder)
        fieldFloat("height", Field::Height, &o.height, e);
    const glm::vec3 rot = o.rot;
    fieldVec3("rot", Field::Rotation, &o.rot, e);
    if (o.rot != rot) o.orient.reset();  // typed angles replace the exact turn
    int op = int(o.op);
    fieldCombo("op", &op, kOpNames, kCsgOpCount, e,
               "How it joins the objects before it in the list: union, subtract (carve it out)\n"
               "or intersect (keep only the overlap).");
    o.op = CsgOp(op);
    fieldFloat("blend", Field::Blend, &o.blend, e);
}

// Friction and restitution show the world's value until the object is given its own.
static void ownFloat(const char* label, Field f, std::optional<float>* own, float world,
                     FieldEdit& e) {
    float value = own->value_or(world);
    fieldFloat(label, f, &value, e);
    if (value != own->value_or(world)) *own = value;
}

static void motionFields(Object& o, const World& w, FieldEdit& e) {
    bool dynamic = !o.isStatic;
    fieldFlag("dynamic", &dynamic, e,
              "A dynamic object (with a mass) falls, tumbles and collides as a rigid body of its\n"
              "shape; a static one never moves.");
    o.isStatic = !dynamic;
    fieldFloat("mass", Field::Mass, &o.mass, e);
    ownFloat("friction", Field::Friction, &o.friction, w.friction, e);
    ownFloat("restitution", Field::Restitution, &o.restitution, w.restitution, e);
    fieldVec3("vel", Field::Velocity, &o.vel, e);
    fieldVec3("spin", Field::Spin, &o.spin, e);
    if (!o.dynamic()) ImGui::TextDisabled("static collider: tick dynamic, with a mass, to move it");
}

// place: the Objects panel or the object popup, whichever shows the fields.
static void objectFields(UiContext& c, int i, Place place) {
    const Scene& s = c.editor.scene();
    Object o = s.objects[size_t(i)];
    FieldEdit e{false, 0, c.ui.messages.at(place)};
    ImGui::PushID(i);
    nameField(&o.name, true, e,
              "The object's name in the list and the file: letters, digits, '_', '.' or '-';\n"
              "empty for none. Return takes it.");
    shapeFields(o, e);
    materialCombo(s, &o.material, e);
    motionFields(o, s.world, e);
    ImGui::PopID();
    if (e.changed)
        c.editor.edit(
            "Edit object", [&](Scene& sc) { sc.objects[size_t(i)] = o; }, e.key);
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
            return objectFields(c, i, Place::Objects);
        case ItemKind::Material:
            return materialFields(c, i);
        case ItemKind::Light:
            return lightFields(c, i);
    }
}

//-----------------------------------------------------------------------------
// Lists
//-----------------------------------------------------------------------------
// Up and down the list: the CSG chain joins objects in list order.
static void moveButtons(UiContext& c, int chosen, std::string* why) {
    ImGui::BeginDisabled(chosen < 0);
    for (int by : {-1, 1}) {
        const char* name = by < 0 ? "up" : "down";
        ImGui::SameLine();
        if (ImGui::ArrowButton(name, by < 0 ? ImGuiDir_Up : ImGuiDir_Down))
            c.editor.reorder(chosen, by, why);
        markItem(itemPath(name));
        itemTooltip(itemPath(name), std::string("Moves the selected object ") + name +
                                        " the list: the CSG chain joins objects in list order.");
    }
    ImGui::EndDisabled();
}

static void listButtons(UiContext& c, ItemKind k) {
    Editor& e = c.editor;
    const Selection& sel = e.selection();
    const int chosen = sel.kind == k ? sel.index : -1;
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
    if (k == ItemKind::Object) moveButtons(c, chosen, why);
}

// A row of the Objects list dragged onto another moves there, one undo step, as Move up and
// Move down do one place at a time.
static void dragToReorder(UiContext& c, int row, const std::string& name) {
    static const char* kPayload = "object row";
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kPayload, &row, sizeof row);
        ImGui::TextUnformatted(name.c_str());
        ImGui::EndDragDropSource();
    }
    if (!ImGui::BeginDragDropTarget()) return;
    if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(kPayload)) {
        const int from = *static_cast<const int*>(p->Data);
        if (from != row) c.editor.reorder(from, row - from, c.ui.messages.at(Place::Objects));
    }
    ImGui::EndDragDropTarget();
}

static void itemList(UiContext& c, ItemKind k, const char* title) {
    const Scene& s = c.editor.scene();
    ImGui::BeginChild("list", ImVec2(0, 150), true);
    for (int i = 0; i < itemCount(s, k); ++i) {
        ImGui::PushID(i);
        int m = k == ItemKind::Material ? i
                : k == ItemKind::Object ? s.objects[size_t(i)].material
                                        : -1;
        if (m >= 0 && m < int(s.materials.size())) {
            swatch(s.materials[size_t(m)]);
            ImGui::SameLine();
        }
        const std::string name = itemName(s, k, i);
        if (ImGui::Selectable(name.c_str(), c.editor.selection().is(k, i))) c.editor.select(k, i);
        markItem(std::string(title) + "/" + name);
        if (k == ItemKind::Object) dragToReorder(c, i, name);
        ImGui::PopID();
    }
    ImGui::EndChild();
}

static void itemWindow(UiContext& c, ItemKind k, Panel p, const char* title, bool* open) {
    if (!*open) return;
    if (beginPanel(c, p, title, open)) {
        listButtons(c, k);
        itemList(c, k, title);
        const Selection& sel = c.editor.selection();
        if (sel.kind == k && !sel.empty()) itemFields(c, k, sel.index);
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
