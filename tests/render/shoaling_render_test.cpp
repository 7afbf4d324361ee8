// Waves over the floor as drawn (issue 37): the beach scene's surface, read back per pixel
// (OceanRenderer::render_surface_aov), against WaveQuery's height at the same world point (the same table in
// double, ocean/shoaling.h): one surface for the renderer, probes, bodies and datasets. The comparison would
// also pass if neither transformed the waves, so it is checked to tell the beach from the untransformed sea.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "ocean/wave_query.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

struct HeightError {
  double rms = 0, worst = 0, rms_untransformed = 0;
  int pixels = 0;
};

class ShoalingRender : public GpuTest {
 protected:
  // Looking down on the surf zone and the slope beyond it from 25 m up.
  HeightError compare(const std::vector<std::string>& extra) {
    std::vector<std::string> o{"render.width=240", "render.height=135", "camera.position=[0,25,30]",
                               "camera.look_at=[0,0,110]", "time_s=5"};
    o.insert(o.end(), extra.begin(), extra.end());
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/beach.json", o);
    EXPECT_TRUE(s) << s.error().message;
    auto renderer = render::OceanRenderer::create(ctx(), *s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    const auto aov = (*renderer)->render_surface_aov(*s);
    ocean::WaveQuery query(s->ocean);
    scene::Scene flat = *s;
    flat.ocean.shoaling = false;
    ocean::WaveQuery untransformed(flat.ocean);
    std::vector<glm::dvec2> points;
    std::vector<double> drawn;
    for (uint32_t y = 0; y < aov.height; y += 2)
      for (uint32_t x = 0; x < aov.width; x += 2) {
        const glm::vec4 w = aov.world_at(x, y);
        // The water within 120 m, where the mesh's triangles are well under a metre.
        if (w.w < 0.5f || glm::length(glm::vec3(w) - s->camera.position) > 120.f) continue;
        points.emplace_back(w.x, w.z);
        drawn.push_back(w.y);
      }
    const std::vector<ocean::WaveSample> a = query.sample(s->time_s, points);
    const std::vector<ocean::WaveSample> b = untransformed.sample(s->time_s, points);
    HeightError e;
    double sum = 0, sum_b = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const double d = drawn[i] - a[i].height;
      sum += d * d;
      sum_b += (drawn[i] - b[i].height) * (drawn[i] - b[i].height);
      e.worst = std::max(e.worst, std::abs(d));
    }
    e.pixels = int(points.size());
    e.rms = std::sqrt(sum / std::max<size_t>(points.size(), 1));
    e.rms_untransformed = std::sqrt(sum_b / std::max<size_t>(points.size(), 1));
    std::printf("beach: %d pixels, rms %.4f m, worst %.4f m; against the untransformed sea rms %.3f m\n",
                e.pixels, e.rms, e.worst, e.rms_untransformed);
    return e;
  }
};

TEST_F(ShoalingRender, TheDrawnSurfaceIsWaveQuerysOverTheFloor) {
  const HeightError e = compare({});
  EXPECT_GT(e.pixels, 3000);
  // The mesh's triangles and its filtering of the wind sea's short waves (mips for the cascades, a fade for
  // summed waves) leave 5.3 cm rms and 23 cm at worst with or without the floor (next test); the floor adds
  // 0.3 cm rms.
  EXPECT_LT(e.rms, 0.08);
  EXPECT_LT(e.worst, 0.35);
  // The waves over the slope are not the deep sea's: the comparison can tell them apart.
  EXPECT_GT(e.rms_untransformed, 5 * e.rms);
}

// The random sea alone, a long-crested swell of the FFT ocean: its cascades' lattices, moved over the floor
// (ocean/random_sea.h), are drawn where WaveQuery has them, and not where the deep sea has them.
TEST_F(ShoalingRender, TheRandomSeasMovedLatticesAreDrawnAsWaveQueryHasThem) {
  const std::vector<std::string> swell{"ocean.swell_waves=[]", "ocean.spectrum.wind_speed_mps=10",
                                       "ocean.spectrum.fetch_km=200", "ocean.spectrum.swell=1",
                                       "ocean.spectrum.wind_direction_deg=30"};
  const HeightError e = compare(swell);
  std::vector<std::string> off = swell;
  off.push_back("ocean.shoaling=false");
  const HeightError deep = compare(off);
  EXPECT_GT(e.pixels, 3000);
  // The mesh and its filtering of this larger sea leave more than the beach's 5 cm; the moved lattices add
  // little to it.
  EXPECT_LT(e.rms, 1.25 * deep.rms + 0.01);
  EXPECT_GT(e.rms_untransformed, 5 * e.rms);
}

TEST_F(ShoalingRender, ShoalingOffDrawsTheUntransformedSea) {
  const HeightError e = compare({"ocean.shoaling=false"});
  EXPECT_LT(e.rms, 0.08);
  EXPECT_LT(e.rms_untransformed, 0.08);
}

// At the waterline the water is centimetres deep: seen from the shore it shows the sand under it (or the
// shore's foam), never the blue of deep water. The refraction pass once left the dry sand out of its target,
// so the water's refracted lookups beside it found nothing there and drew blue-grey notches every few dozen
// pixels along the beach. Per column: the water pixel just above the first dry sand from the bottom.
TEST_F(ShoalingRender, TheWaterAtTheWaterlineIsNeverDeepBlue) {
  const std::vector<std::string> size{"render.width=480", "render.height=270"};
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/beach.json", size);
  ASSERT_TRUE(s) << s.error().message;
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const io::Image8 image = (*renderer)->render(*s);
  auto rgb = [&](uint32_t x, uint32_t y) {
    const uint8_t* p = &image.rgba[(size_t{y} * image.width + x) * 4];
    return glm::ivec3(p[0], p[1], p[2]);
  };
  int columns = 0, blue = 0;
  for (uint32_t x = 0; x < image.width; ++x) {
    uint32_t y = image.height - 1;
    auto sand = [&](glm::ivec3 c) { return c.r > c.b + 15; };  // brown: red over blue
    if (!sand(rgb(x, y))) continue;
    while (y > 0 && sand(rgb(x, y - 1))) --y;
    if (y == 0) continue;
    ++columns;
    const glm::ivec3 water = rgb(x, y - 1);
    if (water.b > water.r + 15) ++blue;
  }
  RecordProperty("columns", columns);
  RecordProperty("deep_blue_at_the_waterline", blue);
  EXPECT_GT(columns, int(image.width) * 9 / 10) << "the sand does not reach the water across the frame";
  EXPECT_EQ(blue, 0) << "of " << columns << " columns";
}

}  // namespace
}  // namespace lagoon::test
