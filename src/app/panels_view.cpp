// panels_view.cpp — View: camera and render settings, debug views; Help; the statistics
// overlay; the shader log.
#include "ui.h"
#include "widgets.h"

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/controls.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <imgui.h>
#include <imgui_internal.h>  // the overlay's size as last drawn

namespace mb {

void FrameStats::add(double seconds) {
    frameMs[next] = float(seconds * 1000.0);
    next = (next + 1) % kHistory;
    count = std::min(count + 1, kHistory);
    // Frames per second over the last half of the plot: steadier than one frame's reciprocal.
    const int n = std::min(count, kHistory / 2);
    float total = 0.0f;
    for (int i = 1; i <= n; ++i) total += frameMs[(next - i + kHistory) % kHistory];
    meanMs = n > 0 ? total / float(n) : 0.0f;
    fps = total > 0.0f ? 1000.0f * float(n) / total : 0.0f;
}

static const char* const kShadowNames[] = {"none", "hard", "soft"};

static void cameraFields(UiContext& c) {
    Camera cam = c.editor.scene().camera;
    FieldEdit e{false, 0, c.ui.messages.at(Place::View)};
    fieldVec3("position", Field::CameraPosition, &cam.pos, e);
    fieldVec3("target", Field::CameraTarget, &cam.target, e);
    fieldFloat("fov", Field::Fov, &cam.fov, e);
    if (e.changed)
        c.editor.edit(
            "Edit camera", [&](Scene& s) { s.camera = cam; }, e.key);
    ImGui::Checkbox("orbit preview (1)", &c.ui.previewOrbit);
    itemTooltip(itemPath("orbit preview (1)"), "A slow turn about the target. Not saved.");
}

static void renderFields(UiContext& c) {
    RenderSettings r = c.editor.scene().render;
    FieldEdit e{false, 0, c.ui.messages.at(Place::View)};
    fieldInt("steps", Field::Steps, &r.steps, e);
    fieldFloat("epsilon", Field::Epsilon, &r.epsilon, e);
    fieldCombo("shadows", &r.shadows, kShadowNames, 3, e, "None, hard, or soft (softness below).");
    fieldInt("reflections", Field::Reflections, &r.reflections, e);
    fieldFloat("fog", Field::Fog, &r.fog, e);
    fieldFlag("ambient occlusion", &r.ao, e, "Darkens creases and contact points.");
    fieldInt("anti-aliasing", Field::Aa, &r.aa, e);
    if (e.changed)
        c.editor.edit(
            "Edit render settings", [&](Scene& s) { s.render = r; }, e.key);
}

static void debugView(UiContext& c) {
    UiState& ui = c.ui;
    const char* names[kRenderModeCount];
    for (int m = 0; m < kRenderModeCount; ++m) names[m] = renderModeName(RenderMode(m));
    int mode = int(ui.render.mode);
    if (ImGui::Combo("debug view", &mode, names, kRenderModeCount))
        ui.render.mode = RenderMode(mode);
    itemTooltip(itemPath("debug view"),
                "What the view shows: the shaded picture or one of its parts.\nNot saved.");
    ImGui::Checkbox("uber shader", &ui.render.uber);
    itemTooltip(
        itemPath("uber shader"),
        "Draw with the general shader instead of the one compiled\nfor this scene. Not saved.");
    // A scene without fog has none to show: unticked and disabled, not a box that does nothing.
    const bool sceneFog = c.editor.scene().render.fog > 0.0f;
    bool shown = sceneFog && ui.render.fog;
    ImGui::BeginDisabled(!sceneFog);
    if (ImGui::Checkbox("fog (F)", &shown)) ui.render.fog = shown;
    ImGui::EndDisabled();
    itemTooltip(itemPath("fog (F)"), sceneFog
                                         ? "Shows the scene's fog (render fog above). Not saved."
                                         : "This scene has no fog: set fog above 0 to see it.");
    postModeCombo(ui);
    itemTooltip(itemPath("post pass"), "FXAA smooths edges after the march. Not saved.");
    ImGui::SliderFloat("shadow softness", &ui.render.quality.softness, 2.0f, 64.0f, "k = %.1f",
                       ImGuiSliderFlags_Logarithmic);
    markItem(itemPath("shadow softness"));
    itemTooltip(itemPath("shadow softness"),
                "k of the soft-shadow estimate, 2 to 64: lower is softer.\nNot saved.");
}

void postModeCombo(UiState& ui) {
    const char* names[kPostModeCount] = {"none", "FXAA (P)", "FXAA edge mask", "FXAA direction"};
    int post = int(ui.render.post);
    if (ImGui::Combo("post pass", &post, names, kPostModeCount)) ui.render.post = PostMode(post);
}

// What the program drawing the view was built for (describeFeatures): the scene compiler's
// choices, so a user sees why an edit compiles anew and what the scene costs.
static void shaderFeatures(UiContext& c) {
    const ShaderFeatures* f = c.view.features();
    if (!f) return;
    ImGui::Separator();
    ImGui::TextDisabled("Shader%s", c.view.compiling() ? " (the scene's own is compiling)" : "");
    for (const std::string& line : describeFeatures(*f)) {
        ImGui::BulletText("%s", line.c_str());
        markItem("View/shader " + line);
    }
}

static void viewWindow(UiContext& c) {
    if (!c.ui.showView) return;
    if (beginPanel(c, Panel::View, "View", &c.ui.showView)) {
        ImGui::TextDisabled("Camera");
        cameraFields(c);
        ImGui::Separator();
        ImGui::TextDisabled("Render (saved with the scene)");
        renderFields(c);
        ImGui::Separator();
        debugView(c);
        messageLine(c, Place::View);
        shaderFeatures(c);
    }
    ImGui::End();
}

// Help > Controls: editorControls(), the table docs/editor.md lists too.
static void helpWindow(UiContext& c) {
    if (!c.ui.showHelp) return;
    if (beginPanel(c, Panel::Controls, "Controls", &c.ui.showHelp) &&
        ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg)) {
        // The keys column as wide as its widest entry ("Ctrl+C, Ctrl+V"): keys cut short read
        // as other keys. The actions wrap beside it, in two lines at most (Controls.*).
        float keys = 0.0f;
        for (const Control& k : editorControls())
            keys = std::max(keys, ImGui::CalcTextSize(k.keys).x);
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, keys);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        for (const Control& k : editorControls()) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k.keys);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", k.action);
        }
        ImGui::EndTable();
        markItem("Controls/table");
    }
    ImGui::End();
}

