// test_controls.cpp — docs/editor.md lists the keys Help > Controls shows, row for row.
#include "marchbox/editor/controls.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace mb;

namespace {

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// The rows "| keys | action |" of the table in docs/editor.md's "## Controls" section, header
// and rule left out.
std::vector<std::pair<std::string, std::string>> documentedControls() {
    std::ifstream in(std::string(MARCHBOX_SOURCE_DIR) + "/docs/editor.md");
    std::vector<std::pair<std::string, std::string>> rows;
    std::string line;
    bool inSection = false;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) inSection = line == "## Controls";
        if (!inSection || line.rfind("| ", 0) != 0 || line.find("---") != std::string::npos)
            continue;
        size_t mid = line.find(" | ");
        std::string keys = trim(line.substr(2, mid - 2)), action = trim(line.substr(mid + 3));
        if (action.size() >= 2 && action.substr(action.size() - 2) == " |")
            action = trim(action.substr(0, action.size() - 2));
        if (keys != "Keys") rows.emplace_back(keys, action);
    }
    return rows;
}

}  // namespace

TEST(Controls, DocsListEveryControlAsHelpShowsIt) {
    auto docs = documentedControls();
    auto table = editorControls();
    ASSERT_EQ(docs.size(), table.size()) << "docs/editor.md's Controls section has " << docs.size()
                                         << " rows of keys, Help > Controls " << table.size();
    for (size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(docs[i].first, table[i].keys) << "row " << i;
        EXPECT_EQ(docs[i].second, table[i].action) << "row " << i;
    }
}

TEST(Controls, EveryKeyTheWindowHandlesIsListed) {
    std::string all;
    for (const Control& c : editorControls()) all += std::string(c.keys) + ", ";
    for (const char* key :
         {"1", "F", "P", "J", "Space", "Delete", "F12", "Esc", "Ctrl+Z", "Ctrl+Y", "Ctrl+N",
          "Ctrl+O", "Ctrl+S", "Ctrl+Shift+S", "W A S D, Q E", "G", "R", "T"})
        EXPECT_NE(all.find(std::string(key) + ","), std::string::npos) << key;
    // Selecting, grouping, duplicating and copying, as in Blender.
    for (const char* key :
         {"Shift+click", "Ctrl box drag", "Ctrl+A", "[", "Ctrl+G", "Ctrl+Alt+G", "Shift+D",
          "Ctrl+C, Ctrl+V"})
        EXPECT_NE(all.find(std::string(key) + ","), std::string::npos) << key;
}

// The Controls panel is 360 px wide: keys of at most 14 characters leave the actions about 31
// a line, so an action of at most 56 reads in two lines. Most rows wrapped over three before.
TEST(Controls, EachRowReadsInTwoLinesOfTheirPanel) {
    for (const Control& k : editorControls()) {
        EXPECT_LE(std::string(k.keys).size(), 14u) << k.keys;
        EXPECT_LE(std::string(k.action).size(), 56u) << k.action;
    }
}
