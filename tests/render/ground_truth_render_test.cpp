// The dataset's ground truth (dataset/ground_truth.h, lagoon render --aov): the depth at an object's pixels
// is the distance along the optical axis to the mesh that a ray through the pixel's centre meets, computed
// here by intersecting the ray with the box analytically (1 cm); every pixel whose ray hits the box well
// inside its faces is labelled with its object id; and the water mask agrees with the side of the surface the
// camera is on. The normal over the water is checked against WaveQuery in surface_normal_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <set>

#include "dataset/ground_truth.h"
#include "dataset/pinhole.h"
#include "optics/colour.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/edited_scene.h"
#include "support/gltf_quads.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

constexpr double kHalf = 1.0;  // the box's half-size (m)

// A closed cube of six quads, 2 kHalf wide, centred on its node.
std::vector<Quad> cube() {
  const double s = std::sqrt(0.5);
  const std::vector<std::pair<json, json>> faces = {
      {{0, 0, -kHalf}, {0, 0, 0, 1}}, {{0, 0, kHalf}, {0, 1, 0, 0}},   {{-kHalf, 0, 0}, {0, s, 0, s}},
      {{kHalf, 0, 0}, {0, -s, 0, s}}, {{0, -kHalf, 0}, {-s, 0, 0, s}}, {{0, kHalf, 0}, {s, 0, 0, s}}};
  std::vector<Quad> quads;
  for (const auto& [t, r] : faces)
    quads.push_back({.material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.3, 0.2, 1}}}},
                                  {"doubleSided", true}},
                     .translation = t,
                     .rotation = r,
                     .half = float(kHalf)});
  return quads;
}

// The distance along `d` from `o` to the axis-aligned box centred on `c` (slabs), or +inf.
double hit_box(glm::dvec3 o, glm::dvec3 d, glm::dvec3 c, double h, double* margin = nullptr) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double lo = (c[a] - h - o[a]) / d[a], hi = (c[a] + h - o[a]) / d[a];
    t0 = std::max(t0, std::min(lo, hi));
    t1 = std::min(t1, std::max(lo, hi));
  }
  if (t0 > t1) return std::numeric_limits<double>::infinity();
  if (margin) {  // how far inside the face's edges the hit point lies
    const glm::dvec3 p = o + t0 * d - c;
    double m = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
      if (std::abs(std::abs(p[a]) - h) > 1e-6) m = std::min(m, h - std::abs(p[a]));
    *margin = m;
  }
  return t0;
}

class GroundTruthRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_ground_truth_render"};

  dataset::GroundTruth ground_truth(const scene::Scene& s, world::CameraSide* side_out = nullptr) {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    const auto aov = (*renderer)->render_surface_aov(s, true);
    const world::CameraSide side = (*renderer)->camera_side(s, {s.render.width, s.render.height});
    if (side_out) *side_out = side;
    const double surface_y =
        (*renderer)->camera_medium().surface_height(s.camera.position.x, s.camera.position.z, s.time_s);
    return dataset::ground_truth(aov, s, side, surface_y);
  }
};

TEST_F(GroundTruthRender, DepthAtAnObjectsPixelsIsTheRayMeshDistance) {
  write_quads(dir_ / "cube.gltf", cube());
  json s = shipped_scene_json("default");
  const glm::dvec3 centre(1.5, 4.0, 12.0);
  s["camera"] = {{"position", {5, 7, -2}}, {"look_at", {0, 4, 12}}, {"fov_deg", 50}};
  s["render"].update({{"width", 160}, {"height", 90}});
  s["seafloor"] = {{"type", "none"}};
  s["objects"] = json::array(
      {json{{"name", "cube"}, {"file", "cube.gltf"}, {"position", {centre.x, centre.y, centre.z}}}});
  const scene::Scene scene = write_and_load(s, dir_ / "scene.json");
  const dataset::GroundTruth gt = ground_truth(scene);
  const dataset::Pinhole cam = dataset::pinhole(scene.camera, gt.width, gt.height);

  int object_pixels = 0, checked = 0, missed = 0, inside = 0, inside_labelled = 0;
  double worst = 0;
  for (uint32_t y = 0; y < gt.height; ++y)
    for (uint32_t x = 0; x < gt.width; ++x) {
      const size_t i = size_t{y} * gt.width + x;
      const glm::dvec3 ray = cam.ray(x, y);
      double margin = 0;
      const double t = hit_box(cam.position, ray, centre, kHalf, &margin);
      if (std::isfinite(t) && margin > 0.05) {
        ++inside;
        inside_labelled += gt.object_id[i] == 1.0f;
      }
      if (gt.object_id[i] != 1.0f) continue;
      ++object_pixels;
      if (!std::isfinite(t)) {
        ++missed;  // a pixel at the silhouette whose centre's ray just passes the box
        continue;
      }
      const double expected = t * glm::dot(ray, cam.forward());
      worst = std::max(worst, std::abs(double(gt.depth[i]) - expected));
      ++checked;
    }
  std::printf(
      "cube: %d object pixels, %d checked, worst depth error %.4f m; %d of %d inside pixels labelled\n",
      object_pixels, checked, worst, inside_labelled, inside);
  ASSERT_GT(checked, 200);
  EXPECT_LT(worst, 0.01);
  EXPECT_LE(missed, object_pixels / 20);
  EXPECT_EQ(inside_labelled, inside);
  // Its normals are the faces' axes.
  for (size_t i = 0; i < gt.object_id.size(); ++i)
    if (gt.object_id[i] == 1.0f) {
      const glm::dvec3 n(gt.normal[3 * i], gt.normal[3 * i + 1], gt.normal[3 * i + 2]);
      ASSERT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.0, 1e-3);
    }
}

