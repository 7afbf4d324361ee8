// Bounded whole-file reads (core/bounded_file.h, io::read_file_bytes; issue 36): what is not a regular file
// (a device such as /dev/zero, a FIFO, a folder) is refused before a byte is read, and so is a file over
// the limit, without reading it (sparse files: their size costs no disk). The readers built on them
// (scene and camera-path JSON, CSV tables, glTF, PNG, NPY, manifests, metadata, demo scripts) inherit it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/bounded_file.h"
#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/png.h"
#include "optics/csv_table.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(BoundedFile, EachProblemIsNamedBeforeAnythingIsRead) {
  TempDir dir;
  EXPECT_EQ(check_file_to_read(dir / "nope", 100).problem, FileProblem::kMissing);
  EXPECT_EQ(check_file_to_read(dir.path(), 100).problem, FileProblem::kFolder);
  EXPECT_EQ(check_file_to_read("/dev/zero", 100).problem, FileProblem::kNotRegular);
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(check_file_to_read(fifo, 100).problem, FileProblem::kNotRegular);
  std::ofstream(dir / "big") << "x";
  fs::resize_file(dir / "big", std::uintmax_t{3} << 30);  // 3 GiB, sparse
  const FileCheck big = check_file_to_read(dir / "big", std::uintmax_t{16} << 20);
  EXPECT_EQ(big.problem, FileProblem::kTooLarge);
  EXPECT_EQ(big.size, std::uintmax_t{3} << 30);
  EXPECT_TRUE(contains(big.reason, "16 MiB")) << big.reason;
}

TEST(BoundedFile, AFileWithinTheLimitIsReadWhole) {
  TempDir dir;
  const std::string text = std::string("a,b\n1,2\n") + std::string(1000, 'z');
  std::ofstream(dir / "t.csv", std::ios::binary) << text;
  Result<std::string> read = read_bounded_file(dir / "t.csv", text.size());
  ASSERT_TRUE(read) << read.error().message;
  EXPECT_EQ(*read, text);
  EXPECT_FALSE(read_bounded_file(dir / "t.csv", text.size() - 1));  // one byte over
  Result<std::string> zero = read_bounded_file("/dev/zero", 100);
  ASSERT_FALSE(zero);
  EXPECT_TRUE(contains(zero.error().message, "not a regular file")) << zero.error().message;
}

// read_file_bytes read a pipe or device until it ended: /dev/zero never does, and opening a FIFO waited for
// a writer. Now both are refused (the FIFO without blocking), and a size limit holds.
TEST(BoundedFile, ReadFileBytesRefusesDevicesPipesAndOversizedFiles) {
  TempDir dir;
  Result<std::vector<std::byte>> zero = io::read_file_bytes("/dev/zero");
  ASSERT_FALSE(zero);
  EXPECT_TRUE(contains(zero.error().message, "/dev/zero: not a regular file")) << zero.error().message;
  const fs::path fifo = dir / "pipe.npy";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(io::read_file_bytes(fifo));
  std::ofstream(dir / "big.png") << "x";
  fs::resize_file(dir / "big.png", std::uintmax_t{2} << 30);  // 2 GiB, sparse: over the 1 GiB default
  Result<std::vector<std::byte>> big = io::read_file_bytes(dir / "big.png");
  ASSERT_FALSE(big);
  EXPECT_TRUE(contains(big.error().message, "more than the 1024 MiB")) << big.error().message;
  std::ofstream(dir / "small.bin", std::ios::binary) << "12345";
  Result<std::vector<std::byte>> small = io::read_file_bytes(dir / "small.bin");
  ASSERT_TRUE(small) << small.error().message;
  EXPECT_EQ(small->size(), 5u);
}

// The readers on top: each names the file and refuses the device or pipe.
TEST(BoundedFile, TheReadersOnTopRefuseADeviceNamingIt) {
  TempDir dir;
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const fs::path& path : {fs::path("/dev/zero"), fifo}) {
    Result<optics::CsvTable> table = optics::CsvTable::read_file(path);
    ASSERT_FALSE(table);
    EXPECT_TRUE(contains(table.error().message, path.string() + ": is not a regular file"))
        << table.error().message;
    Result<io::Image8> png = io::read_png(path);
    ASSERT_FALSE(png);
    EXPECT_TRUE(contains(png.error().message, path.string())) << png.error().message;
    Result<io::NpyArray> npy = io::read_npy(path);
    ASSERT_FALSE(npy);
    EXPECT_TRUE(contains(npy.error().message, "not a regular file")) << npy.error().message;
  }
}

}  // namespace
}  // namespace lagoon::test
