// Sequences as datasets (issue 18): a frame depends only on the scene, its time and the seed, so 4 shards of
// 12 frames with foam and floating bodies are byte-identical to one process, a killed shard resumes to the
// same files, and `lagoon dataset verify` checks the set. The scene is the harbour (two floating bodies,
// breaking waves' foam, vehicles), small, with the wakes off to keep it quick (they replay like the foam).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "io/npy.h"
#include "io/png.h"
#include "support/child_process.h"
#include "support/run_process.h"
#include "support/shared_output.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

const std::string kHarbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
// Wind strong enough for foam; the sequence starts late enough for the bodies to move. A second between
// frames: a shard's frames are 4 s apart, more than the foam's warm-up, so a shard that did not step through
// the frames between its own would start its foam again and differ.
// The cascades are 64² instead of 256²: what is checked is how frames are shared out, not the sea's detail,
// and each step costs a sixteenth.
const std::string kArgs = " --scene " + shell_quote(kHarbour) +
                          " --width 96 --height 54 --frames 12 --fps 1 --time 20 --set wakes.enabled=false"
                          " --set ocean.spectrum.wind_speed_mps=12 --set ocean.cascades[0].resolution=64"
                          " --set ocean.cascades[1].resolution=64 --set ocean.cascades[2].resolution=64";

// The frames' files (PNG and metadata JSON) of a folder, by name.
std::map<std::string, std::string> frame_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& item : fs::directory_iterator(dir)) {
    const std::string name = item.path().filename().string();
    if (name.rfind("f_", 0) == 0) files[name] = read_file(item.path());
  }
  return files;
}

int manifest_lines(const fs::path& path) {
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) lines += !in.eof();
  return lines;
}

// One unsharded run, shared by the tests that compare against it: made by the first of them (ctest runs
// each in its own process) and reused by the rest (support/shared_output.h).
class DatasetCli : public ::testing::Test {
 protected:
  void SetUp() override {
    reference_ = shared_output("dataset reference:" + kArgs, [](const fs::path& dir) {
      const ProcessResult r = lagoon("render" + kArgs + " --out " + shell_quote((dir / "f.png").string()));
      EXPECT_EQ(r.exit_code, 0) << r.output;
      return r.exit_code == 0;
    });
    ASSERT_FALSE(reference_.empty());
  }
  const fs::path& reference() const { return reference_; }

 private:
  fs::path reference_;
};

TEST_F(DatasetCli, FourShardsAreByteIdenticalToOneProcess) {
  const auto expected = frame_files(reference());
  ASSERT_EQ(expected.size(), 24u);  // 12 PNGs and 12 metadata files
  TempDir dir;
  for (int s = 0; s < 4; ++s) {
    const ProcessResult r = lagoon("render" + kArgs + " --shard " + std::to_string(s) + "/4 --out " +
                                   shell_quote((dir / "f.png").string()));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("shard " + std::to_string(s) + "/4: 3 frames of 12 (3 rendered"),
              std::string::npos)
        << r.output;
  }
  const auto sharded = frame_files(dir.path());
  ASSERT_EQ(sharded.size(), expected.size());
  for (const auto& [name, bytes] : expected) EXPECT_TRUE(sharded.at(name) == bytes) << name << " differs";
  // The frames differ from each other (the sea moves), so equality is not trivial.
  EXPECT_NE(expected.at("f_0000.png"), expected.at("f_0011.png"));
  for (const fs::path& set : {reference(), dir.path()}) {
    const ProcessResult v = lagoon("dataset verify " + shell_quote(set.string()));
    EXPECT_EQ(v.exit_code, 0) << v.output;
    EXPECT_NE(v.output.find("1 set(s), 12 frames, 24 files"), std::string::npos) << v.output;
  }
}

