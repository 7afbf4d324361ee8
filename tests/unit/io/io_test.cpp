#include <gtest/gtest.h>

#include <stb_image_write.h>
#include <unistd.h>
#include "support/temp_dir.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/png.h"

namespace lagoon::io {
namespace {

namespace fs = std::filesystem;

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("lagoon_io_test") {}
};

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::span<const std::byte> bytes_of(const std::string& s) {
  return std::as_bytes(std::span(s));
}

Image8 random_image(uint32_t width, uint32_t height, uint32_t seed) {
  Image8 image{width, height, std::vector<uint8_t>(size_t{width} * height * 4)};
  std::mt19937 rng(seed);
  for (uint8_t& v : image.rgba) v = static_cast<uint8_t>(rng());
  return image;
}

// ---- AtomicFile -------------------------------------------------------------------------------------------

TEST(AtomicFile, CommitWritesTargetAndLeavesNoTemporary) {
  TempDir dir;
  Result<AtomicFile> file = AtomicFile::create(dir / "out.bin");
  ASSERT_TRUE(file) << file.error().message;
  ASSERT_TRUE(file->write(bytes_of("hello ")));
  ASSERT_TRUE(file->write(bytes_of("world")));
  ASSERT_TRUE(file->commit());
  EXPECT_EQ(read_text(dir / "out.bin"), "hello world");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, TemporaryIsNamedAfterTargetPidAndCounterInSameFolder) {
  TempDir dir;
  Result<AtomicFile> a = AtomicFile::create(dir / "out.bin");
  Result<AtomicFile> b = AtomicFile::create(dir / "out.bin");
  ASSERT_TRUE(a && b);
  const std::string prefix = "out.bin.tmp-" + std::to_string(::getpid()) + "-";
  EXPECT_EQ(a->temp_path().parent_path(), dir.path());
  EXPECT_EQ(a->temp_path().filename().string().rfind(prefix, 0), 0u) << a->temp_path();
  EXPECT_NE(a->temp_path(), b->temp_path());
  EXPECT_EQ(entries(dir.path()).size(), 2u);  // both temporaries, no target yet
  EXPECT_FALSE(fs::exists(dir / "out.bin"));
}

TEST(AtomicFile, WithoutCommitNothingIsLeftBehind) {
  TempDir dir;
  {
    Result<AtomicFile> file = AtomicFile::create(dir / "out.bin");
    ASSERT_TRUE(file);
    ASSERT_TRUE(file->write(bytes_of("partial")));
  }
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(AtomicFile, WithoutCommitExistingTargetIsUntouched) {
  TempDir dir;
  write_text(dir / "out.bin", "old");
  {
    Result<AtomicFile> file = AtomicFile::create(dir / "out.bin");
    ASSERT_TRUE(file);
    ASSERT_TRUE(file->write(bytes_of("new")));
  }
  EXPECT_EQ(read_text(dir / "out.bin"), "old");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, CommitReplacesExistingTarget) {
  TempDir dir;
  write_text(dir / "out.bin", "old contents, longer");
  ASSERT_TRUE(write_file_atomic(dir / "out.bin", bytes_of("new")));
  EXPECT_EQ(read_text(dir / "out.bin"), "new");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, MovedFileStillCommitsAndMovedFromDoesNotDelete) {
  TempDir dir;
  Result<AtomicFile> created = AtomicFile::create(dir / "out.bin");
  ASSERT_TRUE(created);
  AtomicFile moved = std::move(*created);
  {
    AtomicFile sink = std::move(moved);
    ASSERT_TRUE(sink.write(bytes_of("x")) && sink.commit());
  }
  EXPECT_EQ(read_text(dir / "out.bin"), "x");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, MoveAssignmentDiscardsTheOverwrittenTemporary) {
  TempDir dir;
  Result<AtomicFile> a = AtomicFile::create(dir / "a.bin");
  Result<AtomicFile> b = AtomicFile::create(dir / "b.bin");
  ASSERT_TRUE(a && b);
  *a = std::move(*b);
  ASSERT_TRUE(a->commit());
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"b.bin"});
}

