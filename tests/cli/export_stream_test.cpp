// lagoon export at scale: frames stream to disk (memory does not grow with --frames), the size is printed
// and checked against the free space first, and an error or a signal half-way leaves no output behind.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "io/npy.h"
#include "support/child_process.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

std::string export_command(const fs::path& out, int frames, int resolution) {
  return shell_quote(LAGOON_BINARY) + " export --scene " + kDefaultScene + " --out " +
         shell_quote(out.string()) + " --frames " + std::to_string(frames) +
         " --set 'ocean.cascades=[{\"patch_size_m\":100,\"resolution\":" + std::to_string(resolution) + "}]'";
}

uint64_t folder_bytes(const fs::path& dir) {
  uint64_t total = 0;
  for (const auto& e : fs::directory_iterator(dir)) total += fs::file_size(e.path());
  return total;
}

// Nothing of an export that did not finish: no output folder, no staging folder beside it.
void expect_no_output(const TempDir& dir) {
  for (const auto& e : fs::directory_iterator(dir.path())) ADD_FAILURE() << "left behind: " << e.path();
}

TEST(ExportStream, PrintsTheSizeItThenWrites) {
  TempDir dir;
  auto r = run_process(export_command(dir / "fields", 3, 64));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(will write ([0-9.]+) (B|KiB|MiB))"))) << r.output;
  const double unit = m[2] == "B" ? 1 : m[2] == "KiB" ? 1024 : 1024 * 1024;
  const double announced = std::stod(m[1]) * unit;
  const double written = double(folder_bytes(dir / "fields"));
  // Arrays exactly, meta.json within its 16 KiB allowance; the printed figure is rounded to 0.1 of a unit.
  EXPECT_GE(announced, written * 0.999) << r.output;
  EXPECT_LE(announced, written + 17 * 1024) << r.output;
  auto disp = io::read_npy(dir / "fields" / "cascade0_displacement.npy");
  ASSERT_TRUE(disp) << disp.error().message;
  EXPECT_EQ(disp->shape, (std::vector<size_t>{3, 64, 64, 3}));
}

TEST(ExportStream, RefusesAnOutputLargerThanTheFreeSpace) {
  TempDir dir;
  // 100000 frames of one 1024² cascade: 3.1 TiB, more than any test machine's disk.
  auto r = run_process(export_command(dir / "fields", 100000, 1024));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("needs 3.1 TiB but only"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("fewer --frames"), std::string::npos) << r.output;
  expect_no_output(dir);
}

TEST(ExportStream, MemoryDoesNotGrowWithTheNumberOfFrames) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed memory resident, so peak RSS says nothing here";
#endif
  TempDir dir;
  // One 256² cascade is 2 MiB a frame: 48 frames held in memory would add 96 MiB to the peak.
  ChildProcess few(export_command(dir / "few", 4, 256));
  const ChildProcess::Exit a = few.wait();
  ChildProcess many(export_command(dir / "many", 52, 256));
  const ChildProcess::Exit b = many.wait();
  ASSERT_EQ(a.code, 0) << few.output();
  ASSERT_EQ(b.code, 0) << many.output();
  EXPECT_LT(b.max_rss_kib - a.max_rss_kib, 24 * 1024)
      << "peak RSS " << a.max_rss_kib << " KiB for 4 frames, " << b.max_rss_kib << " KiB for 52";
  EXPECT_EQ(fs::file_size(dir / "many" / "cascade0_displacement.npy"), 128 + 52ull * 256 * 256 * 3 * 4);
}

void interrupt_and_check(int signal) {
  TempDir dir;
  const fs::path out = dir / "fields";
  fs::create_directories(out);
  { std::ofstream(out / "meta.json") << "an earlier export"; }
  ChildProcess child(export_command(out, 1000, 64));
  ASSERT_TRUE(child.wait_for_output("frame 3/1000", 120)) << child.output();
  child.send(signal);
  const ChildProcess::Exit exit = child.wait();
  EXPECT_EQ(exit.code, 128 + signal) << child.output();
  EXPECT_NE(child.output().find("interrupted by signal"), std::string::npos) << child.output();
  // The earlier export is untouched, and nothing of the interrupted one is anywhere.
  std::vector<fs::path> left;
  for (const auto& e : fs::recursive_directory_iterator(dir.path())) left.push_back(e.path());
  EXPECT_EQ(left, (std::vector<fs::path>{out, out / "meta.json"}));
  std::ifstream meta(out / "meta.json");
  std::string text;
  std::getline(meta, text);
  EXPECT_EQ(text, "an earlier export");
}

TEST(ExportStream, SigintLeavesNoPartialOutput) {
  interrupt_and_check(SIGINT);
}

TEST(ExportStream, SigtermLeavesNoPartialOutput) {
  interrupt_and_check(SIGTERM);
}

TEST(ExportStream, AWriteErrorHalfWayLeavesNoPartialOutput) {
  TempDir dir;
  // A file size limit stands in for a full disk: writes past it fail with EFBIG (SIGXFSZ ignored), as they
  // would with ENOSPC, a few frames in.
  auto r = run_process("ulimit -f 400; trap '' XFSZ; " + export_command(dir / "fields", 40, 64));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cascade0_"), std::string::npos) << r.output;  // the file is named
  expect_no_output(dir);
}

}  // namespace
}  // namespace lagoon::test
