// The wakes in the drawn surface (engine/render/passes/wakes_pass.h): a boat crossing a calm bay leaves waves
// whose slopes, read back per pixel from the surface pass's ground truth (OceanRenderer::render_surface_aov),
// are the CPU reference layer's (compute/ocean/dynamic_layer.h, double precision, run here on the same
// hulls) plus the sea's own (WaveQuery) at the same world points.
// Slopes, because the shading normal samples the layer per pixel, while heights reach the picture through
// the surface mesh's vertices, a cell up to 1/12 of the distance apart (render/surface_grid.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "ocean/dynamic_layer.h"
#include "ocean/wave_query.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

class WakesRender : public GpuTest {};

scene::Scene calm_bay_with_a_boat() {
  const std::vector<std::string> overrides{
      "render.width=320", "render.height=180", "time_s=9", "camera.position=[0,14,-6]",
      "camera.look_at=[0,0,22]", "objects=[]",
      // A sea of long waves only: one coarse cascade (6 m texels) of a light breeze.
      "ocean.spectrum.wind_speed_mps=0.5", R"(ocean.cascades=[{"patch_size_m":400,"resolution":64}])",
      R"(vehicles=[{"name":"boat","file":"assets/boat.gltf","path":{"waypoints":[[-40,20],[40,20]],"speed_mps":5,"loop":false}}])",
      R"(wakes={"resolution":256,"cell_size_m":0.25,"step_s":0.1,"history_s":30})"};
  return shipped_scene("default", overrides);
}

// The CPU layer's slope at world (x, z): central differences at the cells, interpolated bilinearly (as the
// GPU's fields are sampled); cell a holds x = a · cell.
glm::dvec2 layer_slope(const ocean::DynamicLayerCpu& layer, double x, double z) {
  const double cell = layer.params().cell_m;
  auto at = [&](int a, int b) {
    return glm::dvec2(layer.height(a + 1, b) - layer.height(a - 1, b),
                      layer.height(a, b + 1) - layer.height(a, b - 1)) /
           (2 * cell);
  };
  const double u = x / cell, v = z / cell;
  const int a = int(std::floor(u)), b = int(std::floor(v));
  const double fu = u - a, fv = v - b;
  return (1 - fu) * (1 - fv) * at(a, b) + fu * (1 - fv) * at(a + 1, b) + (1 - fu) * fv * at(a, b + 1) +
         fu * fv * at(a + 1, b + 1);
}

glm::dvec2 slope_of(const glm::dvec4& n) {
  return {-n.x / n.y, -n.z / n.y};
}

TEST_F(WakesRender, TheShadedSurfaceCarriesTheReferenceLayersSlopes) {
  const scene::Scene with = calm_bay_with_a_boat();
  auto a = render::OceanRenderer::create(ctx(), with);
  ASSERT_TRUE(a) << a.error().message;
  const render::OceanRenderer::SurfaceAov waked = (*a)->render_surface_aov(with);

  const render::WakesPass& wakes = (*a)->wakes();
  ASSERT_TRUE(wakes.active());

  // The same steps on the CPU: the renderer's window, from time 0 (history_s is longer than 9 s).
  const ocean::DynamicLayerGpu& gpu = *wakes.layer();
  ocean::DynamicLayerCpu cpu(gpu.params(), 2);
  cpu.set_window(gpu.window());
  for (int step = 0; step < 90; ++step) cpu.step(0.1, wakes.sources(step * 0.1));

  const glm::vec4 window = wakes.window();
  const glm::dvec2 hull = wakes.sources(with.time_s)[0].centre;
  const double border = with.wakes.border_m;
  std::vector<glm::dvec2> points, drawn, wake;
  for (uint32_t y = 0; y < waked.height; ++y)
    for (uint32_t x = 0; x < waked.width; ++x) {
      const glm::vec4 p = waked.world_at(x, y);
      if (p.w < 0.5) continue;
      if (p.x < window.x + border || p.z < window.y + border || p.x > window.x + window.z - border ||
          p.z > window.y + window.z - border)
        continue;  // outside the window's interior
      // Not under the hull (drawn over it in a frame; here its steep depression, where the mesh's facets
      // and the layer's cells are of a size, is left out).
      if (glm::length(glm::dvec2(p.x, p.z) - hull) < 4.0) continue;
      points.emplace_back(p.x, p.z);
      drawn.push_back(slope_of(glm::dvec4(waked.normal_at(x, y))));
      wake.push_back(layer_slope(cpu, p.x, p.z));
    }
  // The sea's own slopes there: only waves longer than 12 m are left (one coarse cascade), which no mip
  // filters at these distances, so WaveQuery's exact ones are what the shader sums.
  ocean::WaveQuery sea(with.ocean);
  const std::vector<ocean::WaveSample> own = sea.sample(with.time_s, points);
  double err2 = 0, ref2 = 0, sea2 = 0;
  const int count = int(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::dvec2 sea_slope = slope_of(glm::dvec4(own[i].normal, 0.0));
    const glm::dvec2 error = drawn[i] - (wake[i] + sea_slope);
    err2 += glm::dot(error, error);
    ref2 += glm::dot(wake[i], wake[i]);
    sea2 += glm::dot(sea_slope, sea_slope);
  }
  RecordProperty("sea_rms_slope", std::to_string(std::sqrt(sea2 / count)));
  ASSERT_GT(count, 2000);
  const double relative = std::sqrt(err2 / ref2), rms = std::sqrt(ref2 / count);
  RecordProperty("wake_rms_slope", std::to_string(rms));
  RecordProperty("relative_rms_error", std::to_string(relative));
  RecordProperty("pixels", std::to_string(count));
  EXPECT_GT(rms, 0.01) << "no wake where the camera looks: nothing was compared";
  EXPECT_LT(relative, 0.05);
}