TEST(AtomicFile, WriteOrCommitAfterCommitFails) {
  TempDir dir;
  Result<AtomicFile> file = AtomicFile::create(dir / "out.bin");
  ASSERT_TRUE(file && file->commit());
  EXPECT_FALSE(file->write(bytes_of("late")));
  EXPECT_FALSE(file->commit());
  EXPECT_EQ(read_text(dir / "out.bin"), "");
}

TEST(AtomicFile, CreatesMissingParentFolders) {
  TempDir dir;
  ASSERT_TRUE(write_file_atomic(dir / "a/b/c/out.bin", bytes_of("deep")));
  EXPECT_EQ(read_text(dir / "a/b/c/out.bin"), "deep");
}

TEST(AtomicFile, UnderARegularFileFailsNamingPathAndReasonAndLeavesNothing) {
  TempDir dir;
  write_text(dir / "blocker", "I am a file");
  const fs::path target = dir / "blocker/sub/out.bin";
  Result<AtomicFile> file = AtomicFile::create(target);
  ASSERT_FALSE(file);
  EXPECT_NE(file.error().message.find(target.string()), std::string::npos) << file.error().message;
  EXPECT_NE(file.error().message.find("Not a directory"), std::string::npos) << file.error().message;
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"blocker"});
  EXPECT_EQ(read_text(dir / "blocker"), "I am a file");
}

TEST(AtomicFile, CommitOntoADirectoryFailsAndRemovesTemporary) {
  TempDir dir;
  fs::create_directories(dir / "target/inner");
  Result<AtomicFile> file = AtomicFile::create(dir / "target");
  ASSERT_TRUE(file);
  ASSERT_TRUE(file->write(bytes_of("data")));
  Result<void> committed = file->commit();
  ASSERT_FALSE(committed);
  EXPECT_NE(committed.error().message.find((dir / "target").string()), std::string::npos);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"target"});
  EXPECT_TRUE(fs::is_directory(dir / "target/inner"));
}

TEST(ReadFileBytes, MissingFileNamesPathAndReason) {
  TempDir dir;
  Result<std::vector<std::byte>> r = read_file_bytes(dir / "nope.bin");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find((dir / "nope.bin").string()), std::string::npos);
  EXPECT_NE(r.error().message.find("No such file or directory"), std::string::npos) << r.error().message;
}

TEST(ReadFileBytes, DirectoryIsAnError) {
  TempDir dir;
  Result<std::vector<std::byte>> r = read_file_bytes(dir.path());
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("Is a directory"), std::string::npos) << r.error().message;
}

// ---- PNG --------------------------------------------------------------------------------------------------

TEST(Image8, PixelAddressesRowMajorTopRowFirst) {
  Image8 image{3, 2, std::vector<uint8_t>(3 * 2 * 4)};
  image.pixel(2, 1)[0] = 7;
  image.pixel(1, 0)[3] = 9;
  EXPECT_EQ(image.rgba[(1 * 3 + 2) * 4 + 0], 7);
  EXPECT_EQ(image.rgba[(0 * 3 + 1) * 4 + 3], 9);
  const Image8& c = image;
  EXPECT_EQ(c.pixel(2, 1), image.rgba.data() + 20);
}

TEST(Png, RoundTripPreservesEveryByte) {
  TempDir dir;
  // Odd, non-square size catches stride and row-order mistakes; random bytes include all alpha values.
  const Image8 image = random_image(37, 11, 1234);
  ASSERT_TRUE(write_png(dir / "img.png", image));
  Result<Image8> back = read_png(dir / "img.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->width, 37u);
  EXPECT_EQ(back->height, 11u);
  EXPECT_EQ(back->rgba, image.rgba);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"img.png"});
}

TEST(Png, ASideBeyondTheLimitIsRefusedFromTheHeaderAndTheLimitItselfIsRead) {
  TempDir dir;
  ASSERT_TRUE(write_png(dir / "limit.png", random_image(kMaxPngSide, 1, 5)));
  Result<Image8> at_limit = read_png(dir / "limit.png");
  ASSERT_TRUE(at_limit) << at_limit.error().message;
  EXPECT_EQ(at_limit->width, kMaxPngSide);

  ASSERT_TRUE(write_png(dir / "wide.png", random_image(1, kMaxPngSide + 1, 6)));
  Result<Image8> wide = read_png(dir / "wide.png");
  ASSERT_FALSE(wide);
  EXPECT_NE(wide.error().message.find("wide.png: 1x16385 pixels is larger than the limit of 16384 per side"),
            std::string::npos)
      << wide.error().message;
}

