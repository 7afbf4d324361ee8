// What a renderer keeps between runs (render/cached_tables.h: the water LUTs, the environment map;
// render/foam_cache.h: the warm-up's foam): a renderer that read them from the cache draws the picture, byte
// for byte, that one which computed them draws, and a scene with other water gets its own tables, not the
// cached ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "ocean/gpu/dynamic_layer_gpu.h"
#include "render/ocean_renderer.h"
#include "render/passes/wakes_pass.h"
#include "render/pipeline_memory.h"
#include "support/edited_scene.h"
#include "support/image_compare.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

// LAGOON_PIPELINE_CACHE (core/cache_dir.h) for the lifetime of the object, then what it was.
class CacheFolder {
 public:
  explicit CacheFolder(const std::string& value) {
    if (const char* old = std::getenv("LAGOON_PIPELINE_CACHE")) old_ = old;
    setenv("LAGOON_PIPELINE_CACHE", value.c_str(), 1);
  }
  ~CacheFolder() {
    if (old_)
      setenv("LAGOON_PIPELINE_CACHE", old_->c_str(), 1);
    else
      unsetenv("LAGOON_PIPELINE_CACHE");
  }
  CacheFolder(const CacheFolder&) = delete;
  CacheFolder& operator=(const CacheFolder&) = delete;

 private:
  std::optional<std::string> old_;
};

class CachedTablesRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_cached_tables"};

  void SetUp() override {
    GpuTest::SetUp();
    fs::create_directory_symlink(fs::path(LAGOON_SOURCE_DIR) / "scenes/assets", dir_ / "assets");
  }

  scene::Scene small(const std::string& water_type) {
    nlohmann::json s = shipped_scene_json("default");
    s["render"].update({{"width", 64}, {"height", 36}});
    s["water"]["type"] = water_type;
    // A strong wind, so that the warm-up's foam shows: a cached foam that were not the computed one would.
    s["ocean"]["spectrum"]["wind_speed_mps"] = 14;
    s["ocean"]["choppiness"] = 1.5;
    use_small_cascades(s);
    return write_and_load(s, dir_ / "scene.json");
  }

  io::Image8 render(const scene::Scene& s, const std::string& cache) {
    const CacheFolder folder(cache);
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return renderer ? (*renderer)->render(s) : io::Image8{};
  }

  size_t files_of(const std::string& kind) const {
    size_t n = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir_ / "cache/results", ec))
      n += entry.path().filename().string().rfind(kind + "-", 0) == 0;
    return n;
  }
};

TEST_F(CachedTablesRender, TablesFromTheCacheDrawTheSamePictureAndOtherWaterGetsItsOwn) {
  const std::string cache = (dir_ / "cache").string();
  const scene::Scene coastal = small("jerlov-1C"), ocean = small("jerlov-IA");
  const io::Image8 computed = render(coastal, "off");
  const io::Image8 cold = render(coastal, cache);  // computes the tables and files them
  EXPECT_EQ(files_of("water"), 1u);
  EXPECT_EQ(files_of("environment"), 1u);
  EXPECT_EQ(files_of("foam"), 1u);                 // the still frame's warm-up (render/foam_cache.h)
  EXPECT_EQ(files_of("whitecaps"), 1u);            // the cascades' foam onsets (the same file)
  const io::Image8 warm = render(coastal, cache);  // reads them
  EXPECT_EQ(files_of("water"), 1u);
  EXPECT_EQ(max_channel_difference(computed, cold), 0);
  EXPECT_EQ(max_channel_difference(computed, warm), 0);

  const io::Image8 other_computed = render(ocean, "off");
  const io::Image8 other_warm = render(ocean, cache);
  EXPECT_EQ(files_of("water"), 2u);
  EXPECT_EQ(max_channel_difference(other_computed, other_warm), 0);
  EXPECT_GT(max_channel_difference(other_warm, warm), 10) << "other water drew the cached water's colour";
}

