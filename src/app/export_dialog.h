// export_dialog.h — File > Export Mesh...: `marchbox export` from the editor. The solids as the
// view shows them now, or the run baked so far as an animated .glb, meshed on a worker thread
// while the editor stays live, with a progress bar and Cancel. The format follows the file's
// extension; the voxel size says about how many triangles and how much memory it makes.
#pragma once

#include "ui.h"

#include "marchbox/export/export.h"

#include <atomic>
#include <mutex>
#include <string>
#include <thread>

namespace mb {

class ExportDialog {
public:
    ~ExportDialog();  // a run under way is stopped, and nothing of it written
    void draw(UiContext& c);
    bool running() const { return worker_.joinable(); }

private:
    void start(UiContext& c);
    void collect();  // a finished run's result into the status
    void estimate(const Scene& scene);
    void progress();

    std::string path_;  // empty until first shown: then beside the scene, as .stl
    float voxel_ = 0.0f;
    bool animation_ = false;
    float fps_ = 30.0f;

    std::thread worker_;
    std::atomic<bool> stop_{false}, finished_{false};
    std::atomic<double> done_{0.0};
    std::mutex mutex_;   // guards doing_ and result_ while the worker runs
    std::string doing_;  // "simulating", "meshing"
    ExportResult result_;
    std::string status_, shownStatus_;
};

}  // namespace mb