TEST(Png, WritesIntoMissingNestedFolder) {
  TempDir dir;
  const fs::path path = dir / "x/y/z/img.png";
  ASSERT_TRUE(write_png(path, random_image(4, 4, 1)));
  Result<Image8> back = read_png(path);
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->rgba, random_image(4, 4, 1).rgba);
}

// Byte 25 of a PNG is the IHDR colour type: 2 = RGB, 6 = RGBA.
TEST(Png, OpaqueImagesAreWrittenAsRgbAndReadBackExactly) {
  TempDir dir;
  Image8 opaque = random_image(19, 7, 99);
  for (size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 255;
  ASSERT_TRUE(write_png(dir / "opaque.png", opaque));
  EXPECT_EQ(read_text(dir / "opaque.png")[25], 2) << "an opaque image should be stored as RGB";
  Result<Image8> back = read_png(dir / "opaque.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->rgba, opaque.rgba);

  Image8 one_translucent = opaque;
  one_translucent.rgba.back() = 254;  // the last pixel's alpha: the scan must reach the end
  ASSERT_TRUE(write_png(dir / "rgba.png", one_translucent));
  EXPECT_EQ(read_text(dir / "rgba.png")[25], 6) << "an image with alpha should keep it";
  back = read_png(dir / "rgba.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->rgba, one_translucent.rgba);
}

TEST(Png, FileStartsWithPngSignature) {
  TempDir dir;
  ASSERT_TRUE(write_png(dir / "img.png", random_image(2, 2, 3)));
  EXPECT_EQ(read_text(dir / "img.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(Png, RgbFileIsReadAsOpaqueRgba) {
  TempDir dir;
  const std::vector<uint8_t> rgb = {10, 20, 30, 40, 50, 60};  // 2x1
  std::vector<char> encoded;
  auto append = [](void* ctx, void* data, int size) {
    auto* out = static_cast<std::vector<char>*>(ctx);
    out->insert(out->end(), static_cast<char*>(data), static_cast<char*>(data) + size);
  };
  ASSERT_NE(stbi_write_png_to_func(append, &encoded, 2, 1, 3, rgb.data(), 6), 0);
  write_text(dir / "rgb.png", std::string(encoded.begin(), encoded.end()));
  Result<Image8> back = read_png(dir / "rgb.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->rgba, (std::vector<uint8_t>{10, 20, 30, 255, 40, 50, 60, 255}));
}

TEST(Png, MissingFileErrorNamesPath) {
  TempDir dir;
  const fs::path path = dir / "missing.png";
  Result<Image8> r = read_png(path);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("No such file"), std::string::npos) << r.error().message;
}

TEST(Png, NonPngErrorNamesPath) {
  TempDir dir;
  const fs::path path = dir / "text.png";
  write_text(path, "this is not an image at all");
  Result<Image8> r = read_png(path);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("not a PNG"), std::string::npos) << r.error().message;
}

TEST(Png, TruncatedPngErrorNamesPath) {
  TempDir dir;
  ASSERT_TRUE(write_png(dir / "full.png", random_image(16, 16, 5)));
  const std::string full = read_text(dir / "full.png");
  const fs::path path = dir / "cut.png";
  write_text(path, full.substr(0, full.size() / 2));
  Result<Image8> r = read_png(path);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
}

TEST(Png, AChunkLongerThanTheFileIsRefusedWithLibpngsReason) {
  // stb_image grew its buffer to the declared 1 GiB (2 GiB after doubling) before finding the data missing;
  // libpng reads the chunk as a stream and stops where the file does.
  TempDir dir;
  ASSERT_TRUE(write_png(dir / "full.png", random_image(16, 16, 5)));
  std::string bytes = read_text(dir / "full.png");
  const size_t idat = bytes.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  bytes.replace(idat - 4, 4, std::string("\x40\x00\x00\x00", 4));
  write_text(dir / "long.png", bytes);
  Result<Image8> r = read_png(dir / "long.png");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("long.png: cannot decode the PNG (libpng: "), std::string::npos)
      << r.error().message;
}

TEST(Png, InconsistentImageIsRejectedAndNothingWritten) {
  TempDir dir;
  Image8 bad{4, 4, std::vector<uint8_t>(10)};
  Result<void> r = write_png(dir / "bad.png", bad);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find((dir / "bad.png").string()), std::string::npos);
  EXPECT_FALSE(write_png(dir / "empty.png", Image8{}));
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(Png, WriteUnderRegularFileFailsWithReasonAndLeavesNothing) {
  TempDir dir;
  write_text(dir / "blocker", "x");
  const fs::path path = dir / "blocker/img.png";
  Result<void> r = write_png(path, random_image(2, 2, 9));
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("Not a directory"), std::string::npos) << r.error().message;
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"blocker"});
}

