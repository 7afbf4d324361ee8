// lagoon export with vehicles: the wakes' layer and foam trails (wakes_height.npy, wakes_foam.npy) over the
// window meta.json names, against the CPU reference layer (compute/ocean/dynamic_layer.h, double precision)
// run here on the same hulls (world/vehicle_wakes.h) and window; and the poses of what moves, per frame, as
// lagoon probe --object prints them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/npy.h"
#include "ocean/dynamic_layer.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/run_process.h"
#include "support/temp_dir.h"
#include "world/vehicle_wakes.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

TEST(ExportWakes, TheLayerAndItsFoamMatchTheCpuReference) {
  TempDir dir;
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  const std::vector<std::string> overrides{R"(wakes={"resolution":128,"cell_size_m":0.5,"border_m":8})",
                                           "camera.position=[0,8,20]", "camera.look_at=[0,0,50]",
                                           R"(ocean.cascades=[{"patch_size_m":100,"resolution":64}])"};
  std::string command = shell_quote(LAGOON_BINARY) + " export --scene " + harbour + " --out " +
                        shell_quote((dir / "fields").string()) + " --frames 2 --t0 5 --dt 0.5";
  for (const std::string& o : overrides) command += " --set " + shell_quote(o);
  auto r = run_process(command);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream meta_file(dir / "fields" / "meta.json");
  const nlohmann::json meta = nlohmann::json::parse(meta_file);
  ASSERT_TRUE(meta.contains("wakes")) << meta.dump(2);
  auto height = io::read_npy(dir / "fields" / "wakes_height.npy");
  auto foam = io::read_npy(dir / "fields" / "wakes_foam.npy");
  ASSERT_TRUE(height && foam);
  EXPECT_EQ(height->shape, (std::vector<size_t>{2, 128, 128}));
  EXPECT_EQ(foam->shape, (std::vector<size_t>{2, 128, 128}));

  // The same layer on the CPU: the scene's hulls, the window meta.json gives, the same steps.
  auto scene = scene::load_scene(harbour, overrides);
  ASSERT_TRUE(scene) << scene.error().message;
  auto wakes = world::VehicleWakes::create(*scene);
  ASSERT_TRUE(wakes && !wakes->empty());
  ocean::DynamicLayerCpu cpu(wakes->params(), 2);
  const double cell = meta["wakes"]["cell_size_m"];
  const glm::ivec2 window(int(std::lround(meta["wakes"]["window_origin_m"][0].get<double>() / cell)),
                          int(std::lround(meta["wakes"]["window_origin_m"][1].get<double>() / cell)));
  EXPECT_EQ(window, wakes->window_for(scene->camera));
  cpu.set_window(window);
  long long step = wakes->first_step_for(5.0);
  for (int frame = 0; frame < 2; ++frame) {
    for (; step < wakes->step_at(5.0 + 0.5 * frame); ++step)
      cpu.step(wakes->step_s(), wakes->sources(double(step) * wakes->step_s()));
    double d2 = 0, n2 = 0, foam_error = 0, foam_total = 0;
    for (int j = 0; j < 128; ++j)
      for (int i = 0; i < 128; ++i) {
        const size_t at = (size_t(frame) * 128 + j) * 128 + i;
        const double h = cpu.height(window.x + i, window.y + j), f = cpu.foam(window.x + i, window.y + j);
        d2 += std::pow(height->data[at] - h, 2);
        n2 += h * h;
        foam_error = std::max(foam_error, std::abs(foam->data[at] - f));
        foam_total += f;
      }
    EXPECT_GT(n2, 0.1) << "no wake in the window at frame " << frame;
    EXPECT_LT(std::sqrt(d2 / n2), 1e-4) << "frame " << frame;
    EXPECT_GT(foam_total, 10.0) << "no trail in the window at frame " << frame;
    EXPECT_LT(foam_error, 1e-4) << "frame " << frame;
  }

  // The floating objects' and vehicles' poses at each frame, as lagoon probe --object gives them.
  ASSERT_TRUE(meta.contains("poses")) << meta.dump(2);
  const nlohmann::json& poses = meta["poses"]["frames"];
  ASSERT_EQ(poses.size(), 2u);
  const char* names[] = {"buoy", "moored boat", "boat", "auv"};
  for (size_t k = 0; k < 4; ++k) {
    const bool vehicle = k >= 2;
    std::string probe = shell_quote(LAGOON_BINARY) + " probe --scene " + harbour + " --object " +
                        shell_quote(names[k]) + " --time 5 --frames 2 --fps 2";
    for (const std::string& o : overrides) probe += " --set " + shell_quote(o);
    auto p = run_process(probe);
    ASSERT_EQ(p.exit_code, 0) << p.output;
    std::istringstream lines(p.output);
    std::string line;
    for (size_t frame = 0; frame < 2 && std::getline(lines, line); ++frame) {
      const nlohmann::json expected = nlohmann::json::parse(line), got = poses[frame][k];
      EXPECT_EQ(got[vehicle ? "vehicle" : "object"], names[k]);
      EXPECT_DOUBLE_EQ(got["time_s"].get<double>(), 5.0 + 0.5 * double(frame));
      for (const char* field : {"origin", "orientation_wxyz", "velocity_mps"})
        for (size_t i = 0; i < expected[field].size(); ++i)
          EXPECT_NEAR(got[field][i].get<double>(), expected[field][i].get<double>(), 1e-9)
              << names[k] << " " << field << " at frame " << frame;
    }
  }
  EXPECT_NEAR(poses[1][3]["origin"][1].get<double>(), -4.4, 1e-6) << "the AUV at its depth";
}

TEST(ExportWakes, ASceneWithoutVehiclesWritesNoWakesAndNoPoses) {
  TempDir dir;
  auto r = run_process(shell_quote(LAGOON_BINARY) + " export --scene " + std::string(LAGOON_SOURCE_DIR) +
                       "/scenes/default.json --out " + shell_quote((dir / "fields").string()) +
                       " --set 'ocean.cascades=[{\"patch_size_m\":100,\"resolution\":64}]'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "fields" / "wakes_height.npy"));
  std::ifstream meta_file(dir / "fields" / "meta.json");
  const nlohmann::json meta = nlohmann::json::parse(meta_file);
  EXPECT_FALSE(meta.contains("wakes"));
  EXPECT_FALSE(meta.contains("poses"));
}

}  // namespace
}  // namespace lagoon::test
