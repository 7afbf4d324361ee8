// A live frame moves the simulation by the wall clock's step, at most a quarter of a second
// (apps/demo/live_clock.h).
#include "live_clock.h"

#include <gtest/gtest.h>

namespace lagoon::demo {
namespace {

TEST(LiveClock, AFrameMovesTheWorldByTheClockUpToAQuarterOfASecond) {
  EXPECT_DOUBLE_EQ(live_step_s(1.0 / 60.0), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(live_step_s(0.2), 0.2);
  // A slow device's frames (lavapipe's harbour: 1.1 s) and a start-up's (pipelines compiled: 10 s).
  EXPECT_DOUBLE_EQ(live_step_s(1.1), 0.25);
  EXPECT_DOUBLE_EQ(live_step_s(10.0), 0.25);
  EXPECT_DOUBLE_EQ(live_step_s(-0.01), 0.0);  // a clock that stepped back
}

}  // namespace
}  // namespace lagoon::demo
