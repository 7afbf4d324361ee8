// End-to-end tests of the `lagoon` binary: exit codes, messages and no half-written output.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/png.h"
#include "support/run_process.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(LAGOON_TEST_ARTIFACTS) / "cli" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  // Nothing at all in the test's folder: no output, no temporary file.
  void expect_no_files() {
    for (const auto& e : fs::directory_iterator(dir_)) ADD_FAILURE() << "left behind: " << e.path();
  }
  std::string out(const std::string& name) { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(Cli, NoArgumentsPrintsUsageAndExits2) {
  auto r = lagoon("");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("usage: lagoon"), std::string::npos) << r.output;
}

TEST_F(Cli, UnknownCommandExits2) {
  auto r = lagoon("paint");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("unknown command 'paint'"), std::string::npos) << r.output;
}

TEST_F(Cli, EveryCommandHasHelp) {
  for (const char* command : {"info", "render", "export", "probe", "lut", "bench", "compare-images"}) {
    auto r = lagoon(std::string(command) + " --help");
    EXPECT_EQ(r.exit_code, 0) << command;
    EXPECT_NE(r.output.find(std::string("usage: lagoon ") + command), std::string::npos) << r.output;
  }
  auto r = lagoon("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("render"), std::string::npos);
}

TEST_F(Cli, RenderUsageErrorsExit2) {
  struct Case {
    std::string args, expected;
    bool prints_usage = true;
  } cases[] = {
      {"render --scene " + kDefaultScene, "missing --out"},
      {"render --out " + out("a.png"), "missing --scene"},
      {"render --scene " + kDefaultScene + " --out " + out("a.png") + " --width abc", "--width abc", false},
      {"render --scene " + kDefaultScene + " --out " + out("a.png") + " --time soon", "--time soon", false},
      {"render --scene " + kDefaultScene + " --out " + out("a.txt"), "must name a .png", false},
      {"render --scene " + kDefaultScene + " --out " + out("a.png") + " --colour red",
       "unknown option --colour"},
      {"render --scene " + kDefaultScene + " --out " + out("a.png") + " stray",
       "unexpected argument 'stray'"},
      {"render --scene " + kDefaultScene + " --out", "needs a value"},
  };
  for (const Case& c : cases) {
    auto r = lagoon(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    if (c.prints_usage) {
      EXPECT_NE(r.output.find("usage: lagoon render"), std::string::npos) << r.output;
    }
  }
  expect_no_files();
}

TEST_F(Cli, MissingSceneFileExits1AndNamesIt) {
  auto r = lagoon("render --scene " + out("nowhere.json") + " --out " + out("x.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("nowhere.json"), std::string::npos) << r.output;
  expect_no_files();
}

// Issue 36: `--scene /dev/zero` was read to 4.2 GB of memory before it was refused; a FIFO blocked. Both
// are refused before a byte is read, naming the file (the run is short and small, or ctest times it out).
TEST_F(Cli, ADeviceOrPipeAsTheSceneExits1WithoutReadingIt) {
  auto r = lagoon("render --scene /dev/zero --out " + out("x.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("/dev/zero: is not a regular file"), std::string::npos) << r.output;
  const std::string pipe = (fs::path(LAGOON_TEST_ARTIFACTS) / "cli" / "pipe.json").string();
  fs::remove(pipe);
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  r = lagoon("render --scene " + pipe + " --out " + out("x.png"));
  fs::remove(pipe);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("pipe.json: is not a regular file"), std::string::npos) << r.output;
  expect_no_files();
}

TEST_F(Cli, MalformedSceneExits1WithTheFileAndPosition) {
  const std::string scene = (fs::path(LAGOON_TEST_ARTIFACTS) / "cli" / "malformed.json").string();
  { std::ofstream(scene) << "{\n  \"camera\": { \"fov_deg\": 40,, }\n}\n"; }
  auto r = lagoon("render --scene " + scene + " --out " + out("x.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("malformed.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("line 2"), std::string::npos) << r.output;
  expect_no_files();
}

TEST_F(Cli, OutOfRangeOverrideExits1NamingTheField) {
  auto r = lagoon("render --scene " + kDefaultScene + " --out " + out("x.png") + " --set camera.fov_deg=500");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("camera.fov_deg"), std::string::npos) << r.output;
  auto typo = lagoon("render --scene " + kDefaultScene + " --out " + out("x.png") + " --set camera.fov=40");
  EXPECT_EQ(typo.exit_code, 1) << typo.output;
  EXPECT_NE(typo.output.find("fov_deg"), std::string::npos) << typo.output;
  auto tiny = lagoon("render --scene " + kDefaultScene + " --out " + out("x.png") + " --width 0");
  EXPECT_EQ(tiny.exit_code, 1) << tiny.output;
  EXPECT_NE(tiny.output.find("render.width"), std::string::npos) << tiny.output;
  expect_no_files();
}

TEST_F(Cli, UnwritableOutputExits1AndLeavesNothing) {
  { std::ofstream(out("file")) << "x"; }
  auto r =
      lagoon("render --scene " + kDefaultScene + " --out " + out("file") + "/x.png --width 32 --height 32");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("x.png"), std::string::npos) << r.output;
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir_)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "file");
  }
  EXPECT_EQ(entries, 1);
}

// The name on `lagoon info`'s "device   NAME (TYPE), index N" line (NAME may hold parentheses itself, as
// "llvmpipe (LLVM 15.0.6, 256 bits)" does); empty if there is no such line.
std::string device_name_from_info(const std::string& info) {
  std::istringstream lines(info);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("device ", 0) != 0) continue;
    const auto index = line.rfind(", index ");
    const auto type = index == std::string::npos ? index : line.rfind(" (", index);
    const auto start = line.find_first_not_of(' ', 6);
    if (type == std::string::npos || start >= type) return "";
    return line.substr(start, type - start);
  }
  return "";
}

