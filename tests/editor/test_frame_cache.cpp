// test_frame_cache.cpp — a run's pieces, and the frames that follow an edit at a later time.
#include "marchbox/editor/frame_cache.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace mb;

using Piece = std::shared_ptr<const RunPiece>;

static Piece piece(double from, Piece before, float x = 0) {
    Object o;
    o.pos = {x, 1, 0};
    auto objects = std::make_shared<const std::vector<Object>>(std::vector<Object>{o});
    return std::make_shared<const RunPiece>(RunPiece{from, from > 0 ? objects : nullptr, before});
}

// One falling sphere at height y.
static Scene sphereAt(float y) {
    Scene s;
    s.objects.resize(1);
    s.objects[0].pos = {0, y, 0};
    return s;
}

// Frames at 0.1, 0.2, ... 1.0 s, the sphere at height 10 t.
static FrameCache baked(const Piece& run) {
    FrameCache cache;
    for (int k = 1; k <= 10; ++k) cache.record(run, k / 10.0, sphereAt(float(k)));
    return cache;
}

TEST(FrameCache, AnEditBelongsToTheTimeItWasMadeAt) {
    Piece root = piece(0, nullptr), one = piece(1, root), two = piece(2, one);
    EXPECT_EQ(pieceAt(two, 0.5), root);
    EXPECT_EQ(pieceAt(two, 1.0), one);  // the frame at the edit shows the edit
    EXPECT_EQ(pieceAt(two, 1.5), one);
    EXPECT_EQ(pieceAt(two, 2.0), two);
    EXPECT_EQ(pieceAt(two, 9.0), two);
    EXPECT_EQ(pieceAt(nullptr, 1.0), nullptr);
}

TEST(FrameCache, AnEditAtTDropsTheFramesFromTOn) {
    Piece root = piece(0, nullptr);
    FrameCache cache = baked(root);
    Piece edit = piece(0.5, root, 4);
    cache.follow(edit);
    EXPECT_DOUBLE_EQ(cache.end(), 0.4);  // the frame at 0.5 showed the bodies before the edit
    ASSERT_NE(cache.at(0.45), nullptr);
    EXPECT_EQ(cache.at(0.45)->bodies[0].pos.y, 4.0f);  // what ran before stays as it ran

    cache.record(edit, 0.5, sphereAt(5));
    cache.record(edit, 0.6, sphereAt(6));
    cache.follow(edit);  // the run it holds: nothing goes
    EXPECT_DOUBLE_EQ(cache.end(), 0.6);
    cache.follow(root);  // the edit undone: the frames made after it go
    EXPECT_DOUBLE_EQ(cache.end(), 0.4);
    cache.follow(nullptr);  // a new start
    EXPECT_TRUE(cache.empty());
}

// Played again from 0.35 s (a scrub back), the frames after it are made anew.
TEST(FrameCache, RecordingFromAnEarlierTimeReplacesWhatFollowed) {
    Piece root = piece(0, nullptr);
    FrameCache cache = baked(root);
    cache.record(root, 0.35, sphereAt(-1));
    EXPECT_DOUBLE_EQ(cache.end(), 0.35);
    EXPECT_EQ(cache.at(0.99)->bodies[0].pos.y, -1.0f);
    EXPECT_EQ(cache.at(0.3)->bodies[0].pos.y, 3.0f);
    EXPECT_EQ(cache.at(0.05), nullptr);  // before the first frame: the start
}

TEST(FrameCache, AFrameAfterAnEditPutsBackTheEditedObjects) {
    Scene edited = sphereAt(2);
    edited.objects[0].radius = 2;  // the edit made it larger
    auto objects = std::make_shared<const std::vector<Object>>(edited.objects);
    Piece edit = std::make_shared<const RunPiece>(RunPiece{0.5, objects, piece(0, nullptr)});
    FrameCache cache;
    cache.record(edit, 0.5, edited);
    edited.objects[0].pos.y = 1.5f;  // fallen on
    cache.record(edit, 0.6, edited);

    Scene shown = sphereAt(7);  // the start's objects, as a scrub begins
    applyFrame(*cache.at(0.6), shown);
    EXPECT_EQ(shown.objects[0].radius, 2.0f);
    EXPECT_EQ(shown.objects[0].pos, glm::vec3(0, 1.5f, 0));  // the body's state at the frame
}