TEST_F(DatasetCli, OneFrameAloneIsAShardOfOneFrameAndTheSameFiles) {
  // Frame 7 alone, by a fresh process: --shard 7/12 of the same 12 frames steps through frames 0-6 without
  // drawing them, so its foam and bodies carry on as the whole sequence's do.
  TempDir dir;
  const ProcessResult r =
      lagoon("render" + kArgs + " --shard 7/12 --out " + shell_quote((dir / "f.png").string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 frames of 12 (1 rendered"), std::string::npos) << r.output;
  for (const char* name : {"f_0007.png", "f_0007.json"})
    EXPECT_TRUE(read_file(dir / name) == read_file(reference() / name)) << name << " differs";
}

TEST_F(DatasetCli, AKilledShardResumesAndFinishesWithTheSameFiles) {
  TempDir dir;
  const std::string command = shell_quote(LAGOON_BINARY) + " render" + kArgs + " --shard 1/4 --out " +
                              shell_quote((dir / "f.png").string());
  const fs::path manifest = dir / "f.shard-1-of-4.jsonl";
  {
    ChildProcess child(command);
    // Killed as soon as its first frame (of 1, 5, 9) is listed: header + one line.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (manifest_lines(manifest) < 2 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    child.send(SIGKILL);
    ASSERT_EQ(child.wait().code, 128 + SIGKILL) << "finished before it could be killed:\n" << child.output();
  }
  const int listed = manifest_lines(manifest) - 1;
  ASSERT_GE(listed, 1);
  ASSERT_LT(listed, 3);
  // A frame whose files a kill left half-way is re-rendered: damage one that is not listed yet.
  std::ofstream(dir / "f_0009.png", std::ios::binary) << "half a PNG";
  const ProcessResult resumed = run_process(command);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("(" + std::to_string(3 - listed) + " rendered, " + std::to_string(listed) +
                                " already done)"),
            std::string::npos)
      << resumed.output;
  const auto expected = frame_files(reference());
  const auto files = frame_files(dir.path());
  ASSERT_EQ(files.size(), 6u);
  for (const auto& [name, bytes] : files) EXPECT_TRUE(expected.at(name) == bytes) << name << " differs";
  EXPECT_EQ(manifest_lines(manifest), 4);
}

TEST_F(DatasetCli, VerifyNamesADamagedFrameAndAnotherRunIsRefused) {
  TempDir dir;
  fs::copy(reference(), dir.path(), fs::copy_options::recursive);
  std::string png = read_file(dir / "f_0004.png");
  png[png.size() / 2] ^= 0x40;
  std::ofstream(dir / "f_0004.png", std::ios::binary) << png;
  const ProcessResult v = lagoon("dataset verify " + shell_quote(dir.path().string()));
  EXPECT_EQ(v.exit_code, 1) << v.output;
  EXPECT_NE(v.output.find("frame 4: " + (dir / "f_0004.png").string() + " does not match its SHA-256"),
            std::string::npos)
      << v.output;
  // Rendering again mends it (only that frame is drawn), then the set verifies.
  const ProcessResult again = lagoon("render" + kArgs + " --out " + shell_quote((dir / "f.png").string()));
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("(1 rendered, 11 already done)"), std::string::npos) << again.output;
  EXPECT_EQ(lagoon("dataset verify " + shell_quote(dir.path().string())).exit_code, 0);
  // The same folder with other options is another run's: refused, nothing changed.
  const ProcessResult other =
      lagoon("render" + kArgs + " --set sun.elevation_deg=20 --out " + shell_quote((dir / "f.png").string()));
  EXPECT_EQ(other.exit_code, 1) << other.output;
  EXPECT_NE(other.output.find("was written by another run"), std::string::npos) << other.output;
  EXPECT_TRUE(read_file(dir / "f_0004.png") == read_file(reference() / "f_0004.png"));
}

TEST_F(DatasetCli, TheMetadataStatesAPinholeCameraThatSeesItsAimAtTheCentre) {
  const nlohmann::json meta = nlohmann::json::parse(read_file(reference() / "f_0003.json"));
  EXPECT_EQ(meta["frame"], 3);
  EXPECT_NEAR(meta["time_s"].get<double>(), 23, 1e-6);
  EXPECT_EQ(meta["image"], "f_0003.png");
  EXPECT_EQ(meta["seed"]["ocean"], 11);
  EXPECT_EQ(meta["water"]["type"], "jerlov-1C");
  const auto& k = meta["camera"]["K"];
  // harbour: 60° vertical field of view, 96 x 54 pixels.
  const double fy = 27.0 / std::tan(M_PI / 6);
  EXPECT_NEAR(k[0][0].get<double>(), fy, 1e-9);
  EXPECT_NEAR(k[1][1].get<double>(), fy, 1e-9);
  EXPECT_NEAR(k[0][2].get<double>(), 47.5, 1e-9);
  EXPECT_NEAR(k[1][2].get<double>(), 26.5, 1e-9);
  // x_cam = R^T (X - t); the aim projects to the principal point, a point to the camera's right (the quay
  // camera looks south along +z, so its right is west, world -x) to the right half and one above to the
  // upper half.
  const auto& pose = meta["camera"]["world_from_camera"];
  auto project = [&](double x, double y, double z) {
    double c[3];
    for (int i = 0; i < 3; ++i)
      c[i] = pose[0][i].get<double>() * (x - pose[0][3].get<double>()) +
             pose[1][i].get<double>() * (y - pose[1][3].get<double>()) +
             pose[2][i].get<double>() * (z - pose[2][3].get<double>());
    return std::pair{fy * c[0] / c[2] + 47.5, fy * c[1] / c[2] + 26.5};
  };
  const auto centre = project(0, 0, 30);
  EXPECT_NEAR(centre.first, 47.5, 1e-6);
  EXPECT_NEAR(centre.second, 26.5, 1e-6);
  EXPECT_GT(project(-5, 0, 30).first, 50);
  EXPECT_LT(project(0, 5, 30).second, 24);
  // ENU: east = x, north = -z, up = y.
  const auto& enu = meta["camera"]["enu_from_camera"];
  EXPECT_NEAR(enu[0][3].get<double>(), 0, 1e-9);
  EXPECT_NEAR(enu[1][3].get<double>(), 16, 1e-9);
  EXPECT_NEAR(enu[2][3].get<double>(), 5, 1e-9);
}

// One compass (issue 39): azimuths turn clockwise from north (-z) toward east (+x), seen from above. A camera
// looking toward -z faces north in the frame's ENU pose with east on its right, a sun at azimuth a has the
// ENU direction (sin a cos e, cos a cos e, sin e), and the picture agrees: a low sun at 0 stands in front of
// the north-facing view (its glitter brightens the water) and at 180 behind it; at 60 it lights the right
// of the view, at 300 the left. (With the old, mirrored compass, azimuth 0 put the sun behind this view.)
TEST(DatasetCliCompass, TheSunAndTheCameraStandWhereTheCompassSaysInThePictureAndTheEnuPose) {
  const TempDir dir;
  const double elevation = 6;
  struct Picture {
    double right_minus_left = 0, water = 0;
  };
  std::map<int, Picture> pictures;
  for (int azimuth : {0, 60, 180, 300}) {
    const std::string name = "sun" + std::to_string(azimuth);
    const ProcessResult r = lagoon(
        "render --scene " + shell_quote(std::string(LAGOON_SOURCE_DIR) + "/scenes/open-ocean.json") +
        " --width 64 --height 36 --frames 2 --set camera.position=[0,6,0] --set camera.look_at=[0,4.6,-10]"
        " --set sun.elevation_deg=" +
        std::to_string(elevation) + " --set sun.azimuth_deg=" + std::to_string(azimuth) + " --out " +
        shell_quote((dir / (name + ".png")).string()));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json meta = nlohmann::json::parse(read_file(dir / (name + "_0000.json")));
    const double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
    const auto& sun = meta["sun"]["direction_enu"];
    EXPECT_NEAR(sun[0].get<double>(), std::sin(a) * std::cos(e), 1e-5) << "east, azimuth " << azimuth;
    EXPECT_NEAR(sun[1].get<double>(), std::cos(a) * std::cos(e), 1e-5) << "north, azimuth " << azimuth;
    EXPECT_NEAR(sun[2].get<double>(), std::sin(e), 1e-5) << "up, azimuth " << azimuth;
    // The optical frame's columns in ENU: x (right) is east, z (forward) north (-z), tilted down.
    const auto& pose = meta["camera"]["enu_from_camera"];
    EXPECT_NEAR(pose[0][0].get<double>(), 1, 1e-5) << "the camera's right is east";
    EXPECT_NEAR(pose[1][2].get<double>(), 10 / std::hypot(10, 1.4), 1e-5) << "looking toward -z is north";
    EXPECT_NEAR(pose[0][2].get<double>(), 0, 1e-5);
    const Result<io::Image8> image = io::read_png(dir / (name + "_0000.png"));
    ASSERT_TRUE(image.ok()) << image.error().message;
    const uint32_t w = image->width, h = image->height;
    double left = 0, right = 0, water = 0;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          const double v = image->pixel(x, y)[c];
          left += x < w / 3 ? v : 0.0;
          right += x >= w - w / 3 ? v : 0.0;
          water += y >= h / 2 ? v : 0.0;
        }
    pictures[azimuth] = {(right - left) / (3.0 * h * (w / 3)), water / (3.0 * w * (h - h / 2))};
    RecordProperty("sun_" + std::to_string(azimuth),
                   "right - left " + std::to_string(pictures[azimuth].right_minus_left) + ", water mean " +
                       std::to_string(pictures[azimuth].water));
  }
  EXPECT_GT(pictures[0].water, pictures[180].water + 5) << "a sun in the north glitters ahead of the view";
  EXPECT_GT(pictures[60].right_minus_left, 2.0) << "a sun east of north lights the right of the view";
  EXPECT_LT(pictures[300].right_minus_left, -2.0) << "a sun west of north lights its left";
}