TEST_F(Cli, RenderWritesThePngAndNamesTheDevice) {
  auto r = lagoon("render --scene " + kDefaultScene + " --out " + out("sub/dir/frame.png") +
                  " --width 96 --height 64 --time 1.5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frame.png"), std::string::npos) << r.output;
  const std::string device = device_name_from_info(lagoon("info").output);  // lavapipe, or a GPU
  ASSERT_FALSE(device.empty());
  EXPECT_NE(r.output.find("on " + device), std::string::npos) << device << "\n" << r.output;
  auto image = io::read_png(out("sub/dir/frame.png"));
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->width, 96u);
  EXPECT_EQ(image->height, 64u);
  for (const auto& e : fs::recursive_directory_iterator(dir_)) {
    if (e.is_regular_file()) {
      EXPECT_EQ(e.path().filename(), "frame.png") << "stray file " << e.path();
    }
  }
}

TEST_F(Cli, InfoNamesDeviceDriverAndLimits) {
  auto r = lagoon("info");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* s : {"device", "driver", "vulkan api", "max compute workgroup", "timestamp period"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
}

TEST_F(Cli, UnknownDeviceOverrideListsDevices) {
  // Whatever device this machine has (lavapipe, or a GPU), the list must name it.
  auto info = lagoon("info");
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const std::string device = device_name_from_info(info.output);
  ASSERT_FALSE(device.empty()) << "no device line in:\n" << info.output;
  auto r = lagoon("info", "LAGOON_DEVICE=no-such-gpu");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no-such-gpu"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(device), std::string::npos) << "'" << device << "' not listed in:\n" << r.output;
}

TEST_F(Cli, NoVulkanDeviceNamesThePackageToInstall) {
  auto r = lagoon("render --scene " + kDefaultScene + " --out " + out("x.png"),
                  "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("mesa-vulkan-drivers"), std::string::npos) << r.output;
  expect_no_files();
}

}  // namespace
}  // namespace lagoon::test
