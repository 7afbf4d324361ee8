// End-to-end: lagoon export and probe, their files and errors, and bad ocean parameters on every command.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "io/npy.h"
#include "ocean/cpu_step.h"
#include "ocean/gerstner.h"
#include "ocean/perlin.h"
#include "ocean/sines.h"
#include "ocean/springs.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/direct_sum.h"
#include "support/fftw_reference.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

const std::string kSmallOcean =
    "--set "
    "'ocean.cascades=[{\"patch_size_m\":300,\"resolution\":64},{\"patch_size_m\":30,\"resolution\":64}]'";

const std::vector<std::string> kSmallOceanOverride{
    "ocean.cascades=[{\"patch_size_m\":300,\"resolution\":64},{\"patch_size_m\":30,\"resolution\":64}]"};

// One JSON object per line, as lagoon probe prints them (the output holds stderr too: its "lagoon probe:
// note: ..." lines are not the probe's answers).
std::vector<nlohmann::json> json_lines(const std::string& output) {
  std::istringstream lines(output);
  std::vector<nlohmann::json> out;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("lagoon probe: note: ", 0) != 0) out.push_back(nlohmann::json::parse(line));
  return out;
}

TEST(OceanCli, ExportWritesTheGpuFieldsInTheDocumentedLayout) {
  TempDir dir;
  const fs::path out = dir / "fields";
  auto r = lagoon("export --scene " + kDefaultScene + " --out " + out.string() +
                  " --frames 2 --dt 0.5 --t0 1.25 " + kSmallOcean);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream meta_file(out / "meta.json");
  const auto meta = nlohmann::json::parse(meta_file);
  EXPECT_EQ(meta["format_version"], 1);
  EXPECT_EQ(meta["times_s"], nlohmann::json({1.25, 1.75}));
  ASSERT_EQ(meta["cascades"].size(), 2u);
  EXPECT_NEAR(meta["cascades"][0]["k_max_rad_per_m"].get<double>(), M_PI * 64 / (2 * 300.0), 1e-12);
  EXPECT_EQ(meta["cascades"][1]["k_min_rad_per_m"], meta["cascades"][0]["k_max_rad_per_m"]);

  // The same scene through the CPU reference: the exported arrays must be its fields, [frame][z][x][c].
  auto scene = scene::load_scene(kDefaultScene, kSmallOceanOverride);
  ASSERT_TRUE(scene) << scene.error().message;
  std::vector<ocean::CascadeSpectrum> spectra;
  for (uint32_t c = 0; c < 2; ++c) spectra.push_back(ocean::make_cascade_spectrum(scene->ocean, c));
  ocean::CpuOceanStep cpu(
      scene->ocean, spectra,
      [](std::vector<std::complex<double>>& d, uint32_t n, uint32_t b) { fftw_2d(d, int(n), int(b), true); });
  cpu.step(1.25, 0.0);
  cpu.step(1.75, 0.5);
  for (int c = 0; c < 2; ++c) {
    const std::string prefix = "cascade" + std::to_string(c);
    auto disp = io::read_npy(out / (prefix + "_displacement.npy"));
    auto foam = io::read_npy(out / (prefix + "_foam.npy"));
    auto jac = io::read_npy(out / (prefix + "_jacobian.npy"));
    auto normal = io::read_npy(out / (prefix + "_normal.npy"));
    ASSERT_TRUE(disp && foam && jac && normal);
    EXPECT_EQ(disp->shape, (std::vector<size_t>{2, 64, 64, 3}));
    EXPECT_EQ(normal->shape, (std::vector<size_t>{2, 64, 64, 3}));
    EXPECT_EQ(jac->shape, (std::vector<size_t>{2, 64, 64}));
    EXPECT_EQ(foam->shape, (std::vector<size_t>{2, 64, 64}));
    const auto& ref = cpu.cascades()[c];
    double diff = 0, norm = 0, jdiff = 0, jnorm = 0;
    const size_t frame1 = 64 * 64;
    for (size_t i = 0; i < frame1; ++i) {
      for (int k = 0; k < 3; ++k) {
        diff += std::pow(disp->data[(frame1 + i) * 3 + k] - ref.displacement[4 * i + k], 2);
        norm += std::pow(ref.displacement[4 * i + k], 2);
      }
      jdiff += std::pow(jac->data[frame1 + i] - ref.normal_jacobian[4 * i + 3], 2);
      jnorm += std::pow(ref.normal_jacobian[4 * i + 3], 2);
    }
    EXPECT_LT(std::sqrt(diff / norm), 1e-5) << prefix;
    EXPECT_LT(std::sqrt(jdiff / jnorm), 1e-5) << prefix;
  }
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename(), "fields") << "staging folder left behind";
}

