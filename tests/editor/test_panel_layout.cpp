// test_panel_layout.cpp — the editor's panels fit the window and never cover one another.
#include "marchbox/editor/panel_layout.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

bool overlap(const PanelRect& a, const PanelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

// The window sizes people use (960x600 and 1280x720) and the e2e tests' small one; the menu bar and
// the statistics overlay as ImGui draws them at its default font.
const PanelFrame kFrames[] = {{960, 600, 19, 140}, {1280, 720, 19, 140}, {640, 400, 19, 140}};

}  // namespace

TEST(PanelLayout, EveryChoiceOfOpenPanelsFitsTheWindowWithoutOverlap) {
    for (const PanelFrame& f : kFrames)
        for (unsigned open = 0; open < 1u << kPanelCount; ++open) {
            auto rects = layoutPanels(f, open);
            for (int i = 0; i < kPanelCount; ++i) {
                const PanelRect& r = rects[size_t(i)];
                SCOPED_TRACE(testing::Message()
                             << f.width << "x" << f.height << " open " << open << " panel " << i);
                if (!(open & panelBit(Panel(i)))) {
                    EXPECT_EQ(r, PanelRect{});
                    continue;
                }
                EXPECT_GE(r.x, 0.0f);
                EXPECT_GE(r.y, f.top);
                EXPECT_LE(r.x + r.width, f.width);
                EXPECT_LE(r.y + r.height, f.height);
                if (f.height >= 600) {
                    EXPECT_GE(r.height, 90.0f)
                        << "room for a few lines, however many panels share a column";
                }
                for (int j = i + 1; j < kPanelCount; ++j) {
                    if (open & panelBit(Panel(j))) {
                        EXPECT_FALSE(overlap(r, rects[size_t(j)])) << "and panel " << j;
                    }
                }
            }
        }
}

TEST(PanelLayout, TheRightColumnStartsBelowTheStatistics) {
    PanelFrame f{960, 600, 19, 140};
    PanelRect view = layoutPanels(f, panelBit(Panel::View))[size_t(Panel::View)];
    EXPECT_GE(view.y, f.rightTop);
    EXPECT_EQ(view.x + view.width, f.width - kPanelMargin);
    f.rightTop = 0;  // the statistics hidden: up to the menu bar
    EXPECT_EQ(layoutPanels(f, panelBit(Panel::View))[size_t(Panel::View)].y, f.top + kPanelMargin);
}

TEST(PanelLayout, APanelAloneTakesItsWholeColumnAndSharesItWhenAnotherOpens) {
    PanelFrame f{960, 600, 19, 140};
    PanelRect alone = layoutPanels(f, panelBit(Panel::Objects))[0];
    EXPECT_EQ(alone.y + alone.height, f.height - kPanelMargin);
    auto both = layoutPanels(f, panelBit(Panel::Objects) | panelBit(Panel::Lights));
    EXPECT_LT(both[size_t(Panel::Objects)].height, alone.height * 0.55f);
    EXPECT_GT(both[size_t(Panel::Lights)].y, both[size_t(Panel::Objects)].y)
        << "in the menu's order";
}

// The overlay as ImGui draws it at its default font: 233x125 at the window's top right.
static PanelRect statsIn(const PanelFrame& f) { return {f.width - 10 - 233, 30, 233, 125}; }

TEST(PanelLayout, TheStatisticsGiveWayInASmallWindow) {
    const unsigned all = (1u << kPanelCount) - 1;
    for (const PanelFrame& f : kFrames)
        EXPECT_TRUE(statisticsFit(f, all, statsIn(f))) << f.width << "x" << f.height;
    // 400x300: over the Objects panel's column, and four panels would not fit below it.
    const PanelFrame small{400, 300, 19, 0};
    EXPECT_FALSE(statisticsFit(small, panelBit(Panel::Objects), statsIn(small)));
    EXPECT_FALSE(statisticsFit(small, all & ~7u, statsIn(small)));  // the right column alone
    EXPECT_TRUE(statisticsFit(small, 0, statsIn(small)));  // no panel open: room for it
}

TEST(PanelLayout, TheUncoveredRoomLiesBetweenTheOpenColumns) {
    const PanelFrame f = kFrames[1];  // 1280x720
    const unsigned objects = panelBit(Panel::Objects), view = panelBit(Panel::View);
    EXPECT_EQ(uncoveredRoom(f, 0), (PanelRect{0, 19, 1280, 701}));
    EXPECT_EQ(uncoveredRoom(f, objects), (PanelRect{380, 19, 900, 701}));  // 10 + 360 + 10
    EXPECT_EQ(uncoveredRoom(f, objects | view), (PanelRect{380, 19, 520, 701}));
    for (const PanelFrame& small : {kFrames[2]}) {  // 640 wide: the columns meet
        const PanelRect r = uncoveredRoom(small, objects | view);
        EXPECT_EQ(r.x, 0.0f);
        EXPECT_EQ(r.width, small.width);
    }
}
