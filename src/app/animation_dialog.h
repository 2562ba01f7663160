// animation_dialog.h — File > Render Animation...: render --frames from the editor. The scene
// as it stands is played once from t = 0 and its frames written to numbered PNG files or an
// .mp4, one frame's tiles at a time between the editor's frames, with a progress bar and
// Cancel. The files are what `marchbox render SCENE -o OUT --frames A-B --fps F --size WxH
// --quality Q` writes, byte for byte: the same options, checks, sequence and frame output.
#pragma once

#include "frame_output.h"
#include "frame_sequence.h"
#include "render_dialog.h"

#include <memory>
#include <string>

namespace mb {

class AnimationDialog {
public:
    void draw(UiContext& c);          // the window, while c.ui.showAnimation
    void work(double budgetSeconds);  // simulates and draws tiles until the budget is spent
    bool running() const { return out_ != nullptr; }

private:
    // The command line's options from the fields, else status_ says why.
    bool options(Args* a, FramePattern* pattern);
    void start(UiContext& c);
    bool nextFrame(double until);  // true when a frame was drawn and more may follow
    bool handOver();               // the oldest frame in flight to out_; false when stopped
    void stop(const std::string& status);
    void progress() const;

    RenderChoice choice_{640, 360, {}, {}};
    std::string path_ = "frame_%05d.png", frames_ = "0-59", fps_ = "30";
    int first_ = 0, last_ = 0, frame_ = 0;  // the range, and the frame under way
    double startedAt_ = 0.0;
    RenderOptions options_;
    std::unique_ptr<FrameSequence> sequence_;
    std::unique_ptr<FrameOutput> out_;
    std::unique_ptr<Renderer> renderer_;   // its own: the window's keeps drawing meanwhile
    std::unique_ptr<TiledRender> tiles_;   // the frame under way, once the simulation is there
    std::unique_ptr<FrameReadback> ring_;  // frames drawn, on their way back to memory
    std::string status_;
    std::string shownStatus_;  // status_ as last drawn
};

}  // namespace mb
