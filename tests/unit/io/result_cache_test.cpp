// The result cache (io/result_cache.h) that keeps the water LUTs, the PBR tables and the environment map
// between runs: what was stored comes back byte for byte, under its own key only; a damaged, truncated or
// foreign file is a miss, never a wrong result; the folder stays bounded.
#include "io/result_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::byte> bytes_of(std::initializer_list<int> values) {
  std::vector<std::byte> out;
  for (int v : values) out.push_back(std::byte(v));
  return out;
}

io::ResultKey water_key(double elevation_deg) {
  io::ResultKey key("water");
  key.add("type", "jerlov-II").add("sun_elevation", elevation_deg);
  return key;
}

TEST(ResultCache, WhatWasStoredComesBackUnderItsKeyOnly) {
  TempDir dir("lagoon_result_cache");
  const io::ResultCache cache(dir.path());
  const auto payload = bytes_of({1, 2, 3, 250, 0, 7});
  EXPECT_FALSE(cache.load(water_key(30)));
  cache.store(water_key(30), payload);
  const auto loaded = cache.load(water_key(30));
  ASSERT_TRUE(loaded);
  EXPECT_EQ(*loaded, payload);
  // The smallest change of one input is another key (numbers are keyed exactly, not printed rounded).
  EXPECT_FALSE(cache.load(water_key(std::nextafter(30.0, 31.0))));
  io::ResultKey other_kind("dfg");
  other_kind.add("type", "jerlov-II").add("sun_elevation", 30.0);
  EXPECT_FALSE(cache.load(other_kind));
  // An array of plain values (the tables' form) comes back only with the count asked for.
  const std::vector<float> table = {0.5f, 1.5f, -2.0f};
  cache.store_vector(water_key(31), table);
  EXPECT_EQ(cache.load_vector<float>(water_key(31), 3), table);
  EXPECT_FALSE(cache.load_vector<float>(water_key(31), 2));
  EXPECT_FALSE(cache.load_vector<float>(water_key(31), 4));
}

TEST(ResultCache, NamesAndTextsCannotRunIntoEachOther) {
  // "a=xy" + "b=z" must not be the key "a=x" + "yb=z" or any other split of the same characters.
  io::ResultKey one("k"), two("k");
  one.add("a", "x\nb=1:z");
  two.add("a", "x").add("b", "z");
  EXPECT_NE(one.text(), two.text());
  const std::vector<double> values = {1.0, 2.0};
  io::ResultKey list("k"), scalars("k");
  list.add("v", values);
  scalars.add("v", 1.0).add("v", 2.0);
  EXPECT_NE(list.text(), scalars.text());
}

TEST(ResultCache, ADamagedOrTruncatedFileIsAMiss) {
  TempDir dir("lagoon_result_cache");
  const io::ResultCache cache(dir.path());
  const auto payload = bytes_of({10, 20, 30, 40, 50, 60, 70, 80});
  const fs::path file = cache.file(water_key(45));
  auto damage = [&](auto&& edit) {
    cache.store(water_key(45), payload);
    ASSERT_TRUE(cache.load(water_key(45)));
    std::string text;
    {
      std::ifstream in(file, std::ios::binary);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    edit(text);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    EXPECT_FALSE(cache.load(water_key(45)));
  };
  damage([](std::string& t) { t.back() ^= 1; });           // a payload byte flipped
  damage([](std::string& t) { t.pop_back(); });            // the last byte lost
  damage([](std::string& t) { t.resize(t.size() / 3); });  // cut inside the header
  damage([](std::string& t) { t[0] = 'X'; });              // not a result file at all
  damage([](std::string& t) { t.append("more", 4); });     // bytes after the payload
}

TEST(ResultCache, AFileFiledUnderAnotherKeyIsAMiss) {
  // A result copied over another key's file (by hand, a bad sync) says which key it belongs to.
  TempDir dir("lagoon_result_cache");
  const io::ResultCache cache(dir.path());
  cache.store(water_key(10), bytes_of({1}));
  fs::copy_file(cache.file(water_key(10)), cache.file(water_key(20)));
  EXPECT_FALSE(cache.load(water_key(20)));
}

TEST(ResultCache, NoFolderCachesNothingAndAnUnwritableOneIsNotAnError) {
  const io::ResultCache off{fs::path()};
  off.store(water_key(30), bytes_of({1, 2}));
  EXPECT_FALSE(off.load(water_key(30)));
  TempDir dir("lagoon_result_cache");
  std::ofstream(dir / "a-file") << "x";
  const io::ResultCache blocked(dir / "a-file" / "results");  // its parent is a file: nothing can be made
  blocked.store(water_key(30), bytes_of({1, 2}));
  EXPECT_FALSE(blocked.load(water_key(30)));
}

TEST(ResultCache, AtMostTheBoundOfEachKindIsKeptAndTheOthersAreLeftAlone) {
  TempDir dir("lagoon_result_cache");
  const io::ResultCache cache(dir.path());
  io::ResultKey dfg("dfg");
  dfg.add("code", "1");
  cache.store(dfg, bytes_of({9}));
  for (size_t i = 0; i < io::kMaxResultsPerKind + 10; ++i)
    cache.store(water_key(double(i)), bytes_of({int(i)}));
  size_t water = 0;
  for (const auto& entry : fs::directory_iterator(dir.path()))
    water += entry.path().filename().string().rfind("water-", 0) == 0;
  EXPECT_EQ(water, io::kMaxResultsPerKind);
  EXPECT_TRUE(cache.load(dfg));
  EXPECT_TRUE(cache.load(water_key(double(io::kMaxResultsPerKind + 9))));  // the newest stay
}

TEST(ResultCache, ByteReaderRefusesWhatAWriterDidNotWrite) {
  io::ByteWriter w;
  w.put(uint32_t{7});
  w.put_vector(std::vector<float>{1.5f, 2.5f});
  {
    io::ByteReader r(w.bytes());
    EXPECT_EQ(r.get<uint32_t>(), 7u);
    EXPECT_EQ(r.get_vector<float>(16), (std::vector<float>{1.5f, 2.5f}));
    EXPECT_TRUE(r.complete());
  }
  {
    io::ByteReader r(w.bytes());
    r.get<uint32_t>();
    EXPECT_TRUE(r.get_vector<float>(1).empty());  // more elements than the caller allows
    EXPECT_FALSE(r.complete());
  }
  {
    const auto& all = w.bytes();
    io::ByteReader r(std::span<const std::byte>(all).first(all.size() - 1));  // one byte short
    r.get<uint32_t>();
    EXPECT_TRUE(r.get_vector<float>(16).empty());
    EXPECT_FALSE(r.complete());
  }
  {
    io::ByteReader r(w.bytes());
    r.get<uint32_t>();
    EXPECT_FALSE(r.complete());  // bytes left over
  }
}

}  // namespace
}  // namespace lagoon::test