// The harbour's wakes are off: they change the surface's shape, not which side of it a pixel is on, and
// replaying them for a still frame is most of its cost.
TEST_F(GroundTruthRender, TheWaterMaskFollowsTheSideOfTheSurfaceTheCameraIsOn) {
  struct Case {
    const char* scene;
    std::vector<std::string> overrides;
    world::CameraSide side;
    std::set<float> allowed, required;
  } cases[] = {
      {"harbour", {"wakes.enabled=false"}, world::CameraSide::Above, {0, 1}, {0, 1}},
      {"harbour",
       {"camera.position=[0,-3,0]", "camera.look_at=[4,-3,12]", "wakes.enabled=false"},
       world::CameraSide::Below,
       {1, 2},
       {1, 2}},
      {"waterline", {}, world::CameraSide::Waterline, {0, 1, 2}, {0, 1, 2}},
  };
  for (Case& c : cases) {
    c.overrides.insert(c.overrides.end(), {"render.width=96", "render.height=54"});
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + c.scene + ".json", c.overrides);
    ASSERT_TRUE(s) << s.error().message;
    world::CameraSide side;
    const dataset::GroundTruth gt = ground_truth(*s, &side);
    ASSERT_EQ(side, c.side) << c.scene;
    std::set<float> seen(gt.water_mask.begin(), gt.water_mask.end());
    for (float v : seen) EXPECT_TRUE(c.allowed.count(v)) << c.scene << ": water_mask " << v;
    for (float v : c.required) EXPECT_TRUE(seen.count(v)) << c.scene << ": no pixel with water_mask " << v;
    for (size_t i = 0; i < gt.water_mask.size(); ++i) {
      // Water pixels are the surface: finite depth, a normal that faces the camera's side of it.
      if (gt.water_mask[i] != 1.0f) continue;
      ASSERT_TRUE(std::isfinite(gt.depth[i])) << c.scene;
      ASSERT_EQ(gt.object_id[i], 0.0f) << c.scene;
    }
    if (c.side == world::CameraSide::Waterline) {  // the lens cuts the surface: air above, water below
      EXPECT_EQ(gt.water_mask[gt.width / 2], 0.0f);
      EXPECT_EQ(gt.water_mask[gt.water_mask.size() - gt.width / 2], 2.0f);
    }
  }
}