// The pipelines a frame used (render/pipeline_memory.h): the next renderer of the scene, at another time and
// camera too, makes them ahead on another thread without drawing anything, and draws the same picture;
// another scene remembers its own.
TEST_F(CachedTablesRender, ThePipelinesAFrameUsedAreMadeAheadByTheNextRendererOfTheScene) {
  const CacheFolder use((dir_ / "cache").string());
  const scene::Scene s = small("jerlov-1C");
  const size_t before = ctx().pipelines().used_count();
  io::Image8 first;
  {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    ASSERT_TRUE(renderer) << renderer.error().message;
    first = (*renderer)->render(s);
  }
  std::vector<std::string> used = ctx().pipelines().used_keys(before);
  ASSERT_GE(used.size(), 5u);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  scene::Scene moved = s;
  moved.time_s += 1;
  moved.camera.position.x += 3;
  std::vector<std::string> remembered = render::PipelineMemory(ctx(), moved).remembered();
  std::sort(remembered.begin(), remembered.end());
  EXPECT_EQ(remembered, used) << "the memory is not the frame's pipelines";
  EXPECT_TRUE(render::PipelineMemory(ctx(), small("jerlov-IA")).remembered().empty())
      << "another scene read this one's pipelines";

  auto next = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(next) << next.error().message;
  const auto recipes = ctx().pipelines().find(used);
  ASSERT_GE(recipes.size(), used.size());
  size_t made = 0;
  for (int wait = 0; wait < 1000 && made < recipes.size(); ++wait) {  // up to 10 s, nothing drawn meanwhile
    made = 0;
    for (const auto& recipe : recipes) {
      std::lock_guard lock(recipe->mutex);
      made += recipe->pipeline != VK_NULL_HANDLE;
    }
    if (made < recipes.size()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(made, recipes.size()) << "the next renderer did not make the remembered pipelines ahead";
  EXPECT_EQ(max_channel_difference((*next)->render(s), first), 0);
}

// The wakes' history (render/wakes_cache.h): a second renderer of the same frame restores the layer the first
// one's steps left instead of stepping from rest, and draws the same bits; another time is another history.
TEST_F(CachedTablesRender, WakesFromTheCacheAreTheStepsOwnLayerAndPicture) {
  const std::string cache = (dir_ / "cache").string();
  nlohmann::json j = shipped_scene_json("harbour");
  j["render"].update({{"width", 64}, {"height", 36}});
  j["wakes"].update({{"resolution", 128}, {"cell_size_m", 0.5}, {"history_s", 2}});
  use_small_cascades(j);
  const scene::Scene s = write_and_load(j, dir_ / "harbour.json");
  struct Drawn {
    io::Image8 image;
    std::vector<std::byte> layer;
    long long taken = 0, from_cache = 0;
  };
  auto draw = [&](const scene::Scene& scene, const std::string& folder) {
    const CacheFolder use(folder);
    auto renderer = render::OceanRenderer::create(ctx(), scene);
    EXPECT_TRUE(renderer) << renderer.error().message;
    if (!renderer || !(*renderer)->wakes().active()) return Drawn{};
    Drawn d{.image = (*renderer)->render(scene)};
    d.layer = vk::readback_buffer(ctx(), (*renderer)->wakes().layer()->state());
    const std::vector<std::byte> foam = vk::readback_buffer(ctx(), (*renderer)->wakes().layer()->foam());
    d.layer.insert(d.layer.end(), foam.begin(), foam.end());
    d.taken = (*renderer)->wakes().steps_taken();
    d.from_cache = (*renderer)->wakes().steps_from_cache();
    return d;
  };
  const Drawn computed = draw(s, "off");
  ASSERT_GT(computed.taken, 10) << "no history was run: nothing was compared";
  EXPECT_EQ(computed.from_cache, 0);
  const Drawn cold = draw(s, cache);
  EXPECT_EQ(cold.from_cache, 0);
  EXPECT_EQ(files_of("wakes"), 1u);
  const Drawn warm = draw(s, cache);
  EXPECT_EQ(warm.from_cache, computed.taken);
  EXPECT_EQ(warm.taken, computed.taken);
  EXPECT_TRUE(warm.layer == computed.layer) << "the restored layer is not the steps' own";
  EXPECT_EQ(max_channel_difference(computed.image, warm.image), 0);
  scene::Scene later = s;
  later.time_s += 1.0f;
  const Drawn other = draw(later, cache);
  EXPECT_EQ(other.from_cache, 0);
  EXPECT_EQ(files_of("wakes"), 2u);
}

}  // namespace
}  // namespace lagoon::test