// ---- NPY --------------------------------------------------------------------------------------------------

struct ParsedHeader {
  uint8_t major = 0, minor = 0;
  size_t header_len = 0;
  std::string header;
  std::string data;
};

ParsedHeader split_npy(const std::string& file) {
  ParsedHeader p;
  p.major = static_cast<uint8_t>(file[6]);
  p.minor = static_cast<uint8_t>(file[7]);
  p.header_len = static_cast<uint8_t>(file[8]) | static_cast<size_t>(static_cast<uint8_t>(file[9])) << 8;
  p.header = file.substr(10, p.header_len);
  p.data = file.substr(10 + p.header_len);
  return p;
}

TEST(Npy, HeaderFollowsVersion1Spec) {
  TempDir dir;
  std::vector<float> data(2 * 3 * 4);
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<float>(i) * 0.5f - 3.0f;
  const size_t shape[] = {2, 3, 4};
  ASSERT_TRUE(write_npy(dir / "a.npy", data, shape));

  const std::string file = read_text(dir / "a.npy");
  ASSERT_GE(file.size(), 10u);
  EXPECT_EQ(file.substr(0, 6), "\x93NUMPY");
  const ParsedHeader p = split_npy(file);
  EXPECT_EQ(p.major, 1);
  EXPECT_EQ(p.minor, 0);
  EXPECT_EQ((10 + p.header_len) % 64, 0u) << "magic + version + length + header must be 64-byte aligned";
  const std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 4), }";
  ASSERT_EQ(p.header.substr(0, dict.size()), dict);
  EXPECT_EQ(p.header.back(), '\n');
  EXPECT_EQ(p.header.find_first_not_of(' ', dict.size()), p.header.size() - 1) << "padding must be spaces";
  // Data: little-endian IEEE float32 in C order, directly after the header.
  ASSERT_EQ(p.data.size(), data.size() * 4);
  for (size_t i = 0; i < data.size(); ++i) {
    uint32_t bits = 0;
    for (int b = 3; b >= 0; --b) bits = bits << 8 | static_cast<uint8_t>(p.data[i * 4 + b]);
    float value;
    std::memcpy(&value, &bits, 4);
    EXPECT_EQ(value, data[i]) << i;
  }
}

TEST(Npy, ShapeTupleUsesPythonSyntax) {
  TempDir dir;
  const float one[] = {1.0f};
  const float five[] = {1, 2, 3, 4, 5};
  const size_t shape1[] = {5};
  ASSERT_TRUE(write_npy(dir / "v.npy", five, shape1));
  ASSERT_TRUE(write_npy(dir / "s.npy", one, std::span<const size_t>()));
  EXPECT_NE(split_npy(read_text(dir / "v.npy")).header.find("'shape': (5,), }"), std::string::npos);
  EXPECT_NE(split_npy(read_text(dir / "s.npy")).header.find("'shape': (), }"), std::string::npos);
  for (const char* name : {"v.npy", "s.npy"}) {
    EXPECT_EQ((10 + split_npy(read_text(dir / name)).header_len) % 64, 0u) << name;
  }
}

