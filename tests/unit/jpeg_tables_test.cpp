// The JPEG Huffman-table check that stands in front of stb_image (engine/gltf/jpeg_tables.h): tables
// declaring more than 256 codes are refused wherever stb would read them, and bytes that only look like one
// inside another segment are not.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

#include "gltf/image_decode.h"
#include "gltf/jpeg_tables.h"

namespace lagoon::gltf::detail {
namespace {

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A DHT segment holding one table (class and id in `q`: 0x00 DC 0, 0x10 AC 0) whose 16 code counts are all
// `count` (the values follow, as zeros).
std::vector<uint8_t> dht(uint8_t count, uint8_t q = 0x00) {
  const size_t codes = 16u * count;
  const size_t length = 2 + 17 + codes;
  std::vector<uint8_t> s(2 + length, 0);  // the values stay zero
  s[0] = 0xFF;
  s[1] = 0xC4;
  s[2] = uint8_t(length >> 8);
  s[3] = uint8_t(length & 0xff);
  s[4] = q;
  for (size_t i = 0; i < 16; ++i) s[5 + i] = count;
  return s;
}

std::vector<uint8_t> join(std::initializer_list<std::vector<uint8_t>> parts) {
  std::vector<uint8_t> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

const std::vector<uint8_t> kSoi = {0xFF, 0xD8};
const std::vector<uint8_t> kSos = {0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00};
const std::vector<uint8_t> kEoi = {0xFF, 0xD9};
const std::vector<uint8_t> kAc0 = dht(1, 0x10);  // the AC table kSos's component uses besides DC 0

TEST(JpegTables, ATableOf256CodesPassesAndOneOf272IsRefusedWithItsOffset) {
  EXPECT_TRUE(check_jpeg_huffman_tables(join({kSoi, kAc0, dht(16), kSos, kEoi}), "img").ok());
  auto r = check_jpeg_huffman_tables(join({kSoi, kAc0, dht(17), kSos, kEoi}), "images[0] 'hull'");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("images[0] 'hull'"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("at byte 39 declares 272 codes"), std::string::npos) << r.error().message;
}

TEST(JpegTables, ATableAfterTheFirstScanIsCheckedToo) {
  // Progressive JPEGs define tables between scans; scan data can hide no legal 0xFF 0xC4.
  const std::vector<uint8_t> scan_data = {0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD0, 0x56};
  EXPECT_TRUE(
      check_jpeg_huffman_tables(join({kSoi, kAc0, dht(1), kSos, scan_data, dht(16), kSos, kEoi}), "img")
          .ok());
  EXPECT_FALSE(
      check_jpeg_huffman_tables(join({kSoi, kAc0, dht(1), kSos, scan_data, dht(17), kSos, kEoi}), "img")
          .ok());
  // After fill bytes, as stb reads a marker.
  EXPECT_FALSE(check_jpeg_huffman_tables(
                   join({kSoi, kAc0, dht(1), kSos, scan_data, {0xFF, 0xFF}, dht(17), kEoi}), "img")
                   .ok());
}

TEST(JpegTables, TheSameBytesInsideAnApplicationSegmentAreNotATable) {
  // An ICC profile or EXIF block may hold 0xFF 0xC4 followed by anything; stb skips the segment by its
  // length.
  const std::vector<uint8_t> bogus = dht(17);
  std::vector<uint8_t> app2 = {0xFF, 0xE2, uint8_t((bogus.size() + 2) >> 8),
                               uint8_t((bogus.size() + 2) & 0xff)};
  app2.insert(app2.end(), bogus.begin(), bogus.end());
  EXPECT_TRUE(check_jpeg_huffman_tables(join({kSoi, kAc0, app2, dht(16), kSos, kEoi}), "img").ok());
}

TEST(JpegTables, AScanUsingATableNeverDefinedIsRefused) {
  // stb does not clear its tables: decoding with one never defined reads uninitialised memory and indexes
  // past its arrays (fuzz_image found it: UBSan index 320 out of bounds for 'stbi_uc[256]').
  auto no_ac = check_jpeg_huffman_tables(join({kSoi, dht(1), kSos, kEoi}), "img");
  ASSERT_FALSE(no_ac.ok());
  EXPECT_NE(
      no_ac.error().message.find("scan at byte 39 uses Huffman table AC 0, which the file does not define"),
      std::string::npos)
      << no_ac.error().message;
  // Defined only after the scan that uses it is too late.
  EXPECT_FALSE(check_jpeg_huffman_tables(join({kSoi, dht(1), kSos, kAc0, kEoi}), "img").ok());

  const auto hostile = read_bytes(std::string(LAGOON_SOURCE_DIR) +
                                  "/tests/fuzz/regressions/image/jpeg-scan-uses-undefined-huffman-table.jpg");
  ASSERT_FALSE(hostile.empty());
  auto refused = decode_image(hostile, "images[1]", 1024);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("uses Huffman table AC 3"), std::string::npos)
      << refused.error().message;
}

TEST(JpegTables, RealJpegsDecodeAndTheFuzzerFindIsRefusedBeforeStbSeesIt) {
  const std::string fuzz = std::string(LAGOON_SOURCE_DIR) + "/tests/fuzz/";
  const auto sand = read_bytes(fuzz + "corpus/image/sand16.jpg");
  ASSERT_FALSE(sand.empty());
  auto decoded = decode_image(sand, "sand16.jpg", 1024);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  EXPECT_EQ(decoded->width, 16u);

  // fuzz_image's input: a DHT of 257+ codes that made stb_image write past its table (UBSan,
  // stb_image.h:1990).
  const auto hostile = read_bytes(fuzz + "regressions/image/jpeg-huffman-counts-over-256.jpg");
  ASSERT_FALSE(hostile.empty());
  auto refused = decode_image(hostile, "images[3]", 1024);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("Huffman table"), std::string::npos) << refused.error().message;
}

}  // namespace
}  // namespace lagoon::gltf::detail
