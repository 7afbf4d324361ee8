// The dataset manifest: round trip, a line cut off by a kill, damaged or hostile lines, and verify_dataset's
// findings (missing shard, unfinished frame, changed file, frame listed twice, another run's shard).
#include <gtest/gtest.h>

#include <fstream>

#include "dataset/manifest.h"
#include "io/sha256.h"
#include "support/temp_dir.h"

namespace lagoon::dataset {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A set of `frames` frames in `shards` shards, one file per frame, every manifest complete.
void write_set(const fs::path& dir, int frames, int shards,
               const nlohmann::json& run = {{"scene", "a.json"}}) {
  for (int s = 0; s < shards; ++s) {
    Manifest m{.run = run, .frames = frames, .shard_index = s, .shard_count = shards};
    for (int f = s; f < frames; f += shards) {
      const std::string name = "f_" + std::to_string(f) + ".png";
      write(dir / name, "frame " + std::to_string(f));
      Result<ManifestFile> file = describe_file(dir / name, name);
      ASSERT_TRUE(file);
      m.entries.push_back({.frame = f, .time_s = f / 30.0, .device = "test", .files = {*file}});
    }
    ASSERT_TRUE(ManifestWriter::create(
        dir / ("f.shard-" + std::to_string(s) + "-of-" + std::to_string(shards) + ".jsonl"), m));
  }
}

bool has_problem(const DatasetReport& r, const std::string& needle) {
  for (const std::string& p : r.problems)
    if (p.find(needle) != std::string::npos) return true;
  return false;
}

std::string all(const DatasetReport& r) {
  std::string text;
  for (const std::string& p : r.problems) text += p + "\n";
  return text;
}

TEST(DatasetManifest, RoundTripsAndAppends) {
  test::TempDir dir;
  write(dir / "a.png", "pixels");
  Manifest m{.run = {{"scene", "x.json"}, {"fps", 30}}, .frames = 8, .shard_index = 1, .shard_count = 4};
  Result<ManifestWriter> writer = ManifestWriter::create(dir / "m.jsonl", m);
  ASSERT_TRUE(writer) << writer.error().message;
  Result<ManifestFile> file = describe_file(dir / "a.png", "a.png");
  ASSERT_TRUE(file);
  EXPECT_EQ(file->bytes, 6u);
  EXPECT_EQ(file->sha256, io::sha256_hex(std::as_bytes(std::span("pixels", 6))));
  ASSERT_TRUE(writer->append({.frame = 5, .time_s = 1.5, .device = "dev", .files = {*file}}));
  const Result<Manifest> back = read_manifest(dir / "m.jsonl");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->run, m.run);
  EXPECT_EQ(back->frames, 8);
  EXPECT_EQ(back->shard_index, 1);
  EXPECT_EQ(back->shard_count, 4);
  ASSERT_EQ(back->entries.size(), 1u);
  EXPECT_EQ(back->entries[0].frame, 5);
  EXPECT_EQ(back->entries[0].files[0].sha256, file->sha256);
  EXPECT_FALSE(back->cut_off_tail);
  EXPECT_EQ(entry_mismatch(dir.path(), back->entries[0]), "");
  write(dir / "a.png", "pixelz");
  EXPECT_NE(entry_mismatch(dir.path(), back->entries[0]).find("does not match its SHA-256"),
            std::string::npos);
  write(dir / "a.png", "pix");
  EXPECT_NE(entry_mismatch(dir.path(), back->entries[0]).find("has 3 bytes"), std::string::npos);
}

TEST(DatasetManifest, ALineCutOffByAKillIsLeftOutAndTheRestKept) {
  test::TempDir dir;
  write_set(dir.path(), 4, 1);
  const fs::path path = dir / "f.shard-0-of-1.jsonl";
  std::ofstream(path, std::ios::app) << R"({"frame":3,"files":[{"name":"f_3.pn)";
  const Result<Manifest> m = read_manifest(path);
  ASSERT_TRUE(m) << m.error().message;
  EXPECT_TRUE(m->cut_off_tail);
  EXPECT_EQ(m->entries.size(), 4u);
  EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "its last line is cut off"));
  // Rewriting it (as a resumed shard does) drops the tail.
  ASSERT_TRUE(ManifestWriter::create(path, *m));
  EXPECT_FALSE(read_manifest(path)->cut_off_tail);
  EXPECT_TRUE(verify_dataset(dir.path()).problems.empty()) << all(verify_dataset(dir.path()));
}