// Inside a solid the picture is black, or the inside of a shell: say so, and the way out.
static void eyeNote(UiContext& c) {
    const int around = solidAroundEye(c.editor.scene(), c.editor.shownCamera().pos);
    if (around == kHitNone) return;
    const std::string where =
        around == kHitGround ? "below the ground" : "inside object " + std::to_string(around);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "the camera is %s: wheel out, or Home",
                       where.c_str());
    markItem("Statistics/camera inside");
}

static void statsOverlay(UiContext& c) {
    c.ui.statsBottom = 0.0f;  // the right column may go up to the menu bar
    ImGuiIO& io = ImGui::GetIO();
    // As large as it was last drawn; where it would cover a panel, it gives way.
    const ImGuiWindow* last = ImGui::FindWindowByName("##stats");
    const ImVec2 size = last ? last->Size : ImVec2(0, 0);
    const PanelFrame frame = panelFrame(c.ui);  // rightTop 0, just set
    const PanelRect place{io.DisplaySize.x - 10 - size.x, 30, size.x, size.y};
    if (!c.ui.showStats || !statisticsFit(frame, c.ui.openPanels(), place)) {
        markPanelHidden("##stats");
        return;
    }
    const FrameStats& s = c.stats;
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 10, 30), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("##stats", nullptr, flags)) {
        markPanel();
        float worst = *std::max_element(s.frameMs, s.frameMs + FrameStats::kHistory);
        // The window's rate and the scene's cost apart: one figure each, never mixed. Short
        // lines and a low plot keep the overlay in the corner, clear of the view.
        ImGui::Text("UI %.0f fps, %.0f ms/frame", s.fps, s.meanMs);
        if (s.scene.done)
            ImGui::Text("scene %s in %.1f s", s.scene.state.c_str(), s.scene.refinedMs / 1000.0);
        else ImGui::Text("scene %s", s.scene.state.c_str());
        if (s.scene.passMs > 0.0)
            ImGui::Text("%.0f ms/step, full %.1f s", s.scene.stepMs, s.scene.passMs / 1000.0);
        else ImGui::Text("%.0f ms/step", s.scene.stepMs);
        ImGui::PlotLines("##frames", s.frameMs, FrameStats::kHistory, s.next, "UI frame ms", 0.0f,
                         std::max(worst, 1.0f), ImVec2(200, 24));
        const double simulated = c.editor.document().time();
        ImGui::Text("%zu objects   simulated %.2f s%s", c.editor.scene().objects.size(), simulated,
                    c.editor.simulation().playing() ? ", playing" : "");
        markItem("Statistics/simulated");
        eyeNote(c);
        // The scene's own program on its way: meanwhile the uber stand-in or the last program
        // draws. The row is always there: a row that came and went would grow the auto-sized
        // overlay a frame late, and a compile shorter than a frame would never show.
        if (c.view.compiling()) {
            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "compiling the scene's shader...");
            markItem("Statistics/compiling");
        } else {
            ImGui::TextDisabled("shader up to date");
            markItem("Statistics/shader up to date");
        }
        c.ui.statsBottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
    }
    ImGui::End();
}

static void shaderLogWindow(const std::string& log) {
    if (log.empty()) return;
    // Along the bottom, so the scene the last good program draws stays in view above it.
    ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10, display.y - 10), ImGuiCond_FirstUseEver, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(std::min(620.0f, display.x - 20), 150), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Shader error")) {
        ImGui::TextUnformatted(
            "The last program that compiled keeps drawing. Fix the file in "
            "shaders/ and it reloads.");
        ImGui::Separator();
        ImGui::BeginChild("log");
        ImGui::TextUnformatted(log.c_str());
        ImGui::EndChild();
        markItem("Shader error/log");
    }
    ImGui::End();
}

// Failures no panel owns, along the bottom until Messages lets them go.
static void statusLine(UiContext& c) {
    const std::string& text = c.ui.messages.text(Place::Status);
    if (text.empty()) return;
    ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 10), ImGuiCond_Always,
                            ImVec2(0.5f, 1));
    // As wide as the text up to the window's width, wrapping past it; as tall as that makes it.
    const float pad = 2.0f * ImGui::GetStyle().WindowPadding.x;
    const float width = std::min(ImGui::CalcTextSize(text.c_str()).x + pad, display.x - 20.0f);
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("##status", nullptr, flags)) messageLine(c, Place::Status);
    ImGui::End();
}

void drawViewWindows(UiContext& c) {
    viewWindow(c);
    helpWindow(c);
    statsOverlay(c);
    shaderLogWindow(c.view.shaderLog());
    statusLine(c);
}

}  // namespace mb
