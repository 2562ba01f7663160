// export_dialog.cpp — meshing off the UI thread, told and stopped through export.h's callbacks.
#include "export_dialog.h"

#include "marchbox/editor/events.h"
#include "marchbox/editor/files.h"
#include "widgets.h"

#include <cstdio>
#include <filesystem>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

ExportDialog::~ExportDialog() {
    stop_ = true;
    if (worker_.joinable()) worker_.join();
}

// Bytes and counts as a person reads them: 1.2 M, 340 k.
static std::string roughly(double v) {
    char text[32];
    if (v >= 1e9) std::snprintf(text, sizeof text, "%.1f G", v / 1e9);
    else if (v >= 1e6) std::snprintf(text, sizeof text, "%.1f M", v / 1e6);
    else if (v >= 1e3) std::snprintf(text, sizeof text, "%.0f k", v / 1e3);
    else std::snprintf(text, sizeof text, "%.0f", v);
    return text;
}

void ExportDialog::estimate(const Scene& scene) {
    const ExportEstimate e = estimateExport(scene, voxel_);
    char text[96];
    std::snprintf(text, sizeof text, "voxel %.4g m: up to about %striangles, %sB of memory",
                  e.voxel, roughly(e.triangles).c_str(), roughly(e.bytes).c_str());
    hintLine(text);
    markItem("export/estimate");
}

// The scene as the view shows it now, or the run from its start: frames 0 to the last baked at
// the fps chosen.
void ExportDialog::start(UiContext& c) {
    MeshFormat format;
    if (!meshFormatOf(path_, &format)) {
        status_ = "the file must end in .stl, .obj, .ply or .glb";
        return emitEvent("refuse " + status_);
    }
    const Editor& e = c.editor;
    const int last = int(e.simulation().cache().end() * fps_ + 1e-6);
    if (animation_ && (format != MeshFormat::Glb || last < 1)) {
        status_ = format != MeshFormat::Glb ? "an animation is exported as a .glb file"
                                            : "nothing has run yet: Play first, or export now";
        return emitEvent("refuse " + status_);
    }
    const Scene scene = animation_ ? e.document().start() : e.scene();
    ExportSettings s;
    s.voxel = voxel_;
    s.stop = [this] { return stop_.load(); };
    s.progress = [this](const char* doing, double done) {
        std::lock_guard<std::mutex> lock(mutex_);
        doing_ = doing;
        done_ = done;
    };
    stop_ = finished_ = false;
    done_ = 0.0;
    const ExportFrames frames{0, last, double(fps_)};
    const bool animated = animation_;
    const std::string path = path_;
    worker_ = std::thread([this, scene, path, frames, animated, s] {
        ExportResult r = animated ? exportAnimation(scene, path, frames, s)
                                  : exportScene(scene, path, s);
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = r;
        finished_ = true;
    });
    status_.clear();
    emitEvent("export started " + path_);
}

void ExportDialog::collect() {
    if (!worker_.joinable() || !finished_) return;
    worker_.join();
    const ExportResult& r = result_;
    if (r.status != ExportResult::Written) {
        status_ = r.status == ExportResult::Stopped ? "cancelled: nothing written" : r.error;
        return emitEvent("export " + status_);
    }
    // The file field above holds the whole path; wrapped here it would scroll the form away.
    const std::string told = ": " + std::to_string(r.triangles) + " triangles";
    status_ = "wrote " + std::filesystem::path(path_).filename().string() + told;
    emitEvent("export wrote " + path_ + told);
}

void ExportDialog::progress() {
    std::string doing;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        doing = doing_.empty() ? "starting" : doing_;
    }
    ImGui::ProgressBar(float(done_.load()), ImVec2(-1, 0), doing.c_str());
    markItem("export/progress");
    if (ImGui::Button("Cancel")) stop_ = true;
    markItem("export/cancel");
}

void ExportDialog::draw(UiContext& c) {
    collect();
    if (!c.ui.showExport) return;
    if (path_.empty())
        path_ = std::filesystem::path(proposeSavePath(c.editor.document().path(),
                                                      c.editor.lastFile()))
                    .replace_extension(".stl")
                    .string();
    if (beginPanel(c, Panel::Render, "Export Mesh", &c.ui.showExport)) {
        ImGui::BeginDisabled(running());
        ImGui::InputText("file", &path_, ImGuiInputTextFlags_AutoSelectAll);
        markItem("export/file");
        markTyping("export/file");
        itemTooltip("export/file", ".stl, .obj (with its .mtl), .ply with colours, or .glb");
        ImGui::DragFloat("voxel", &voxel_, 0.001f, 0.0f, 10.0f, voxel_ > 0 ? "%.4f m" : "auto");
        markItem("export/voxel");
        markTyping("export/voxel");
        estimate(animation_ ? c.editor.document().start() : c.editor.scene());
        if (ImGui::RadioButton("now", !animation_)) animation_ = false;
        markItem("export/now");
        ImGui::SameLine();
        if (ImGui::RadioButton("the run, animated (.glb)", animation_)) animation_ = true;
        markItem("export/animation");
        if (animation_) ImGui::DragFloat("fps", &fps_, 1.0f, 1.0f, 240.0f, "%.0f");
        if (ImGui::Button("Export")) start(c);
        markItem("export/go");
        ImGui::EndDisabled();
        if (running()) progress();
        statusLine(status_, &shownStatus_, "export/status");
    }
    ImGui::End();
}

}  // namespace mb
