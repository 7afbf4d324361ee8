// The demo's camera controller against the renderer's own view matrix: looking and moving right go to the
// screen's right, forward goes into the screen, orbit keeps its centre, pitch stops short of the poles.
#include <gtest/gtest.h>

#include "camera_controller.h"
#include "render/camera.h"

namespace lagoon::test {
namespace {

using demo::CameraController;
using demo::CameraInput;

glm::vec3 in_view(const scene::Camera& camera, const glm::vec3& world) {
  return glm::vec3(render::camera_matrices(camera, 16.0f / 9.0f).view * glm::vec4(world, 1.0f));
}

scene::Camera start() {
  scene::Camera c;
  c.position = {3, 6, -40};
  c.look_at = {10, 0, 0};
  return c;
}

TEST(DemoCamera, StartsLookingWhereTheSceneLooks) {
  const scene::Camera c = start();
  CameraController controller(c);
  scene::Camera out = c;
  controller.apply(out);
  EXPECT_NEAR(glm::dot(glm::normalize(out.look_at - out.position), glm::normalize(c.look_at - c.position)),
              1.0f, 1e-5f);
  EXPECT_EQ(out.position, c.position);
}

TEST(DemoCamera, MouseRightTurnsAndDRightMovesTowardsTheScreensRight) {
  const scene::Camera c = start();
  CameraController controller(c);
  const glm::vec3 before = controller.forward();
  controller.update({.look = {40.0f, 0.0f}}, 0.016f);
  // The new view direction, seen from the old camera, points right of centre (view space x > 0).
  EXPECT_GT(in_view(c, c.position + controller.forward()).x, 0.05f);
  EXPECT_NEAR(controller.forward().y, before.y, 1e-5f);  // horizontal mouse movement keeps the pitch

  CameraController mover(c);
  mover.update({.move = {1, 0, 0}}, 0.5f);
  const glm::vec3 moved = in_view(c, mover.position());
  EXPECT_GT(moved.x, 0.5f);
  EXPECT_NEAR(moved.y, 0.0f, 1e-3f);
  CameraController forward(c);
  forward.update({.move = {0, 0, 1}}, 0.5f);
  EXPECT_LT(in_view(c, forward.position()).z, -0.5f);  // into the screen (-z in view space)
  EXPECT_NEAR(in_view(c, forward.position()).x, 0.0f, 1e-3f);
}

TEST(DemoCamera, MouseUpLooksUpAndPitchStopsShortOfStraightUp) {
  CameraController controller(start());
  const float pitch = controller.pitch_deg();
  controller.update({.look = {0.0f, -20.0f}}, 0.016f);
  EXPECT_GT(controller.pitch_deg(), pitch);
  controller.update({.look = {0.0f, -100000.0f}}, 0.016f);
  EXPECT_FLOAT_EQ(controller.pitch_deg(), CameraController::kMaxPitchDeg);
  scene::Camera out;
  controller.apply(out);
  EXPECT_GT(glm::length(out.look_at - out.position), 0.5f);  // still a valid look_at
}

TEST(DemoCamera, ScrollChangesSpeedWithinLimits) {
  CameraController controller(start());
  const float speed = controller.speed_mps();
  controller.update({.scroll = 3.0f}, 0.016f);
  EXPECT_NEAR(controller.speed_mps(), speed * 1.728f, 1e-3f * speed);
  controller.update({.scroll = -1000.0f}, 0.016f);
  EXPECT_FLOAT_EQ(controller.speed_mps(), CameraController::kMinSpeed);
}

TEST(DemoCamera, OrbitTurnsAroundAFixedCentre) {
  const scene::Camera c = start();
  CameraController controller(c);
  controller.set_mode(CameraController::Mode::Orbit);
  scene::Camera a;
  controller.apply(a);
  controller.update({.look = {120.0f, 30.0f}}, 0.016f);
  scene::Camera b;
  controller.apply(b);
  EXPECT_NEAR(glm::distance(a.look_at, b.look_at), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::distance(a.position, a.look_at), glm::distance(b.position, b.look_at), 1e-3f);
  EXPECT_GT(glm::distance(a.position, b.position), 1.0f);
  // Zooming in keeps the centre and shortens the distance.
  controller.update({.scroll = 2.0f}, 0.016f);
  scene::Camera z;
  controller.apply(z);
  EXPECT_LT(glm::distance(z.position, z.look_at), glm::distance(b.position, b.look_at));
}

TEST(DemoCamera, OrbitFromBelowTheWaterCentresInFront) {
  scene::Camera c;
  c.position = {0, -5, 0};
  c.look_at = {0, -10, 5};  // looking down and ahead, under the surface
  CameraController controller(c);
  controller.set_mode(CameraController::Mode::Orbit);
  scene::Camera out;
  controller.apply(out);
  EXPECT_GT(glm::dot(out.look_at - c.position, c.look_at - c.position), 0.0f) << "centre behind the camera";
  controller.update({}, 0.016f);  // no input: the camera stays put
  EXPECT_LT(glm::distance(controller.position(), c.position), 1e-3f);
}

TEST(DemoCamera, KeepsTheModeWhenRestartedFromAnEditedScene) {
  scene::Camera c = start();
  CameraController controller(c, CameraController::Mode::Orbit);
  EXPECT_EQ(controller.mode(), CameraController::Mode::Orbit);
  scene::Camera out;
  controller.apply(out);
  EXPECT_EQ(out.look_at, c.look_at);  // a typed look_at stays the orbit centre
}

TEST(DemoCamera, ALongStallDoesNotFlingTheCamera) {
  CameraController controller(start());
  const glm::vec3 p = controller.position();
  controller.update({.move = {0, 0, 1}}, 30.0f);  // 30 s frame (debugger, minimised window)
  EXPECT_LT(glm::distance(p, controller.position()), controller.speed_mps() * 0.26f);
}

}  // namespace
}  // namespace lagoon::test
