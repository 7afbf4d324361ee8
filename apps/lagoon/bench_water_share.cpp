#include "bench_water_share.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "bench_report.h"
#include "optics/lut.h"
#include "render/ocean_renderer.h"
#include "render/water_luts.h"

namespace lagoon::cli {
namespace {

double pass_ms(const std::vector<vk::PassTime>& timings, const std::string& name) {
  for (const vk::PassTime& t : timings)
    if (t.name == name) return t.ms;
  return 0;
}

}  // namespace

WaterShare bench_water_share(vk::Context& ctx, const scene::Scene& scene, int rounds) {
  scene::Scene physical = scene, classic = scene;
  physical.render.shading = scene::Shading::Physical;
  classic.render.shading = scene::Shading::BlinnPhong;
  auto a = render::OceanRenderer::create(ctx, physical);
  auto b = render::OceanRenderer::create(ctx, classic);
  if (!a || !b) throw std::runtime_error(!a ? a.error().message : b.error().message);
  std::vector<vk::PassTime> timings;
  for (int w = 0; w < 2; ++w) (*a)->render(physical, &timings), (*b)->render(classic, &timings);
  std::vector<double> frame_a, frame_b, surface_a, surface_b, difference, share;
  for (int r = 0; r < rounds; ++r) {
    frame_a.push_back(time_ms([&] { (*a)->render(physical, &timings); }));
    surface_a.push_back(pass_ms(timings, "surface"));
    frame_b.push_back(time_ms([&] { (*b)->render(classic, &timings); }));
    surface_b.push_back(pass_ms(timings, "surface"));
    difference.push_back(frame_a.back() - frame_b.back());
    share.push_back(difference.back() / frame_a.back());
  }
  std::vector<double> lut;
  for (int r = 0; r < std::min(rounds, 5); ++r)
    lut.push_back(time_ms([&] {
      auto inputs = render::scene_lut_inputs(scene);
      if (inputs) (void)optics::build_water_lut(*inputs);
    }));
  std::printf("\nWater colour (physical shading against blinn-phong, alternated; wall time, medians)\n");
  std::printf("%-34s %12.3f\n", "frame, physical", median(frame_a));
  std::printf("%-34s %12.3f\n", "frame, blinn-phong", median(frame_b));
  std::printf("%-34s %12.3f  (%.1f %% of the frame)\n", "water colour per frame", median(difference),
              100 * median(share));
  std::printf("%-34s %12.3f / %.3f (GPU timestamps)\n", "surface pass, physical / classic", median(surface_a),
              median(surface_b));
  std::printf("%-34s %12.3f  (once per change of water, sun or sea)\n", "LUT build (CPU)", median(lut));
  WaterShare out{.rows = nlohmann::json::array(), .share = median(share), .per_frame_ms = median(difference)};
  nlohmann::json& rows = out.rows;
  rows.push_back(result_entry("render/water_colour/frame_physical", frame_a, "wall"));
  rows.push_back(result_entry("render/water_colour/frame_blinn_phong", frame_b, "wall"));
  rows.push_back(result_entry("render/water_colour/lut_build", lut, "wall"));
  return out;
}

}  // namespace lagoon::cli
