// The demo's scene edits (panel and --script) go through the loader, and its script file format.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "demo_options.h"
#include "parameter_panel.h"
#include "scene/scene_io.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

scene::Scene default_scene() {
  auto s = scene::load_scene(fs::path(LAGOON_SOURCE_DIR) / "scenes" / "default.json");
  EXPECT_TRUE(s) << s.error().message;
  return *s;
}

TEST(DemoEdits, ValidEditChangesOnlyThatField) {
  scene::Scene s = default_scene();
  const scene::Scene before = s;
  ASSERT_TRUE(demo::edit_scene(s, "ocean.spectrum.wind_speed_mps=17.5"));
  EXPECT_EQ(s.ocean.spectrum.wind_speed_mps, 17.5);
  s.ocean.spectrum.wind_speed_mps = before.ocean.spectrum.wind_speed_mps;
  EXPECT_EQ(scene::scene_to_json(s, {}), scene::scene_to_json(before, {}));
  EXPECT_EQ(s.source, before.source);
  // Object files stay usable: the edited scene still names existing files.
  for (const auto& object : s.objects) EXPECT_TRUE(fs::exists(object.file)) << object.file;
}

TEST(DemoEdits, InvalidEditLeavesTheSceneAndNamesTheField) {
  scene::Scene s = default_scene();
  const auto before = scene::scene_to_json(s, {});
  for (const char* bad :
       {"camera.fov_deg=500", "ocean.cascades[0].resolution=100", "water.type=\"jerlov-99\"",
        "ocean.spectrum.wind_speedd_mps=3", "render.gamma=\"bright\"", "no-equals-sign"}) {
    const auto r = demo::edit_scene(s, bad);
    ASSERT_FALSE(r) << bad;
    const std::string field = std::string(bad).substr(0, std::string(bad).find_first_of("=["));
    EXPECT_NE(r.error().message.find(
                  field.substr(0, field.find('.') == std::string::npos ? field.size() : field.find('.'))),
              std::string::npos)
        << r.error().message;
    EXPECT_EQ(scene::scene_to_json(s, {}), before) << bad;
  }
}

TEST(DemoEdits, ScriptLinesAreFrameAndAssignment) {
  const fs::path dir = fs::path(LAGOON_TEST_ARTIFACTS) / "demo_edits";
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "ok.txt");
    f << "# comment\n\n0 sun.elevation_deg=20\n  12\tcamera.fov_deg=40  # trailing comment\n";
  }
  auto steps = demo::read_script((dir / "ok.txt").string());
  ASSERT_TRUE(steps) << steps.error().message;
  ASSERT_EQ(steps->size(), 2u);
  EXPECT_EQ((*steps)[0].frame, 0);
  EXPECT_EQ((*steps)[0].assignment, "sun.elevation_deg=20");
  EXPECT_EQ((*steps)[1].frame, 12);
  EXPECT_EQ((*steps)[1].assignment, "camera.fov_deg=40");
  for (const char* bad : {"-1 sun.elevation_deg=20", "x sun.elevation_deg=20", "7", "1.5 a=b"}) {
    {
      std::ofstream f(dir / "bad.txt");
      f << "1 sun.elevation_deg=20\n" << bad << "\n";
    }
    auto r = demo::read_script((dir / "bad.txt").string());
    ASSERT_FALSE(r) << bad;
    EXPECT_NE(r.error().message.find("bad.txt:2"), std::string::npos) << r.error().message;
  }
  EXPECT_FALSE(demo::read_script((dir / "missing.txt").string()));
}

}  // namespace
}  // namespace lagoon::test
