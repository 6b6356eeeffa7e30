// FrameMemo (render/FrameMemo.h) keeps what a frame asked for into the next frame and drops what
// two frames in a row did not ask for: the renderer's kept footprints must neither grow without
// bound as objects move nor be worked out again while they stay put.
#include "render/FrameMemo.h"

#include <gtest/gtest.h>

#include <string>

namespace penumbra::render {
namespace {

TEST(FrameMemo, KeepsWhatTheLastFrameAskedForAndDropsTheRest) {
    FrameMemo<std::string> memo;
    bool made = false;
    memo.at(1, made) = "one";
    EXPECT_TRUE(made);
    memo.at(2, made) = "two";
    EXPECT_EQ(memo.madeThisFrame(), 2u);
    EXPECT_EQ(memo.at(1, made), "one");
    EXPECT_FALSE(made) << "asked twice in one frame";

    memo.nextFrame();  // frame 2 asks for 1 only
    EXPECT_EQ(memo.at(1, made), "one");
    EXPECT_FALSE(made);
    EXPECT_EQ(memo.madeThisFrame(), 0u);

    memo.nextFrame();  // frame 3: 2 was last asked for in frame 1, so it is gone
    EXPECT_EQ(memo.at(2, made), "");
    EXPECT_TRUE(made);
    EXPECT_EQ(memo.at(1, made), "one") << "asked for in frame 2";
    EXPECT_FALSE(made);

    for (int frame = 0; frame < 10; ++frame) {  // a moving object: a new key every frame
        memo.nextFrame();
        memo.at(100 + static_cast<std::uint64_t>(frame), made);
        EXPECT_TRUE(made);
    }
    EXPECT_LE(memo.size(), 2u) << "old keys are dropped, not kept";
}

}  // namespace
}  // namespace penumbra::render
