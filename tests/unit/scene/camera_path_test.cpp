// The camera path of lagoon render --path and bench effects: passes through every keyframe, keeps a constant
// velocity exactly, has a continuous velocity at the keys, and refuses bad files naming the field.
#include <gtest/gtest.h>

#include <fstream>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "scene/camera_path.h"
#include "support/temp_dir.h"

namespace lagoon::scene {
namespace {

using nlohmann::json;

json key(double t, glm::vec3 p, glm::vec3 a) {
  return {{"t", t}, {"position", {p.x, p.y, p.z}}, {"look_at", {a.x, a.y, a.z}}};
}

CameraPath parse(const json& document) {
  Result<CameraPath> path = parse_camera_path(document, "path.json");
  EXPECT_TRUE(path) << (path ? "" : path.error().message);
  return path ? *path : CameraPath{};
}

std::string error_of(const json& document) {
  Result<CameraPath> path = parse_camera_path(document, "path.json");
  return path ? "" : path.error().message;
}

TEST(CameraPath, PassesThroughEveryKeyframe) {
  const CameraPath path = parse({{"keyframes",
                                  {key(0, {0, 5, -16}, {0, 0, 30}), key(1.5, {3, 1, -4}, {1, -1, 9}),
                                   key(4, {-2, -3, 6}, {5, -4, 8}), key(5, {0, 2, 0}, {0, 0, 20})}}});
  for (const CameraKey& k : path.keys) {
    const Camera c = path.at(k.t, Camera{});
    EXPECT_LT(glm::distance(c.position, k.position), 1e-5f) << k.t;
    EXPECT_LT(glm::distance(c.look_at, k.look_at), 1e-5f) << k.t;
  }
  EXPECT_DOUBLE_EQ(path.duration_s(), 5.0);
  // Outside the path the camera stays at its ends; the lens comes from the scene.
  Camera lens;
  lens.fov_deg = 33;
  EXPECT_LT(glm::distance(path.at(9, lens).position, path.keys.back().position), 1e-6f);
  EXPECT_EQ(path.at(2, lens).fov_deg, 33.f);
}

TEST(CameraPath, AConstantVelocityFlightStaysExactlyLinearOnUnevenKeyTimes) {
  // Keys on a straight line at uneven times but one speed: a uniform-parameter spline would bulge between
  // them; tangents on the keys' own times reproduce the line.
  const glm::vec3 v(2, -0.5, 3), a(0, 0, 100);
  json keys = json::array();
  for (double t : {0.0, 0.3, 2.0, 2.2, 6.0}) keys.push_back(key(t, glm::vec3(float(t)) * v, a));
  const CameraPath path = parse({{"keyframes", keys}});
  for (double t = 0; t <= 6.0; t += 0.05)
    EXPECT_LT(glm::distance(path.at(t, Camera{}).position, glm::vec3(float(t)) * v), 2e-5f) << t;
}

TEST(CameraPath, VelocityIsContinuousAtTheKeysAndSmoothBetween) {
  const CameraPath path = parse({{"keyframes",
                                  {key(0, {0, 5, -16}, {0, 0, 30}), key(2, {4, 1, -4}, {1, -1, 9}),
                                   key(3, {-2, -3, 6}, {5, -4, 8}), key(7, {0, 2, 0}, {0, 0, 20})}}});
  const double h = 1e-4;
  auto velocity = [&](double t0, double t1) {
    return (glm::dvec3(path.at(t1, Camera{}).position) - glm::dvec3(path.at(t0, Camera{}).position)) /
           (t1 - t0);
  };
  for (double t : {2.0, 3.0}) {
    const glm::dvec3 before = velocity(t - h, t), after = velocity(t, t + h);
    EXPECT_LT(glm::length(before - after), 0.01 * glm::length(before) + 1e-3) << "at key t = " << t;
  }
  // (Linear interpolation would have a kink here: one-sided velocities (2, -2, 6) and (-6, -4, 10).)
}

TEST(CameraPath, BadFilesNameTheFieldAndTheFix) {
  const json good = key(0, {0, 5, 0}, {0, 0, 10});
  EXPECT_NE(error_of(json::object()).find("path.json: keyframes: must be given (required)"),
            std::string::npos)
      << error_of(json::object());
  EXPECT_NE(error_of({{"keyframes", {good}}}).find("keyframes"), std::string::npos);
  const std::string order =
      error_of({{"keyframes", {good, key(2, {1, 1, 1}, {0, 0, 0}), key(1, {1, 2, 1}, {0, 0, 0})}}});
  EXPECT_NE(order.find("keyframes[2].t: must be greater than the previous keyframe's t"), std::string::npos)
      << order;
  const std::string start =
      error_of({{"keyframes", {key(1, {0, 5, 0}, {0, 0, 10}), key(2, {1, 1, 1}, {0, 0, 0})}}});
  EXPECT_NE(start.find("keyframes[0].t: must be 0"), std::string::npos) << start;
  const std::string aim = error_of({{"keyframes", {good, key(2, {1, 1, 1}, {1, 1, 1})}}});
  EXPECT_NE(aim.find("keyframes[1].look_at: must be different from position"), std::string::npos) << aim;
  const std::string missing = error_of({{"keyframes", {good, {{"t", 1}, {"position", {0, 1, 0}}}}}});
  EXPECT_NE(missing.find("keyframes[1].look_at: must be given"), std::string::npos) << missing;
  const std::string typo = error_of({{"keyframes", {good, key(1, {1, 1, 1}, {0, 0, 0})}}, {"keyframe", 1}});
  EXPECT_NE(typo.find("keyframe"), std::string::npos) << typo;
  EXPECT_NE(error_of(json::array()).find("is not a JSON object"), std::string::npos);
}

TEST(CameraPath, FilesAreReadLikeScenes) {
  test::TempDir dir;
  const Result<CameraPath> missing = load_camera_path(dir / "nope.json");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("file not found"), std::string::npos) << missing.error().message;
  { std::ofstream(dir / "broken.json") << "{\"keyframes\": ["; }
  const Result<CameraPath> broken = load_camera_path(dir / "broken.json");
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().message.find("invalid JSON"), std::string::npos) << broken.error().message;
  const Result<CameraPath> shipped =
      load_camera_path(std::string(LAGOON_SOURCE_DIR) + "/scenes/paths/evaluation.json");
  ASSERT_TRUE(shipped) << shipped.error().message;
  EXPECT_GE(shipped->duration_s(), 10.0);
  // The evaluation flies above the water, under it and back.
  bool above = false, below = false;
  for (double t = 0; t <= shipped->duration_s(); t += 0.5) {
    const float y = shipped->at(t, Camera{}).position.y;
    above |= y > 1, below |= y < -1;
  }
  EXPECT_TRUE(above && below);
  EXPECT_GT(shipped->at(shipped->duration_s(), Camera{}).position.y, 1.f);
}

}  // namespace
}  // namespace lagoon::scene