// Under the water the picture is the image formation model of the terms: the PNG's pixel is the display
// encoding (exposure, the tone curve of optics::tone_map, gamma) of clean · transmission + backscatter,
// except where the forward-scatter blur mixes in neighbours (edges of objects), so the check is on the bulk.
TEST_F(GroundTruthRender, UnderTheWaterThePictureIsCleanTimesTransmissionPlusBackscatter) {
  auto s = scene::load_scene(
      std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json",
      std::vector<std::string>{"render.width=128", "render.height=72", "camera.position=[0,-3,0]",
                               "camera.look_at=[4,-3.5,12]", "wakes.enabled=false"});
  ASSERT_TRUE(s) << s.error().message;
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const io::Image8 image = (*renderer)->render(*s);
  dataset::GroundTruth gt =
      dataset::ground_truth((*renderer)->render_surface_aov(*s, true), *s, world::CameraSide::Below, 0.0);
  dataset::add_underwater_terms(gt, (*renderer)->render_underwater_terms(*s));
  optics::ToneMapParams tone;
  tone.world_adaptation_luminance = s->render.tone_map_adaptation;
  tone.white_luminance = s->render.tone_map_white;
  std::vector<double> errors, errors_unattenuated;
  double t_min = 1, t_max = 0, b_max = 0;
  for (size_t i = 0; i < gt.water_mask.size(); ++i) {
    if (gt.water_mask[i] != 2.0f || gt.object_id[i] == 0.0f)
      continue;  // the floor and objects, through water
    const glm::dvec3 j(gt.clean[3 * i], gt.clean[3 * i + 1], gt.clean[3 * i + 2]),
        t(gt.transmission[3 * i], gt.transmission[3 * i + 1], gt.transmission[3 * i + 2]),
        b(gt.backscatter[3 * i], gt.backscatter[3 * i + 1], gt.backscatter[3 * i + 2]);
    auto encode = [&](glm::dvec3 radiance) {
      const glm::dvec3 mapped = optics::tone_map(radiance * double(s->render.exposure), tone);
      return 255.0 * glm::pow(glm::clamp(mapped, 0.0, 1.0), glm::dvec3(1.0 / s->render.gamma));
    };
    const glm::dvec3 drawn(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
    errors.push_back(glm::length(encode(j * t + b) - drawn));
    errors_unattenuated.push_back(glm::length(encode(j + b) - drawn));
    t_min = std::min(t_min, std::min({t.x, t.y, t.z}));
    t_max = std::max(t_max, std::max({t.x, t.y, t.z}));
    b_max = std::max(b_max, std::max({b.x, b.y, b.z}));
  }
  ASSERT_GT(errors.size(), 2000u);
  std::sort(errors.begin(), errors.end());
  std::sort(errors_unattenuated.begin(), errors_unattenuated.end());
  const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
  std::printf(
      "%zu pixels through water: |encode(J T + B) - PNG| median %.2f, 90th %.2f levels (J + B: median "
      "%.1f); transmission %.3f..%.3f, backscatter up to %.3f\n",
      errors.size(), median, p90, errors_unattenuated[errors.size() / 2], t_min, t_max, b_max);
  EXPECT_LT(median, 1.5);
  EXPECT_LT(p90, 4.0);
  // The terms are not trivial: the water takes away and adds visibly.
  EXPECT_GT(errors_unattenuated[errors.size() / 2], 10.0);
  EXPECT_LT(t_min, 0.5);
  EXPECT_GT(b_max, 0.0);
}

// A dataset draws the underwater terms right after the picture of the same frame, whose caustic map and
// refraction they reuse: the terms are those a renderer that drew nothing before gives, and a picture of
// another view is not reused.
TEST_F(GroundTruthRender, TheTermsReuseThePicturesViewsOnlyWhenTheyAreOfTheSameFrame) {
  const std::vector<std::string> below = {"render.width=64", "render.height=36", "camera.position=[0,-3,0]",
                                          "camera.look_at=[4,-3.5,12]", "wakes.enabled=false"};
  std::vector<std::string> turned = below;
  turned[3] = "camera.look_at=[-6,-4,8]";
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  auto s = scene::load_scene(harbour, below);
  auto other = scene::load_scene(harbour, turned);
  ASSERT_TRUE(s && other);
  auto terms_alone = [&](const scene::Scene& scene) {
    auto fresh = render::OceanRenderer::create(ctx(), scene);
    EXPECT_TRUE(fresh) << fresh.error().message;
    return (*fresh)->render_underwater_terms(scene);
  };
  auto drew = [](const render::OceanRenderer& r, const std::string& pass) {
    const auto times = r.timings(0);
    return std::any_of(times.begin(), times.end(), [&](const vk::PassTime& t) { return t.name == pass; });
  };
  // The largest difference between two frames' terms, relative to the largest term.
  auto difference = [](const render::OceanRenderer::UnderwaterTerms& a,
                       const render::OceanRenderer::UnderwaterTerms& b) {
    double most = 0, largest = 1e-9;
    for (const auto& [x, y] : {std::pair{&a.clean, &b.clean}, std::pair{&a.transmission, &b.transmission},
                               std::pair{&a.backscatter, &b.backscatter}})
      for (size_t i = 0; i < x->size(); ++i)
        for (int c = 0; c < 3; ++c) {
          most = std::max(most, double(std::abs((*x)[i][c] - (*y)[i][c])));
          largest = std::max(largest, double(std::abs((*x)[i][c])));
        }
    return most / largest;
  };
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  (*renderer)->render(*s);
  (*renderer)->render_surface_aov(*s, true);
  const auto reused = (*renderer)->render_underwater_terms(*s);
  EXPECT_FALSE(drew(**renderer, "refraction")) << "the picture's refraction is drawn again";
  EXPECT_FALSE(drew(**renderer, "caustics"));
  const auto alone = terms_alone(*s);
  const double same = difference(reused, alone);
  // The picture of another view: its refraction is not this frame's.
  (*renderer)->render(*other);
  const auto redrawn = (*renderer)->render_underwater_terms(*s);
  EXPECT_TRUE(drew(**renderer, "refraction"));
  const double after_other = difference(redrawn, alone);
  const double views_differ = difference(terms_alone(*other), alone);
  std::printf(
      "terms reused: %.2e of the largest term from those drawn alone; after another view's picture "
      "%.2e; the two views' terms differ by %.2f\n",
      same, after_other, views_differ);
  EXPECT_LT(same, 1e-5);
  EXPECT_LT(after_other, 1e-5);
  EXPECT_GT(views_differ, 0.1);  // the check can see a wrong view
}

}  // namespace
}  // namespace lagoon::test