// A sequence (History::Sequence) carries the layer and the sea's foam from frame to frame, never starting
// them again however far apart its frames are, and a renderer that only advance()s through the frames it does
// not draw has the same bits at the one it draws: how shards agree (docs/datasets.md).
TEST_F(WakesRender, ASequenceCarriesTheLayerAndAdvancingWithoutDrawingGivesTheSameBits) {
  scene::Scene s = calm_bay_with_a_boat();
  s.render.width = 64;
  s.render.height = 36;
  s.wakes.history_s = 2.0f;  // 20 steps of 0.1 s
  s.ocean.spectrum.wind_speed_mps = 14.0f;
  s.ocean.foam.threshold = 0.9;  // each cascade's own foam (the state a step carries) where it compresses
  s.ocean.cascades = {{.patch_size_m = 400.0, .resolution = 64},
                      {.patch_size_m = 60.0, .resolution = 64},
                      {.patch_size_m = 8.0, .resolution = 64}};
  auto layer_bits = [&](const render::OceanRenderer& r) {
    std::vector<std::byte> bits = vk::readback_buffer(ctx(), r.wakes().layer()->state());
    const std::vector<std::byte> foam = vk::readback_buffer(ctx(), r.wakes().layer()->foam());
    bits.insert(bits.end(), foam.begin(), foam.end());
    return bits;
  };
  auto drawn = render::OceanRenderer::create(ctx(), s);
  auto advanced = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(drawn && advanced) << (drawn ? advanced.error().message : drawn.error().message);
  (*drawn)->set_history(render::OceanRenderer::History::Sequence);
  (*advanced)->set_history(render::OceanRenderer::History::Sequence);
  const render::WakesPass& wakes = (*drawn)->wakes();
  ASSERT_TRUE(wakes.active());
  // (time, steps taken in all): 3.0 s runs steps 10-29 from rest; 3.2 and 4.5 s step on, although 4.5 s
  // is 13 steps ahead (more than a live frame's 8, which would start again from rest at step 25).
  const std::vector<std::pair<float, long long>> frames{{3.0f, 20}, {3.2f, 22}, {4.5f, 35}};
  for (size_t i = 0; i < frames.size(); ++i) {
    s.time_s = frames[i].first;
    (*drawn)->render(s);
    EXPECT_EQ(wakes.steps_taken(), frames[i].second) << "at " << s.time_s << " s";
    if (i + 1 < frames.size()) (*advanced)->advance(s);
  }
  (*advanced)->render(s);
  EXPECT_EQ((*advanced)->wakes().steps_taken(), 35);
  EXPECT_TRUE(layer_bits(**drawn) == layer_bits(**advanced)) << "advancing left another layer than drawing";
  const std::vector<float> foam = (*drawn)->ocean().read_foam();
  EXPECT_GT(*std::max_element(foam.begin(), foam.end()), 0.1f) << "no foam: nothing was compared";
  EXPECT_TRUE(foam == (*advanced)->ocean().read_foam()) << "advancing left other foam than drawing";
  // A renderer that starts at 4.5 s runs from rest 2 s before it: another layer.
  auto fresh = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(fresh);
  (*fresh)->set_history(render::OceanRenderer::History::Sequence);
  (*fresh)->render(s);
  EXPECT_EQ((*fresh)->wakes().steps_taken(), 20);
  EXPECT_FALSE(layer_bits(**drawn) == layer_bits(**fresh));
}

// A live renderer (History::Continuous) whose frames are further apart than the steps a frame records steps
// the layer on to them as a sequence does, as long as that is no longer than starting again from rest: a slow
// device's frames would otherwise each replay the whole history. Further ahead it starts again, as a fresh
// renderer does.
TEST_F(WakesRender, ALiveFrameFarAheadStepsOnUnlessStartingAgainIsShorter) {
  scene::Scene s = calm_bay_with_a_boat();
  s.render.width = 48;
  s.render.height = 27;
  s.wakes.history_s = 2.0f;  // 20 steps of 0.1 s
  auto state = [&](const render::OceanRenderer& r) {
    return vk::readback_buffer(ctx(), r.wakes().layer()->state());
  };
  auto live = render::OceanRenderer::create(ctx(), s);
  auto sequence = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(live && sequence) << (live ? sequence.error().message : live.error().message);
  (*sequence)->set_history(render::OceanRenderer::History::Sequence);
  ASSERT_TRUE((*live)->wakes().active());
  // (time, steps taken in all): 3.0 s runs steps 10-29 from rest; 4.5 s is 15 steps ahead, more than a
  // frame's 8 and fewer than the history's 20: it steps on, as the sequence does.
  for (const auto& [time, steps] : std::vector<std::pair<float, long long>>{{3.0f, 20}, {4.5f, 35}}) {
    s.time_s = time;
    (*live)->render(s);
    (*sequence)->render(s);
    EXPECT_EQ((*live)->wakes().steps_taken(), steps) << "at " << time << " s";
  }
  EXPECT_TRUE(state(**live) == state(**sequence)) << "stepping on left another layer than the sequence's";
  // 8.0 s is 35 steps ahead: starting again 20 steps before it is shorter, and gives a fresh renderer's bits.
  s.time_s = 8.0f;
  (*live)->render(s);
  EXPECT_EQ((*live)->wakes().steps_taken(), 55);
  auto fresh = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(fresh);
  (*fresh)->render(s);
  EXPECT_EQ((*fresh)->wakes().steps_taken(), 20);
  EXPECT_TRUE(state(**live) == state(**fresh))
      << "a jump past the history left another layer than a fresh one";
}

}  // namespace
}  // namespace lagoon::test