TEST(OceanCli, ExportErrorsLeaveNothing) {
  TempDir dir;
  const std::string out = (dir / "fields").string();
  struct Case {
    std::string args, expected;
    int code;
  } cases[] = {
      {"--frames 0", "--frames 0", 2},
      {"--dt -1", "--dt -1", 2},
      {"--set ocean.cascades='[{\"patch_size_m\":100,\"resolution\":300}]'", "ocean.cascades[0].resolution",
       1},
      {"--set ocean.spectrum.wind_speed_mps=-2", "ocean.spectrum.wind_speed_mps", 1},
      {"--set ocean.spectrum.type=jonswep", "did you mean 'jonswap'", 1},
      {"--set ocean.spectrum.fetch_km=0", "ocean.spectrum.fetch_km", 1},
  };
  for (const Case& c : cases) {
    auto r = lagoon("export --scene " + kDefaultScene + " --out " + out + " " + c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    if (c.code == 1) {
      EXPECT_NE(r.output.find("default.json"), std::string::npos) << r.output;  // the file is named
    }
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
  { std::ofstream(dir / "file") << "x"; }
  auto r = lagoon("export --scene " + kDefaultScene + " --out " + (dir / "file").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("not a folder"), std::string::npos) << r.output;
}

TEST(OceanCli, ProbePrintsOneJsonObjectPerPointMatchingTheExactSum) {
  auto r = lagoon("probe --scene " + kDefaultScene + " --time 2.5 --at 0,0 --at 17.5,-3.25 " + kSmallOcean +
                  " --set ocean.choppiness=0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto scene = scene::load_scene(kDefaultScene, kSmallOceanOverride);
  std::vector<ocean::CascadeSpectrum> spectra;
  for (uint32_t c = 0; c < 2; ++c) spectra.push_back(ocean::make_cascade_spectrum(scene->ocean, c));
  std::istringstream lines(r.output);
  std::string line;
  int count = 0;
  const double xs[] = {0, 17.5}, zs[] = {0, -3.25};
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    for (const char* key :
         {"x", "z", "time_s", "height_m", "normal", "velocity_mps", "error_bound_m", "converged"})
      EXPECT_TRUE(j.contains(key)) << key << " in " << line;
    EXPECT_EQ(j["x"].get<double>(), xs[count]);
    const double exact = direct_sum(spectra, ocean::Field::Height, 2.5, xs[count], zs[count]);
    EXPECT_LE(std::abs(j["height_m"].get<double>() - exact), j["error_bound_m"].get<double>()) << line;
    ++count;
  }
  EXPECT_EQ(count, 2);
}

TEST(OceanCli, ProbeUsageErrors) {
  for (const char* args : {"--time 1 --at 3", "--time soon --at 1,2", "--time 1 --at 1,2,3x", "--at 1,2"}) {
    auto r = lagoon(std::string("probe --scene ") + kDefaultScene + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  }
  // Positions and times beyond what a double resolves (issue 11: 1e30 answered "converged").
  for (const char* args : {"--time 1 --at 1e30,5", "--time 1 --at 5,-5e9", "--time 1e10 --at 1,2"}) {
    auto r = lagoon(std::string("probe --scene ") + kDefaultScene + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("is beyond ±4294967296"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("resolved only to"), std::string::npos) << r.output;
  }
  auto near_limit = lagoon("probe --scene " + kDefaultScene + " --time 1e9 --at 4e9,-4e9 " + kSmallOcean);
  EXPECT_EQ(near_limit.exit_code, 0) << near_limit.output;
  auto r = lagoon("probe --scene " + kDefaultScene + " --time 1 --at 1,2 --set ocean.depth_m=-5");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("ocean.depth_m"), std::string::npos) << r.output;
}

const std::string kFloatingBuoy =
    R"( --set 'objects=[{"name":"buoy","file":"assets/buoy.gltf","position":[2,0,12],"floating":{"enabled":true,)"
    R"("density_kg_m3":400,"centre_of_mass_offset":[0,-0.6,0]}}]')";

TEST(OceanCli, ProbeObjectPrintsAFloatingObjectsPoseFrameByFrame) {
  const std::string command =
      "probe --scene " + kDefaultScene + " --time 2 --object buoy --frames 3" + kFloatingBuoy;
  auto r = lagoon(command);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    for (const char* key : {"object", "time_s", "origin", "orientation_wxyz", "centre_of_mass",
                            "velocity_mps", "angular_velocity_radps"})
      EXPECT_TRUE(j.contains(key)) << key << " in " << line;
    EXPECT_NEAR(j["time_s"].get<double>(), 2.0 + count / 30.0, 1e-12);
    const auto q = j["orientation_wxyz"];
    EXPECT_NEAR(std::hypot(std::hypot(q[0].get<double>(), q[1].get<double>()),
                           std::hypot(q[2].get<double>(), q[3].get<double>())),
                1.0, 1e-9)
        << "not a unit quaternion: " << line;
    ++count;
  }
  EXPECT_EQ(count, 3);
  EXPECT_EQ(lagoon(command).output, r.output) << "not deterministic";
}

TEST(OceanCli, ProbeObjectErrorsNameTheFix) {
  const std::string scene = "probe --scene " + kDefaultScene + " --time 1 ";
  auto r = lagoon(scene + "--object boat");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("objects[1] \"boat\" does not float; set objects[1].floating.enabled"),
            std::string::npos)
      << r.output;
  r = lagoon(scene + "--object dinghy");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no object or vehicle is named \"dinghy\"; the scene's: \"buoy\", \"boat\""),
            std::string::npos)
      << r.output;
  EXPECT_EQ(lagoon(scene + "--object buoy --at 1,2").exit_code, 2);
  EXPECT_EQ(lagoon(scene + "--object buoy --frames 0").exit_code, 2);
}