// 100 frames of one body against a budget of 41 (so that it thins an even count): every other
// frame goes, the newest stays, and frames are kept half as often after.
TEST(FrameCache, PastItsBudgetTheCacheKeepsEveryOtherFrame) {
    Piece root = piece(0, nullptr);
    FrameCache probe;
    probe.record(root, 0.01, sphereAt(1));
    const size_t perFrame = probe.bytes();
    FrameCache cache(41 * perFrame);
    for (int k = 1; k <= 100; ++k) {
        const size_t before = cache.frames();
        cache.record(root, k / 100.0, sphereAt(float(k)));
        if (cache.frames() < before) {  // thinned
            EXPECT_DOUBLE_EQ(cache.end(), k / 100.0);
        }
    }
    EXPECT_LE(cache.bytes(), 41 * perFrame);
    EXPECT_GE(cache.frames(), 10u);
    EXPECT_DOUBLE_EQ(cache.end(), 1.0);  // the newest is always there
    EXPECT_EQ(cache.at(1.0)->bodies[0].pos.y, 100.0f);
    std::vector<double> kept;  // the frames' times, found through at()
    for (int ms = 0; ms <= 1000; ++ms)
        if (const BakedFrame* f = cache.at(ms / 1000.0); f && (kept.empty() || f->t != kept.back()))
            kept.push_back(f->t);
    ASSERT_EQ(kept.size(), cache.frames());
    double least = 1, most = 0;  // thinned evenly: no crowd, no long hole
    for (size_t i = 1; i + 1 < kept.size(); ++i) {
        least = std::min(least, kept[i] - kept[i - 1]);
        most = std::max(most, kept[i] - kept[i - 1]);
    }
    EXPECT_LE(most, 2.5 * least);  // 0.04 s and 0.02 s here; 0.08 and 0.01 without the gap

    Piece edit = piece(1.001, root, 4);  // an edit's first frame stays, however near
    cache.follow(edit);
    cache.record(edit, 1.001, sphereAt(-1));
    cache.record(edit, 1.002, sphereAt(-2));
    EXPECT_EQ(cache.at(1.0015)->bodies[0].pos.y, -1.0f);
    EXPECT_EQ(cache.at(1.002)->bodies[0].pos.y, -2.0f);
}

// A bake thinned again and again lies unevenly (frames before the last thinning twice as far
// apart as those after), and every time up to its end is in it; a frame recorded after a hole
// (a run undone and redone keeps its last pose alone) leaves the time before it out, back to the
// frame before. Planted: a hole guessed from the spacing (wider than the frames' average or a
// quarter second): 33 s of frames in a budget of 41 had times left out.
TEST(FrameCache, EveryTimeOfAThinnedBakeIsHeldAndAHoleIsNot) {
    Piece root = piece(0, nullptr);
    FrameCache probe;
    probe.record(root, 0.01, sphereAt(1));
    FrameCache cache(41 * probe.bytes());
    for (int k = 1; k <= 2000; ++k) cache.record(root, (k + k / 7) / 60.0, sphereAt(float(k)));
    for (double t = 0.0; t <= cache.end(); t += 0.01) EXPECT_TRUE(cache.holds(t)) << "t = " << t;
    const double end = cache.end();
    cache.record(root, end + 10.0, sphereAt(0), true);
    EXPECT_TRUE(cache.holds(end));
    EXPECT_FALSE(cache.holds(end + 5.0));
    EXPECT_TRUE(cache.holds(end + 10.0));
    EXPECT_FALSE(cache.holds(end + 10.5));  // past the end
}