TEST(DatasetCliAov, GroundTruthIsWrittenBesideEachFrameListedCheckedAndPreviewed) {
  TempDir dir;
  // From under the water, looking along the floor: every kind of ground truth has something to say.
  const ProcessResult r =
      lagoon("render --scene " + shell_quote(kHarbour) +
             " --width 48 --height 27 --frames 2 --set wakes.enabled=false"
             " --set camera.position=[-2,-2.6,1] --set camera.look_at=[5,-3.6,10]"
             " --aov depth,normal,water_mask,object_id,clean,transmission,backscatter --out " +
             shell_quote((dir / "f.png").string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::pair<std::string, size_t>> kinds = {
      {"depth", 1}, {"normal", 3},       {"water_mask", 1}, {"object_id", 1},
      {"clean", 3}, {"transmission", 3}, {"backscatter", 3}};
  std::map<std::string, io::NpyArray> first;
  for (const char* frame : {"f_0000", "f_0001"}) {
    for (const auto& [kind, channels] : kinds) {
      auto npy = io::read_npy(dir / (std::string(frame) + "." + kind + ".npy"));
      ASSERT_TRUE(npy) << npy.error().message;
      const std::vector<size_t> shape =
          channels == 3 ? std::vector<size_t>{27, 48, 3} : std::vector<size_t>{27, 48};
      EXPECT_EQ(npy->shape, shape) << kind;
      if (std::string(frame) == "f_0000") first[kind] = std::move(*npy);
    }
    const nlohmann::json meta = nlohmann::json::parse(read_file(dir / (std::string(frame) + ".json")));
    EXPECT_EQ(meta["aov"]["depth"], std::string(frame) + ".depth.npy");
    EXPECT_EQ(meta["aov"].size(), kinds.size());
  }
  // Each file holds its own kind: the water through which the floor is seen (mask 2, id -1), the floor's
  // light let through in part (0 < T < 1) with light added (B > 0), and the surface above (mask 1, T = 1,
  // clean NaN).
  const auto& mask = first["water_mask"].data;
  const auto& ids = first["object_id"].data;
  const auto& t = first["transmission"].data;
  const auto& b = first["backscatter"].data;
  const auto& clean = first["clean"].data;
  int floor_seen = 0, floor_through = 0, surface_seen = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i] == 2.0f && ids[i] == -1.0f) {
      ++floor_seen;
      // 0 where the floor lies beyond the water's reach (the underwater tables' end: < 1e-3 gets through).
      EXPECT_TRUE(t[3 * i + 1] >= 0.0f && t[3 * i + 1] < 1.0f) << i;
      floor_through += t[3 * i + 1] > 0.0f;  // green: red is all but gone within metres
      EXPECT_GT(b[3 * i + 1], 0.0f) << i;
      EXPECT_FALSE(std::isnan(clean[3 * i])) << i;
    }
    if (mask[i] == 1.0f) {
      ++surface_seen;
      EXPECT_EQ(t[3 * i], 1.0f);
      EXPECT_TRUE(std::isnan(clean[3 * i]));
    }
  }
  EXPECT_GT(floor_seen, 100);
  EXPECT_GT(floor_through, floor_seen / 2);
  EXPECT_GT(surface_seen, 20);
  const ProcessResult v = lagoon("dataset verify " + shell_quote(dir.path().string()));
  EXPECT_EQ(v.exit_code, 0) << v.output;
  EXPECT_NE(v.output.find("2 frames, 18 files"), std::string::npos) << v.output;
  // The preview: the image and the seven AOVs, four panels across, each 48 x 27 under an 18-pixel label.
  const ProcessResult p = lagoon("dataset preview " + shell_quote((dir / "f_0000.json").string()) +
                                 " --out " + shell_quote((dir / "preview.png").string()));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const auto sheet = io::read_png(dir / "preview.png");
  ASSERT_TRUE(sheet) << sheet.error().message;
  EXPECT_EQ(sheet->width, 4u * 48);
  EXPECT_EQ(sheet->height, 2u * (27 + 18));
  // A broken set is named: a missing AOV file.
  std::filesystem::remove(dir / "f_0001.depth.npy");
  const ProcessResult broken = lagoon("dataset preview " + shell_quote((dir / "f_0001.json").string()) +
                                      " --out " + shell_quote((dir / "p1.png").string()));
  EXPECT_EQ(broken.exit_code, 1) << broken.output;
  EXPECT_NE(broken.output.find("f_0001.depth.npy"), std::string::npos) << broken.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "p1.png"));
  const ProcessResult unknown = lagoon("render --scene " + shell_quote(kHarbour) +
                                       " --aov depth,colour --out " + shell_quote((dir / "g.png").string()));
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(
      unknown.output.find("unknown ground truth 'colour'; available: depth, normal, water_mask, object_id, "
                          "clean, transmission, backscatter"),
      std::string::npos)
      << unknown.output;
}

