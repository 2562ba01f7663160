// editor_window.cpp — the App: owns the window, the editor state, the scene view and the UI
// state, and runs the frame loop (Initialization / Update / Draw / De-Initialization).
#include "editor_window.h"

#include "args.h"
#include "imgui_input.h"
#include "marchbox/editor/events.h"
#include "marchbox/editor/files.h"
#include "marchbox/editor/picking.h"
#include "marchbox/gl/gl.h"
#include "animation_dialog.h"
#include "export_dialog.h"
#include "render_dialog.h"
#include "scene_view.h"
#include "ui.h"
#include "viewport_input.h"
#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace mb {

namespace {

const char* envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v && *v ? v : fallback;
}

constexpr double kIdleWaitSeconds = 1.0 / 30.0;

// Milliseconds `draw` took, or 0 when it drew nothing (returned false).
template <typename Draw>
double timed(Draw draw) {
    double start = glfwGetTime();
    return draw() ? (glfwGetTime() - start) * 1000.0 : 0.0;
}

class App {
public:
    ~App();
    void load(const Scene& scene, const std::string& file);
    bool start(std::string* error);
    void run();

private:
    bool idle() const;  // nothing to draw and nothing moving: the loop may sleep
    void frame(double seconds, int width, int height);
    void buildUi(UiContext& c, int width, int height, double seconds);
    void present(int width, int height);
    void openDrops(UiContext& c);
    void screenshot(int width, int height);
    std::string title() const;
    void syncView(double now);
    void showScene(uint64_t version);  // shown_ for the document at `version`

    // Destroyed bottom-up: the scene view's GL objects go while the window's context lives.
    Window window_;
    SceneView view_;
    // The scene the view draws where it is not the editor's own (syncView()), as of a version.
    Scene shown_;
    bool ownScene_ = false;
    uint64_t shownVersion_ = ~uint64_t(0);
    Renumbering shownObjects_;  // the editor's objects to the view's, while some are hidden
    Editor editor_;
    UiState ui_;
    RenderDialog renderDialog_;
    AnimationDialog animationDialog_;
    ExportDialog exportDialog_;
    FrameStats stats_;
    InputState input_;  // this frame's, taken from the window's queue
    ViewportInput viewport_;
    double frameStart_ = 0.0;  // glfwGetTime() as this frame began
    bool imgui_ = false;
};

App::~App() {
    if (!imgui_) return;
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

//-----------------------------------------------------------------------------
// Initialization
//-----------------------------------------------------------------------------
void App::load(const Scene& scene, const std::string& file) {
    ui_.scenesDir = std::string(MARCHBOX_SOURCE_DIR) + "/scenes";
    editor_.start(scene, file);
}

bool App::start(std::string* error) {
    int w = 1280, h = 720;
    // MARCHBOX_WINDOW_SIZE=WxH: tests ask for a small window so a software renderer keeps up.
    std::sscanf(envOr("MARCHBOX_WINDOW_SIZE", "1280x720"), "%dx%d", &w, &h);
    if (!window_.create(title(), std::max(w, 64), std::max(h, 64), error)) return false;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    imgui_ = true;
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
    // As in Blender: a click on a number field types into it; a drag still changes it.
    ImGui::GetIO().ConfigDragClickToInputText = true;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_.handle(), false);  // the window queues the input
    ImGui_ImplOpenGL3_Init("#version 330");
    return view_.init(editor_.scene(), error);
}