TEST(DatasetManifest, DamagedOrHostileLinesAreErrorsNamingTheLine) {
  test::TempDir dir;
  const std::string header = R"({"lagoon_dataset_manifest":1,"frames":4,"shard":[0,1],"run":{}})"
                             "\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "no complete header"},
      {"{}\n", ":1: is not a Lagoon dataset manifest"},
      {R"({"lagoon_dataset_manifest":1,"frames":4,"shard":[4,4],"run":{}})"
       "\n",
       "which no run writes"},
      {header + "not json\n", ":2: not a JSON line"},
      {header + R"({"frame":9,"files":[]})" + "\n", ":2: not a frame entry"},
      {header + R"({"frame":1,"files":[{"name":"../../etc/passwd","sha256":"x","bytes":1}]})" + "\n",
       ":2: not a frame entry"},
      {header + std::string(100000, '[') + "\n", ":2: not a JSON line"},
  };
  for (const auto& [text, needle] : cases) {
    write(dir / "m.jsonl", text);
    const Result<Manifest> m = read_manifest(dir / "m.jsonl");
    ASSERT_FALSE(m) << text.substr(0, 80);
    EXPECT_NE(m.error().message.find(needle), std::string::npos) << m.error().message;
  }
}

TEST(DatasetManifest, VerifyFindsEveryKindOfIncompleteSet) {
  {
    test::TempDir dir;
    write_set(dir.path(), 12, 4);
    const DatasetReport ok = verify_dataset(dir.path());
    EXPECT_TRUE(ok.problems.empty()) << all(ok);
    EXPECT_EQ(ok.frames, 12);
    EXPECT_EQ(ok.sets, 1);
    fs::remove(dir / "f.shard-2-of-4.jsonl");
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "shard 2 of 4 has no manifest; run it (--shard 2/4)"))
        << all(verify_dataset(dir.path()));
  }
  {
    test::TempDir dir;
    write_set(dir.path(), 12, 4);
    write(dir / "f_7.png", "frame 7!");
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "frame 7: ")) << all(verify_dataset(dir.path()));
    fs::remove(dir / "f_5.png");
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "f_5.png is missing"));
  }
  {
    test::TempDir dir;
    write_set(dir.path(), 12, 4);
    // A shard stopped before its last frame: its manifest lacks it.
    Result<Manifest> m = read_manifest(dir / "f.shard-1-of-4.jsonl");
    m->entries.pop_back();
    ASSERT_TRUE(ManifestWriter::create(dir / "f.shard-1-of-4.jsonl", *m));
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()),
                            "1 of 12 frames are not finished (the first is frame 9, shard 1)"))
        << all(verify_dataset(dir.path()));
  }
  {
    test::TempDir dir;
    write_set(dir.path(), 12, 4);
    // One shard from another run.
    Result<Manifest> m = read_manifest(dir / "f.shard-3-of-4.jsonl");
    m->run["scene"] = "b.json";
    ASSERT_TRUE(ManifestWriter::create(dir / "f.shard-3-of-4.jsonl", *m));
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "written by another run"));
  }
  {
    test::TempDir dir;
    write_set(dir.path(), 12, 4);
    Result<Manifest> m = read_manifest(dir / "f.shard-0-of-4.jsonl");
    m->entries.push_back(m->entries.front());
    ASSERT_TRUE(ManifestWriter::create(dir / "f.shard-0-of-4.jsonl", *m));
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "lists frame 0 again"));
  }
  {
    test::TempDir dir;
    EXPECT_TRUE(has_problem(verify_dataset(dir.path()), "no manifest"));
    EXPECT_TRUE(has_problem(verify_dataset(dir / "nope"), "not a folder"));
  }
}

}  // namespace
}  // namespace lagoon::dataset