TEST(DatasetCliErrors, BadShardsPathsAndFoldersAreClearErrors) {
  TempDir dir;
  const std::string base = "render --scene " + shell_quote(kHarbour) + " --width 32 --height 18 --out " +
                           shell_quote((dir / "f.png").string());
  for (const char* shard : {"4/4", "x", "1/0", "-1/4", "1/4/2"}) {
    const ProcessResult r = lagoon(base + " --frames 4 --shard " + shard);
    EXPECT_EQ(r.exit_code, 2) << shard << "\n" << r.output;
    EXPECT_NE(r.output.find("--shard"), std::string::npos) << r.output;
  }
  std::ofstream(dir / "short.json") << R"({"keyframes":[{"t":0,"position":[0,5,0],"look_at":[0,0,9]},)"
                                       R"({"t":1,"position":[0,4,0],"look_at":[0,0,9]}]})";
  const ProcessResult shortp =
      lagoon(base + " --frames 10 --fps 5 --path " + shell_quote((dir / "short.json").string()));
  EXPECT_EQ(shortp.exit_code, 1) << shortp.output;
  EXPECT_NE(shortp.output.find("the path lasts 1 s but --frames 10 at --fps 5 needs 1.8 s"),
            std::string::npos)
      << shortp.output;
  std::ofstream(dir / "bad.json") << R"({"keyframes":[{"t":0,"position":[0,5,0],"look_at":[0,5,0]}]})";
  const ProcessResult bad = lagoon(base + " --frames 2 --path " + shell_quote((dir / "bad.json").string()));
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("bad.json: keyframes: has 1 element"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "f_0000.png"));
  const ProcessResult none = lagoon("dataset verify " + shell_quote((dir / "nothing").string()));
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("not a folder"), std::string::npos) << none.output;
  EXPECT_EQ(lagoon("dataset check " + shell_quote(dir.path().string())).exit_code, 2);
}

}  // namespace
}  // namespace lagoon::test
