// Saving a scene (scene::save_scene): what is saved loads back to the same scene, for every shipped scene and
// for values that do not print exactly in a few digits, with file paths kept relative to the saved file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/scene.h"
#include "scene/scene_io.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

fs::path temp_folder(const std::string& name) {
  const fs::path folder = fs::path(LAGOON_TEST_ARTIFACTS) / "scene_save" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

TEST(SceneSave, ShippedScenesRoundTrip) {
  for (const char* name :
       {"default", "open-ocean", "tropical-lagoon", "reef-dive", "waterline", "harbour", "beach"}) {
    const fs::path source = fs::path(LAGOON_SOURCE_DIR) / "scenes" / (std::string(name) + ".json");
    auto scene = scene::load_scene(source);
    ASSERT_TRUE(scene) << scene.error().message;
    // Saved next to the original, so relative asset paths stay valid and stay relative.
    const fs::path saved =
        fs::path(LAGOON_SOURCE_DIR) / "scenes" / (std::string(name) + ".saved-by-test.json");
    ASSERT_TRUE(scene::save_scene(*scene, saved));
    auto reloaded = scene::load_scene(saved);
    const std::string text = [&] {
      std::ifstream in(saved);
      return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    fs::remove(saved);
    ASSERT_TRUE(reloaded) << reloaded.error().message;
    EXPECT_EQ(scene::scene_to_json(*reloaded, source.parent_path()),
              scene::scene_to_json(*scene, source.parent_path()))
        << name;
    EXPECT_EQ(text.find(LAGOON_SOURCE_DIR), std::string::npos) << "absolute path in the saved " << name;
  }
}

TEST(SceneSave, ValuesReloadBitForBit) {
  auto scene = scene::parse_scene(nlohmann::json::object(), "test");
  ASSERT_TRUE(scene);
  scene->camera.position = {0.1f, 1.0f / 3.0f, -1234.5677f};
  scene->camera.look_at = {1e-3f, -0.7f, 3.3333333f};
  scene->ocean.spectrum.wind_speed_mps = 7.123456789;  // a double field
  scene->sun.elevation_deg = 0.1f;
  scene->time_s = 12.345678f;
  const fs::path file = temp_folder("bits") / "scene.json";
  ASSERT_TRUE(scene::save_scene(*scene, file));
  EXPECT_FALSE(fs::exists(file.string() + ".partial"));
  auto back = scene::load_scene(file);
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->camera.position, scene->camera.position);
  EXPECT_EQ(back->camera.look_at, scene->camera.look_at);
  EXPECT_EQ(back->ocean.spectrum.wind_speed_mps, scene->ocean.spectrum.wind_speed_mps);
  EXPECT_EQ(back->sun.elevation_deg, scene->sun.elevation_deg);
  EXPECT_EQ(back->time_s, scene->time_s);
}

TEST(SceneSave, UnwritableFolderSaysWhyAndLeavesNothing) {
  auto scene = scene::parse_scene(nlohmann::json::object(), "test");
  ASSERT_TRUE(scene);
  const fs::path file = temp_folder("missing") / "no-such-folder" / "scene.json";
  const auto result = scene::save_scene(*scene, file);
  ASSERT_FALSE(result);
  EXPECT_NE(result.error().message.find("no-such-folder"), std::string::npos) << result.error().message;
  EXPECT_FALSE(fs::exists(file.parent_path()));
}

}  // namespace
}  // namespace lagoon::test
