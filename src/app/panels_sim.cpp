// panels_sim.cpp — Simulation: Step, Reset, Keep poses, and the world the bodies fall in.
#include "ui.h"
#include "widgets.h"

#include <imgui.h>

namespace mb {

// Play, Loop and the timeline are under the view (timeline_strip.cpp).
static void controls(UiContext& c) {
    Editor& e = c.editor;
    if (ImGui::Button("Step")) e.step();
    ImGui::SameLine();
    ImGui::BeginDisabled(e.document().time() <= 0);
    if (ImGui::Button("Reset")) e.resetSimulation();
    ImGui::SameLine();
    if (ImGui::Button("Keep poses")) e.keepPoses();
    ImGui::EndDisabled();
}

static void worldFields(UiContext& c) {
    World w = c.editor.scene().world;
    FieldEdit e{false, 0, c.ui.messages.at(Place::Simulation)};
    fieldFloat("gravity", Field::Gravity, &w.gravity, e);
    fieldFloat("restitution", Field::Restitution, &w.restitution, e);
    fieldFloat("friction", Field::Friction, &w.friction, e);
    fieldFloat("rolling", Field::Rolling, &w.rolling, e);
    fieldFloat("floor", Field::Floor, &w.floor, e);
    fieldFlag("ground", &w.ground, e,
              "The checkered ground plane at the floor height; off removes it.");
    if (e.changed)
        c.editor.edit(
            "Edit world", [&](Scene& s) { s.world = w; }, e.key);
}

static void statistics(const Simulation& sim) {
    const PhysicsWorld* w = sim.world();
    if (!w) {
        ImGui::TextDisabled("not started");
        return;
    }
    ImGui::Text("steps %lld   bodies %d   awake %d", w->stepCount(), w->bodyCount(),
                w->stats().awake);
    ImGui::Text("contacts %d   deepest overlap %.4f m", w->stats().contacts,
                w->stats().maxPenetration);
    ImGui::Text("energy %.3f J", w->kineticEnergy() + w->potentialEnergy());
}

void drawSimulationWindow(UiContext& c) {
    if (!c.ui.showSimulation) return;
    if (beginPanel(c, Panel::Simulation, "Simulation", &c.ui.showSimulation)) {
        controls(c);
        ImGui::Separator();
        worldFields(c);
        messageLine(c, Place::Simulation);
        ImGui::Separator();
        statistics(c.editor.simulation());
    }
    ImGui::End();
}

}  // namespace mb
