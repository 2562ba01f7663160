// marchbox/editor/disk_file.h — the open scene's file as it stands on disk, to notice a change
// made elsewhere (a text editor, sed, a checkout) and never to save over it unasked.
//
// What counts is the text: a file rewritten with the same bytes (touched, or saved by us) has
// not changed. Each look stats the file, which costs microseconds; only when its time or size
// moved is it read and hashed. A file gone (deleted, or moved away) is no change to act on:
// Save writes it again.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace mb {

class DiskFile {
public:
    // After New, Open or Save: the file at `path` ("" for none) holds what the editor knows.
    void track(const std::string& path);
    const std::string& path() const { return path_; }

    // True once for each new text that differs from the one the editor knows.
    bool changedElsewhere();
    // The text on disk now differs from the one the editor knows (seen before or not).
    bool differs();
    // The change is dealt with (loaded, or the user keeps their own): its text is the known one.
    void accept() { known_ = seen_; }

private:
    void look();  // stamp, and the hash where the stamp moved

    std::string path_;
    std::filesystem::file_time_type time_{};
    uintmax_t size_ = 0;
    uint64_t known_ = 0;  // hash of the text the editor loaded or saved
    uint64_t seen_ = 0;   // hash of the text last read
    uint64_t told_ = 0;   // hash last reported by changedElsewhere()
};

}  // namespace mb
