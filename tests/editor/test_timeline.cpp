// test_timeline.cpp — the timeline strip's seconds and pixels, and clicks on camera keys.
#include "marchbox/editor/timeline.h"

#include <gtest/gtest.h>

using namespace mb;

static std::vector<Keyframe> keysAt(std::initializer_list<float> times) {
    std::vector<Keyframe> keys;
    for (float t : times) keys.push_back(Keyframe{t});
    return keys;
}

TEST(Timeline, TheStripSpansEverythingThereIsToShowAndATenthMore) {
    EXPECT_DOUBLE_EQ(timelineStrip(0, 100, 0, {}, 0).span, 1.0);  // nothing yet: one second
    EXPECT_DOUBLE_EQ(timelineStrip(0, 100, 5, {}, 2).span, 5.5);
    EXPECT_DOUBLE_EQ(timelineStrip(0, 100, 5, keysAt({1, 8}), 2).span, 8.8);
    EXPECT_DOUBLE_EQ(timelineStrip(0, 100, 5, {}, 6).span, 6.6);  // shown past what is baked
}

TEST(Timeline, PixelsAndSecondsGoBothWays) {
    const TimelineStrip s = timelineStrip(20, 200, 10, {}, 0);  // 11 s over 200 px from x = 20
    EXPECT_FLOAT_EQ(s.x(0), 20.0f);
    EXPECT_FLOAT_EQ(s.x(5.5), 120.0f);
    EXPECT_NEAR(s.time(120), 5.5, 1e-9);
    EXPECT_EQ(s.time(0), 0.0);       // left of the strip: its start
    EXPECT_EQ(s.time(400), s.span);  // right of it: its end
}

TEST(Timeline, AClickNearAKeysMarkerIsOnTheNearestKey) {
    const std::vector<Keyframe> keys = keysAt({0, 1, 1.5f, 9});
    const TimelineStrip s = timelineStrip(0, 110, 10, keys, 0);  // 10 px a second
    EXPECT_EQ(keyMarkerAt(s, keys, 3, 6), 0);
    EXPECT_EQ(keyMarkerAt(s, keys, 10.5f, 6), 1);
    EXPECT_EQ(keyMarkerAt(s, keys, 13.5f, 6), 2);   // between 1 and 1.5 s: the nearer
    EXPECT_EQ(keyMarkerAt(s, keys, 12.5f, 6), 1);   // as near to both: the earlier
    EXPECT_EQ(keyMarkerAt(s, keys, 50, 6), -1);     // far from any
    EXPECT_EQ(keyMarkerAt(s, keys, 96.5f, 6), -1);  // 6.5 px from the last: out of reach
    EXPECT_EQ(keyMarkerAt(s, {}, 0, 6), -1);
}

TEST(Timeline, ALoopEndsAtTheLastKeyElseWhereTheBakedFramesEnd) {
    EXPECT_EQ(loopEnd(keysAt({0, 1, 4}), 2.5), 4.0);
    EXPECT_EQ(loopEnd(keysAt({0}), 2.5), 2.5);  // one key at 0 makes no clip
    EXPECT_EQ(loopEnd({}, 2.5), 2.5);
    EXPECT_EQ(loopEnd({}, 0), 0.0);  // nothing to loop over
}

TEST(Timeline, ThePlayHeadGoesBackToZeroPastTheEnd) {
    EXPECT_DOUBLE_EQ(playHead(0.5, 0.25, 1.0), 0.75);
    EXPECT_DOUBLE_EQ(playHead(0.75, 0.25, 1.0), 1.0);  // the end itself is shown
    EXPECT_EQ(playHead(0.9, 0.25, 1.0), 0.0);
    EXPECT_EQ(playHead(1.0, 1.0 / 120, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(playHead(5.0, 0.25, 0.0), 5.25);  // no end: on and on
}

TEST(Timeline, TicksAreRoundTimesFarEnoughApartForTheirLabels) {
    EXPECT_EQ(tickStep({0, 480, 10.0}, 48), 1.0);    // 48 px a second
    EXPECT_EQ(tickStep({0, 480, 11.0}, 48), 2.0);    // 43.6 px a second: too close
    EXPECT_EQ(tickStep({0, 480, 30.0}, 48), 5.0);
    EXPECT_EQ(tickStep({0, 480, 60.0}, 48), 10.0);
    EXPECT_EQ(tickStep({0, 480, 1.0}, 48), 0.1);
    EXPECT_EQ(tickStep({0, 480, 2.2}, 48), 0.5);
}

TEST(Timeline, TickLabelsHaveTheDecimalsTheirStepNeeds) {
    EXPECT_EQ(tickLabel(0.0, 1.0), "0");
    EXPECT_EQ(tickLabel(12.0, 2.0), "12");
    EXPECT_EQ(tickLabel(1.5, 0.5), "1.5");
    EXPECT_EQ(tickLabel(0.3, 0.1), "0.3");
    EXPECT_EQ(tickLabel(0.25, 0.05), "0.25");
    EXPECT_EQ(tickLabel(20.0, 10.0), "20");
}
