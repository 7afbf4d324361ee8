// The demo's helm (apps/demo/helm.h): the ordered speed follows the throttle keys, the vehicle's speed
// follows the order at the set acceleration, full rudder turns on the set circle (starboard with Right), and
// a steady course gives no new orders.
#include "helm.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lagoon::test {
namespace {

using demo::Helm;
using demo::HelmInput;

physics::TrackPoint cruising(double speed) {
  physics::TrackPoint p;
  p.velocity = {0.0, speed};
  return p;
}

TEST(Helm, NoOrdersUntilTaken) {
  Helm helm;
  EXPECT_FALSE(helm.update({1, 1}, 0.1));
}

TEST(Helm, SpeedFollowsTheThrottleAtTheSetAcceleration) {
  Helm helm;
  helm.take(0, cruising(4.0));
  EXPECT_DOUBLE_EQ(helm.speed(), 4.0);
  const double dt = 1.0 / 60;
  for (int i = 0; i < 60; ++i) ASSERT_TRUE(helm.update({1, 0}, dt));  // Up held for 1 s
  EXPECT_NEAR(helm.ordered_speed(), 4.0 + Helm::kThrottleMps2, 1e-9);
  EXPECT_NEAR(helm.speed(), 4.0 + Helm::kAccelerationMps2, 1e-9);
  for (int i = 0; i < 120; ++i) helm.update({0, 0}, dt);  // the order is reached 2 s later
  EXPECT_NEAR(helm.speed(), 4.0 + Helm::kThrottleMps2, 1e-9);
  EXPECT_FALSE(helm.update({0, 0}, dt)) << "a steady course adds no order";
  for (int i = 0; i < 600; ++i) helm.update({1, 0}, dt);
  EXPECT_DOUBLE_EQ(helm.ordered_speed(), Helm::kMaxSpeedMps);
  for (int i = 0; i < 600; ++i) helm.update({-1, 0}, dt);
  EXPECT_DOUBLE_EQ(helm.ordered_speed(), 0.0);
}

TEST(Helm, FullRudderTurnsOnTheSetCircleToThatSide) {
  Helm helm;
  helm.take(1, cruising(6.0));
  const auto right = helm.update({0, 1}, 0.02);
  ASSERT_TRUE(right);
  EXPECT_DOUBLE_EQ(right->speed_mps, 6.0);
  // Starboard: the compass heading (clockwise from north) grows; radius v / |w| is the turning circle.
  EXPECT_NEAR(right->yaw_rate_radps, 6.0 / Helm::kTurningRadiusM, 1e-12);
  const auto left = helm.update({0, -0.5}, 0.02);
  ASSERT_TRUE(left);
  EXPECT_NEAR(left->yaw_rate_radps, -0.5 * 6.0 / Helm::kTurningRadiusM, 1e-12);
  // Fast, the rate of turn is capped.
  Helm fast;
  fast.take(0, cruising(Helm::kMaxSpeedMps));
  EXPECT_NEAR(fast.update({0, 1}, 0.02)->yaw_rate_radps, Helm::kMaxYawRateRadps, 1e-12);
  // Stopped, the rudder does nothing.
  Helm stopped;
  stopped.take(0, cruising(0.0));
  EXPECT_EQ(stopped.update({0, 1}, 0.02)->yaw_rate_radps, 0.0);
}

}  // namespace
}  // namespace lagoon::test
