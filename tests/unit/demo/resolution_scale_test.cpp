// The demo's dynamic resolution (apps/demo/resolution_scale.h) against a device whose frame costs a fixed
// part plus a part proportional to the pixels: it settles on the largest step of an eighth that meets the
// target, stays there, comes back up when frames get cheap, goes to its floor when nothing meets the target,
// and draws at the window's size when the target is 0.
#include "resolution_scale.h"

#include <gtest/gtest.h>

namespace lagoon::demo {
namespace {

// Frames of `fixed_ms` + `pixel_ms` x scale² for `frames` frames; returns the scales seen.
std::vector<double> run(ResolutionScale& r, double fixed_ms, double pixel_ms, int frames) {
  std::vector<double> seen;
  for (int i = 0; i < frames; ++i) {
    r.observe(fixed_ms + pixel_ms * r.scale() * r.scale());
    seen.push_back(r.scale());
  }
  return seen;
}

TEST(ResolutionScale, SettlesOnTheLargestStepThatMeetsTheTargetAndStays) {
  ResolutionScale r(15.0);  // 66.7 ms
  // 10 ms fixed + 200 ms at full size: 0.5 gives 60 ms, 0.625 gives 88 ms.
  const std::vector<double> seen = run(r, 10.0, 200.0, 200);
  EXPECT_DOUBLE_EQ(r.scale(), 0.5);
  for (size_t i = 100; i < seen.size(); ++i) EXPECT_DOUBLE_EQ(seen[i], 0.5) << "frame " << i;
  EXPECT_EQ(r.render_extent({1280, 720}).width, 640u);
  EXPECT_EQ(r.render_extent({1280, 720}).height, 360u);
  // Cheaper frames (another view): back up to full size.
  run(r, 10.0, 40.0, 200);
  EXPECT_DOUBLE_EQ(r.scale(), 1.0);
}

TEST(ResolutionScale, OutOfReachGoesToTheFloorAndZeroMeansFullSize) {
  ResolutionScale r(15.0);
  run(r, 100.0, 40.0, 200);  // 100 ms even with no pixels
  EXPECT_DOUBLE_EQ(r.scale(), ResolutionScale::kLowest);
  r.set_target_fps(0);
  EXPECT_DOUBLE_EQ(r.scale(), 1.0);
  run(r, 100.0, 40.0, 200);
  EXPECT_DOUBLE_EQ(r.scale(), 1.0);
  EXPECT_EQ(r.render_extent({37, 11}).width, 37u);
}

TEST(ResolutionScale, TheCausticMapCoarsensWithTheSize) {
  ResolutionScale r(15.0);
  EXPECT_EQ(r.caustic_coarsening(), 1);  // full size: the full map
  run(r, 100.0, 40.0, 200);              // to the floor, a quarter of the window each way
  EXPECT_EQ(r.caustic_coarsening(), 4);
  r.set_target_fps(0);
  EXPECT_EQ(r.caustic_coarsening(), 1);
}

TEST(ResolutionScale, TheFirstFrameAtASizeIsNotItsCost) {
  ResolutionScale r(15.0);
  r.observe(5000.0);  // a frame that compiled pipelines or re-made targets
  for (int i = 0; i < 20; ++i) r.observe(50.0);
  EXPECT_DOUBLE_EQ(r.scale(), 1.0);
}

TEST(ResolutionScale, FramesFarOverTheTargetMoveAtOnce) {
  // lavapipe under load: 2 s frames for a 240 fps target. Waiting kSettleFrames of them would leave a user
  // (and the demo's live test, which sees 4 frames in 6 s) at full size for 12 s.
  ResolutionScale r(240.0);
  r.observe(2500.0);  // the first frame at a size is not its cost
  EXPECT_DOUBLE_EQ(r.scale(), 1.0);
  r.observe(2000.0);
  EXPECT_DOUBLE_EQ(r.scale(), ResolutionScale::kLowest);
  // Near the target it still settles: 1.5x the target's time waits kSettleFrames before moving.
  ResolutionScale near(15.0);
  near.observe(100.0);
  for (int i = 0; i < ResolutionScale::kSettleFrames - 2; ++i) {
    near.observe(100.0);
    EXPECT_DOUBLE_EQ(near.scale(), 1.0) << "frame " << i;
  }
  near.observe(100.0);
  EXPECT_LT(near.scale(), 1.0);
}

}  // namespace
}  // namespace lagoon::demo
