// fresh_dir.h — an empty folder of the build tree for a test's files.
#pragma once

#include <filesystem>
#include <string>

namespace mb::test {

// build/test-output/GROUP/NAME, emptied: what a test left there last time is gone.
inline std::filesystem::path freshDir(const std::string& group, const std::string& name) {
    std::filesystem::path dir =
        std::filesystem::path(MARCHBOX_BINARY_DIR) / "test-output" / group / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace mb::test