// The harbour's vehicles: the AUV runs level at its depth on its path; the boat at the surface moves at its
// path's speed while the water heaves it.
TEST(OceanCli, ProbeObjectPrintsAVehiclesPose) {
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  auto r = lagoon("probe --scene " + harbour + " --time 3 --object auv --frames 2 --fps 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  std::vector<nlohmann::json> auv;
  while (std::getline(lines, line)) auv.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(auv.size(), 2u);
  EXPECT_EQ(auv[0]["vehicle"], "auv");
  for (const auto& j : auv) EXPECT_NEAR(j["origin"][1].get<double>(), -4.4, 1e-6) << j;
  const double moved = std::hypot(auv[1]["origin"][0].get<double>() - auv[0]["origin"][0].get<double>(),
                                  auv[1]["origin"][2].get<double>() - auv[0]["origin"][2].get<double>());
  EXPECT_NEAR(moved, 1.5, 0.05);  // 1.5 m/s, one second apart (a chord of a gently curving path)
  r = lagoon("probe --scene " + harbour + " --time 5 --object boat");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto boat = nlohmann::json::parse(r.output);
  const auto v = boat["velocity_mps"];
  EXPECT_NEAR(std::hypot(v[0].get<double>(), v[2].get<double>()), 6.0, 1e-6) << r.output;
  EXPECT_LT(std::abs(boat["origin"][1].get<double>()), 0.5)
      << "a surface vehicle rides the water: " << r.output;
}

// Behind the harbour's boat the probe's heights include its wake (wakes.felt_by_bodies): the height is the
// sea's plus wake_height_m, and the normal tilts with the wake's slopes.
TEST(OceanCli, ProbeAtAPointIncludesTheWakes) {
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  const std::string args = " --time 12.5 --at 8,26";
  auto with = lagoon("probe --scene " + harbour + args);
  auto without = lagoon("probe --scene " + harbour + args + " --set wakes.felt_by_bodies=false");
  ASSERT_EQ(with.exit_code, 0) << with.output;
  ASSERT_EQ(without.exit_code, 0) << without.output;
  const auto a = nlohmann::json::parse(with.output), b = nlohmann::json::parse(without.output);
  const double wake = a["wake_height_m"].get<double>();
  EXPECT_GT(std::abs(wake), 0.05) << "the boat's wake reaches the buoy by then: " << with.output;
  EXPECT_EQ(b["wake_height_m"].get<double>(), 0.0);
  EXPECT_NEAR(a["height_m"].get<double>(), b["height_m"].get<double>() + wake, 1e-9);
  EXPECT_GT(std::abs(a["normal"][0].get<double>() - b["normal"][0].get<double>()) +
                std::abs(a["normal"][2].get<double>() - b["normal"][2].get<double>()),
            1e-3);
}

// Model gerstner through the tools: lagoon probe answers eq. 11 of the exact waves (summed directly, bound
// 0), and lagoon export's cascades sum to eq. 11's displacement at the texels' rest points (ocean/gerstner.h,
// docs/models.md). Eq. 11 as written: the bay's floor left out (its waves over it: shoaling_test.cpp).
TEST(OceanCli, ModelGerstnerThroughProbeAndExport) {
  const std::vector<std::string> sets{
      "ocean.model=gerstner", "ocean.choppiness=0.9", "ocean.shoaling=false",
      R"(ocean.cascades=[{"patch_size_m":200,"resolution":64},{"patch_size_m":20,"resolution":64}])",
      R"(ocean.gerstner.waves=[{"amplitude_m":0.6,"wavelength_m":37,"direction_deg":20,"phase_deg":30},)"
      R"({"amplitude_m":0.05,"wavelength_m":2.3,"direction_deg":75}])"};
  std::string set_args;
  for (const std::string& s : sets) set_args += " --set " + shell_quote(s);
  constexpr double kRad = std::numbers::pi / 180;
  const ocean::GerstnerSurface cpu(
      {.waves = {{0.6, 37, 20, 30 * kRad, 0.9}, {0.05, 2.3, 75, 0, 0.9}}, .limit_steepness = false});

  auto r = lagoon("probe --scene " + kDefaultScene + " --time 2.5 --at 3,4 --at -17.5,8.25" + set_args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<nlohmann::json> points = json_lines(r.output);
  EXPECT_EQ(points.size(), 2u);
  for (const nlohmann::json& j : points) {
    const ocean::WaveSample exact = cpu.sample(2.5, j["x"].get<double>(), j["z"].get<double>());
    EXPECT_LE(std::abs(j["height_m"].get<double>() - exact.height), 1e-9) << j;
    EXPECT_EQ(j["error_bound_m"].get<double>(), 0.0) << j;
  }

  TempDir dir;
  r = lagoon("export --scene " + kDefaultScene + " --out " + shell_quote((dir / "g").string()) + " --t0 1.5" +
             set_args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto big = io::read_npy(dir / "g" / "cascade0_displacement.npy");
  auto small = io::read_npy(dir / "g" / "cascade1_displacement.npy");
  ASSERT_TRUE(big && small);
  double worst = 0;
  for (int j = 0; j < 64; j += 7)
    for (int i = 0; i < 64; i += 5) {  // texel (i, j) of 200 m rests at 3.125 (i, j): texel 10 (i, j) of 20 m
      const size_t a = (size_t(j) * 64 + i) * 3, b = (size_t((10 * j) % 64) * 64 + (10 * i) % 64) * 3;
      const glm::dvec2 x0 = 3.125 * glm::dvec2(i, j);
      const glm::dvec3 d = cpu.at_rest(x0, 1.5).position - glm::dvec3(x0.x, 0, x0.y);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(big->data[a + c] + small->data[b + c] - d[c]));
    }
  EXPECT_LT(worst, 1e-4);
}

// Model sines through lagoon probe: eqs. 2-3's direct sum within the query's bound (the bay's floor left
// out); picking the model with --set also sets the choppiness it needs.
TEST(OceanCli, ModelSinesThroughProbe) {
  const std::vector<std::string> sets{"ocean.model=sines", "ocean.choppiness=0", "ocean.shoaling=false"};
  auto scene = scene::load_scene(kDefaultScene, sets);
  ASSERT_TRUE(scene) << scene.error().message;
  auto r = lagoon("probe --scene " + kDefaultScene +
                  " --time 4.5 --at 3,4 --at -17.5,8.25 --set ocean.model=sines "
                  "--set ocean.choppiness=0 --set ocean.shoaling=false");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<nlohmann::json> points = json_lines(r.output);
  EXPECT_EQ(points.size(), 2u);
  for (const nlohmann::json& j : points)
    EXPECT_LE(std::abs(j["height_m"].get<double>() -
                       ocean::sines_height(scene->ocean, 4.5, j["x"].get<double>(), j["z"].get<double>())),
              j["error_bound_m"].get<double>())
        << j;
  // The same probe without the choppiness: the override that picks sines sets it (issue 39; the refusals
  // are SceneCli.PickingAModelWithSetAlsoSetsWhatTheModelNeedsAndSaysSo's), with the same heights.
  const ProcessResult implied = lagoon("probe --scene " + kDefaultScene +
                                       " --time 4.5 --at 3,4 --at -17.5,8.25 --set ocean.model=sines "
                                       "--set ocean.shoaling=false");
  ASSERT_EQ(implied.exit_code, 0) << implied.output;
  EXPECT_NE(implied.output.find("also sets ocean.choppiness 0.8 -> 0"), std::string::npos) << implied.output;
  const std::vector<nlohmann::json> same = json_lines(implied.output);
  ASSERT_EQ(same.size(), points.size());
  for (size_t i = 0; i < same.size(); ++i) EXPECT_EQ(same[i]["height_m"], points[i]["height_m"]);
}

// Model perlin through lagoon probe: at t = 0 at the first cascade's grid points, the noise less its grid
// mean.
TEST(OceanCli, ModelPerlinThroughProbe) {
  const std::vector<std::string> sets{"ocean.model=perlin", "ocean.choppiness=0", "ocean.perlin.octaves=2",
                                      R"(ocean.cascades=[{"patch_size_m":128,"resolution":64}])"};
  auto scene = scene::load_scene(kDefaultScene, sets);
  ASSERT_TRUE(scene) << scene.error().message;
  double mean = 0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) mean += ocean::perlin_height(scene->ocean, 2.0 * i, 2.0 * j) / (64 * 64);
  std::string command = "probe --scene " + kDefaultScene + " --time 0 --at 6,10 --at 40,2";
  for (const std::string& s : sets) command += " --set " + shell_quote(s);
  auto r = lagoon(command);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<nlohmann::json> points = json_lines(r.output);
  ASSERT_EQ(points.size(), 2u);
  for (const nlohmann::json& j :
       points)  // grid points (2 m apart), where the cascade holds the noise's samples
    EXPECT_NEAR(j["height_m"].get<double>(),
                ocean::perlin_height(scene->ocean, j["x"].get<double>(), j["z"].get<double>()) - mean, 1e-6)
        << j;
}

// Model springs through lagoon probe and export: at nodes, probe answers the CPU grid (ocean/springs.h) and
// the exported heights are the GPU's, which match it; foam runs; a time the grid cannot reach is refused.
TEST(OceanCli, ModelSpringsThroughProbeAndExport) {
  const std::vector<std::string> sets{
      "ocean.model=springs", R"(ocean.cascades=[{"patch_size_m":128,"resolution":64}])",
      R"(ocean.springs.drops=[{"x_m":30,"z_m":40,"time_s":0,"radius_m":6,"speed_mps":2}])",
      "ocean.springs.boundary_amplitude_m=0.2"};
  std::string set_args;
  for (const std::string& s : sets) set_args += " --set " + shell_quote(s);
  auto scene = scene::load_scene(kDefaultScene, sets);
  ASSERT_TRUE(scene) << scene.error().message;
  ocean::SpringGrid grid(scene->ocean);
  const std::vector<glm::dvec2> at = grid.surface_at(9.0);

  auto r = lagoon("probe --scene " + kDefaultScene + " --time 9 --at 40,40 --at 50,30 --at 4,60" + set_args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<nlohmann::json> points = json_lines(r.output);
  ASSERT_EQ(points.size(), 3u);
  for (const nlohmann::json& j : points) {  // nodes 2 m apart
    const size_t node = size_t(j["z"].get<double>() / 2) * 64 + size_t(j["x"].get<double>() / 2);
    EXPECT_NEAR(j["height_m"].get<double>(), at[node].x, 1e-9) << j;
    EXPECT_NEAR(j["velocity_mps"][1].get<double>(), at[node].y, 1e-9) << j;
  }
  EXPECT_GT(std::abs(points[0]["height_m"].get<double>()), 0.01) << "the drop's ring should have arrived";

  TempDir dir;
  r = lagoon("export --scene " + kDefaultScene + " --out " + shell_quote((dir / "s").string()) + " --t0 9" +
             set_args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto heights = io::read_npy(dir / "s" / "cascade0_displacement.npy");
  ASSERT_TRUE(heights);
  double diff = 0, norm = 0;
  for (size_t i = 0; i < at.size(); ++i) {
    diff += std::pow(heights->data[i * 3 + 1] - at[i].x, 2);
    norm += at[i].x * at[i].x;
  }
  EXPECT_LT(std::sqrt(diff / norm), 1e-5);

  r = lagoon("probe --scene " + kDefaultScene + " --time 1e6 --at 0,0" + set_args);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("steps of the springs grid"), std::string::npos) << r.output;
}

// Foam runs with every model (issue 15): two exported frames 0.5 s apart follow the foam law at every texel
// of every cascade, new foam = clamp(threshold - J, 0, 1) from the exported J, the last faded as
// (foam + 0.4) exp(-decay dt) - 0.4 (shared/foam.h: to nothing within ln 3.5 / decay).
class ModelFoam : public testing::TestWithParam<const char*> {};

TEST_P(ModelFoam, FollowsTheFoamLawThroughExport) {
  TempDir dir;
  const std::string model = GetParam();
  std::string sets =
      " --set ocean.model=" + model + " --set ocean.foam.threshold=1.05 --set ocean.foam.decay_per_s=0.5" +
      " --set " +
      shell_quote(
          R"(ocean.cascades=[{"patch_size_m":200,"resolution":64},{"patch_size_m":23,"resolution":64}])");
  if (model == "sines") sets += " --set ocean.choppiness=0";
  if (model == "perlin") sets += " --set ocean.perlin.octaves=2";
  auto r = lagoon("export --scene " + kDefaultScene + " --out " + shell_quote((dir / "f").string()) +
                  " --frames 2 --dt 0.5 --t0 3" + sets);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double kept = std::exp(-0.5 * 0.5);
  double worst = 0, largest = 0;
  // Only fft draws on the second cascade; for the others it holds still water (J = 1, normal up) and no foam:
  // nothing steps it.
  for (const char* prefix : {"cascade0", "cascade1"}) {
    if (model != "fft" && std::string(prefix) == "cascade1") {
      auto jac = io::read_npy(dir / "f" / "cascade1_jacobian.npy");
      auto normal = io::read_npy(dir / "f" / "cascade1_normal.npy");
      ASSERT_TRUE(jac && normal);
      EXPECT_EQ(*std::min_element(jac->data.begin(), jac->data.end()), 1.0f);
      EXPECT_EQ(normal->data[1], 1.0f);
      continue;
    }
    auto foam = io::read_npy(dir / "f" / (std::string(prefix) + "_foam.npy"));
    auto jac = io::read_npy(dir / "f" / (std::string(prefix) + "_jacobian.npy"));
    ASSERT_TRUE(foam && jac);
    const size_t texels = 64 * 64;
    for (size_t i = 0; i < texels; ++i) {
      const double first = std::clamp(1.05 - jac->data[i], 0.0, 1.0);
      const double second =
          std::max((first + 0.4) * kept - 0.4, std::clamp(1.05 - double(jac->data[texels + i]), 0.0, 1.0));
      worst = std::max({worst, std::abs(foam->data[i] - first), std::abs(foam->data[texels + i] - second)});
      largest = std::max(largest, double(foam->data[texels + i]));
    }
  }
  EXPECT_LT(worst, 1e-5) << model;
  EXPECT_GT(largest, 0.04) << model << ": no foam at all";
}

INSTANTIATE_TEST_SUITE_P(Models, ModelFoam, testing::Values("fft", "gerstner", "sines", "perlin", "springs"));

TEST(OceanCli, AVehicleWithoutAHullFailsNamingTheField) {
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  const std::string out = testing::TempDir() + "never.png";
  auto r = lagoon("render --scene " + harbour + " --out " + out +
                  " --set 'vehicles=[{\"file\":\"missing.gltf\"}]'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("vehicles[0].file"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missing.gltf"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace lagoon::test