//-----------------------------------------------------------------------------
// Update
//-----------------------------------------------------------------------------
void App::run() {
    double last = glfwGetTime();
    bool ready = false;
    while (!editor_.quitRequested()) {
        // With the picture finished, nothing moving and no input waiting for its frame, sleep
        // until input comes; the timeout still looks at shaders/, background compiles and
        // ImGui's own timers a few times a second.
        if (idle() && window_.input().empty()) glfwWaitEventsTimeout(kIdleWaitSeconds);
        else glfwPollEvents();
        if (window_.closeRequested()) {
            window_.clearCloseRequest();
            std::vector<std::string> none;
            editor_.request(Leave::Exit, "", &none);
        }
        int w = 0, h = 0;
        window_.framebufferSize(&w, &h);
        double now = glfwGetTime(), seconds = now - last;
        last = now;
        if (w <= 0 || h <= 0) {  // minimised: nothing to draw into, so wait for the window
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        frame(seconds, w, h);
        if (!ready) emitEvent("ready " + std::to_string(w) + " " + std::to_string(h));
        ready = true;
    }
}

bool App::idle() const {
    return view_.done() && !renderDialog_.running() && !animationDialog_.running() &&
           !exportDialog_.running() &&
           !editor_.simulation().playing() && !ui_.previewOrbit && !viewport_.dragging();
}

void App::frame(double seconds, int width, int height) {
    frameStart_ = glfwGetTime();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    window_.input().takeFrame(&input_, frameStart_, ImGui::GetIO().WantTextInput);
    feedImGui(input_, seconds);
    ImGui::NewFrame();
    UiContext c{editor_, ui_, stats_, view_};
    buildUi(c, width, height, seconds);
    editor_.frame(seconds);
    ImGui::Render();
    present(width, height);
    window_.setTitle(title());
    stats_.add(seconds);
    stats_.scene = view_.status();
}

void App::buildUi(UiContext& c, int width, int height, double seconds) {
    handleShortcuts(c, input_.presses);
    openDrops(c);
    watchSceneFile(c);
    viewport_.update(c, glm::vec2(width, height), float(seconds));
    viewport_.drawSelection(c);
    drawGizmo(c, viewport_.hotHandle(c), glm::vec2(width, height));
    drawMenuBar(c);
    drawEditWindows(c);
    drawSimulationWindow(c);
    drawTimelineBar(c);
    drawViewWindows(c);
    drawDialogs(c);
    renderDialog_.draw(c);
    animationDialog_.draw(c);
    exportDialog_.draw(c);
    // A released widget or drag ends its undo step; the next change starts a new one.
    if (!ImGui::IsAnyItemActive() && !viewport_.dragging()) editor_.endEdit();
    ui_.messages.endFrame(editor_.selection(), ImGui::GetTime());
}

void App::openDrops(UiContext& c) {
    for (const std::string& path : window_.takeDrops()) {
        if (!hasSceneExtension(path)) continue;
        openFile(c, path);  // the first scene file; the rest would only replace it
        break;
    }
}

//-----------------------------------------------------------------------------
// Draw
//-----------------------------------------------------------------------------
// While playing along the keyframes the view shows the path's camera, not the record. The
// version tells the two apart too, so pausing (which changes no scene) draws the record again.
// Objects hidden with the Objects list's eye are left out of the view. The scene shown is made
// again only when the version changes, not every frame.
void App::syncView(double now) {
    const uint64_t version = editor_.document().version() * 2 + (editor_.followsPath() ? 1 : 0);
    if (version != shownVersion_) showScene(version);
    view_.sync(ownScene_ ? shown_ : editor_.scene(), version, ui_.render, ui_.quality, now);
}

void App::showScene(uint64_t version) {
    const Scene& scene = editor_.scene();
    const bool anyHidden = std::any_of(scene.objects.begin(), scene.objects.end(),
                                       [](const Object& o) { return o.hidden; });
    shownVersion_ = version;
    shownObjects_ = {};
    ownScene_ = editor_.followsPath() || anyHidden;
    if (!ownScene_) {
        shown_ = Scene{};
        return;
    }
    shown_ = anyHidden ? visibleScene(scene, &shownObjects_) : scene;
    shown_.camera = editor_.shownCamera();
}

void App::present(int width, int height) {
    double now = glfwGetTime();
    view_.pollShaders(editor_.scene(), now);
    syncView(now);
    renderDialog_.work(0.03);  // a few tiles a frame keep the window responsive
    animationDialog_.work(0.03);
    // A changed scene draws its preview first, so this frame shows the change; bands of
    // refinement wait until after the swap, so the UI never waits for them.
    int selected = editor_.selection().object();  // as the view numbers it
    if (selected >= 0 && selected < int(shownObjects_.objects.size()))
        selected = shownObjects_.objects[size_t(selected)];
    double sceneMs =
        timed([&] { return view_.update(width, height, selected, StepKind::Preview); });
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    view_.show(width, height);  // the last picture of the scene, however far it has got
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (ui_.wantScreenshot) screenshot(width, height);
    window_.swap();
    if (sceneMs == 0.0)
        sceneMs = timed([&] { return view_.update(width, height, selected, StepKind::Band); });
    view_.otherWork((glfwGetTime() - frameStart_) * 1000.0 - sceneMs);
}

void App::screenshot(int width, int height) {
    ui_.wantScreenshot = false;
    std::string path, error;
    if (saveScreenshot(width, height, envOr("MARCHBOX_SCREENSHOT_DIR", "."), &path, &error))
        emitEvent("screenshot " + path);
    else ui_.messages.say(Place::Status, error);
}

std::string App::title() const {
    const Document& d = editor_.document();
    std::string notes = d.time() > 0 ? timeLabel(d.time()) : "";
    if (d.runEdits()) notes += (notes.empty() ? "" : ", ") + std::string("edits not in the start");
    return "Marchbox - " + d.name() + (d.dirty() ? " *" : "") +
           (notes.empty() ? "" : " (" + notes + ")");
}

}  // namespace

//-----------------------------------------------------------------------------
// De-Initialization happens in ~App, in reverse order of the members.
//-----------------------------------------------------------------------------
int runEditorWindow(const Scene& scene, const std::string& file) {
    if (std::string(envOr("MARCHBOX_EVENT_LOG", "0")) != "0") setEventStream(&std::cout);
    App app;
    app.load(scene, file);
    std::string error;
    if (!app.start(&error)) {
        std::cerr << "marchbox: cannot open the editor window: " << error << '\n';
        return kNoWindow;
    }
    app.run();
    emitEvent("exit 0");
    return kExitOk;
}

}  // namespace mb