TEST(Npy, RoundTrip) {
  TempDir dir;
  std::vector<float> data = {0.0f, -0.0f, 1.5f, -2.25f, 3.4e38f, 1e-45f,
                             7.0f, 8.0f,  9.0f, 10.0f,  11.0f,   12.0f};
  const size_t shape[] = {3, 1, 4};
  ASSERT_TRUE(write_npy(dir / "sub/a.npy", data, shape));
  Result<NpyArray> back = read_npy(dir / "sub/a.npy");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->shape, (std::vector<size_t>{3, 1, 4}));
  ASSERT_EQ(back->data.size(), data.size());
  EXPECT_EQ(std::memcmp(back->data.data(), data.data(), data.size() * 4), 0);
  EXPECT_EQ(entries(dir / "sub"), std::vector<std::string>{"a.npy"});
}

TEST(Npy, EmptyArrayRoundTrips) {
  TempDir dir;
  const size_t shape[] = {0, 4};
  ASSERT_TRUE(write_npy(dir / "e.npy", std::span<const float>(), shape));
  Result<NpyArray> back = read_npy(dir / "e.npy");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->shape, (std::vector<size_t>{0, 4}));
  EXPECT_TRUE(back->data.empty());
}

TEST(Npy, ShapeMismatchIsRejectedAndNothingWritten) {
  TempDir dir;
  const float data[] = {1, 2, 3, 4, 5};
  const size_t shape[] = {2, 3};
  Result<void> r = write_npy(dir / "a.npy", data, shape);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("(2, 3)"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find((dir / "a.npy").string()), std::string::npos) << r.error().message;
  EXPECT_TRUE(entries(dir.path()).empty());
}

// Builds a version 1.0 file by hand, for inputs write_npy never produces.
std::string npy_file(const std::string& dict, const std::string& data) {
  std::string header = dict;
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string file = "\x93NUMPY\x01";
  file += '\0';
  file += static_cast<char>(header.size() & 0xff);
  file += static_cast<char>(header.size() >> 8);
  return file + header + data;
}

TEST(Npy, ReadsHandWrittenFileWithDoubleQuotesAndNoTrailingComma) {
  TempDir dir;
  const float values[] = {1.0f, 2.0f};
  write_text(dir / "a.npy", npy_file(R"({"shape": (2,), "fortran_order": False, "descr": "<f4"})",
                                     std::string(reinterpret_cast<const char*>(values), 8)));
  Result<NpyArray> r = read_npy(dir / "a.npy");
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->shape, std::vector<size_t>{2});
  EXPECT_EQ(r->data, (std::vector<float>{1.0f, 2.0f}));
}

TEST(Npy, ReadErrorsNameThePathAndTheProblem) {
  TempDir dir;
  const std::string four_bytes(4, '\0');
  struct Case {
    std::string name, contents, expected;
  };
  const Case cases[] = {
      {"double.npy",
       npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", std::string(8, '\0')), "'<f8'"},
      {"big.npy", npy_file("{'descr': '>f4', 'fortran_order': False, 'shape': (1,), }", four_bytes), "'>f4'"},
      {"fortran.npy", npy_file("{'descr': '<f4', 'fortran_order': True, 'shape': (1,), }", four_bytes),
       "fortran_order"},
      {"short.npy", npy_file("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", four_bytes),
       "does not match"},
      {"garbled.npy", npy_file("{'descr': '<f4', 'shape': (1,), }", four_bytes), "malformed header"},
      {"magic.npy", "PK\x03\x04 a zip file, not npy", "wrong magic"},
      {"version.npy", std::string("\x93NUMPY\x09\x00\x00\x00", 10), "version 9.0"},
  };
  for (const Case& c : cases) {
    write_text(dir / c.name, c.contents);
    Result<NpyArray> r = read_npy(dir / c.name);
    ASSERT_FALSE(r) << c.name;
    EXPECT_NE(r.error().message.find((dir / c.name).string()), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(c.expected), std::string::npos) << r.error().message;
  }
  Result<NpyArray> missing = read_npy(dir / "missing.npy");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find((dir / "missing.npy").string()), std::string::npos);
}

}  // namespace
}  // namespace lagoon::io
