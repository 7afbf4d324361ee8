#include "scene/scene.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#ifndef LAGOON_SOURCE_DIR
#define LAGOON_SOURCE_DIR "."  // running by hand from the repository root
#endif

namespace lagoon::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kSource = "scenes/x.json";

// Fails with the whole message when a part is missing, so a failing test shows what the user would see.
testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "missing \"" << part << "\" in:\n" << text;
}

// The error message of a parse that must fail.
std::string ErrorOf(const Result<Scene>& result) {
  EXPECT_FALSE(result.ok()) << "expected the scene to be rejected";
  return result.ok() ? std::string() : result.error().message;
}

std::string ParseError(const std::string& text) {
  return ErrorOf(parse_scene(json::parse(text), kSource));
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each test gets its own directory for scene files.
class SceneFileTest : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("lagoon_scene_test_" + std::to_string(getpid()) + "_" + std::string(info->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  fs::path dir_;
};

// ---- Reading ----

TEST(SceneParse, EmptyObjectGivesDefaults) {
  Result<Scene> scene = parse_scene(json::object(), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->source, fs::path());
  EXPECT_EQ(scene->camera.position, glm::vec3(0.f, 6.f, -40.f));
  EXPECT_EQ(scene->camera.look_at, glm::vec3(0.f));
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 55.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 0.1f);
  EXPECT_FLOAT_EQ(scene->camera.far_m, 5000.f);
  EXPECT_FLOAT_EQ(scene->sun.elevation_deg, 35.f);
  EXPECT_FLOAT_EQ(scene->sun.azimuth_deg, 210.f);
  EXPECT_FLOAT_EQ(scene->sun.intensity, 1.f);
  EXPECT_EQ(scene->render.width, 1280u);
  EXPECT_EQ(scene->render.height, 720u);
  EXPECT_FLOAT_EQ(scene->render.exposure, 1.f);
  EXPECT_FLOAT_EQ(scene->render.gamma, 2.2f);
  EXPECT_FLOAT_EQ(scene->time_s, 0.f);
}

TEST(SceneParse, EmptyBlocksGiveDefaults) {
  Result<Scene> scene = parse_scene(json::parse(R"({"camera": {}, "sun": {}, "render": {}})"), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 55.f);
}

TEST(SceneParse, ReadsEveryField) {
  Result<Scene> scene = parse_scene(json::parse(R"({
    "comment": "all fields",
    "camera": {"position": [1, 2, 3], "look_at": [4, 5, 6.5], "fov_deg": 40, "near_m": 0.5, "far_m": 900,
               "comment": "c"},
    "sun": {"elevation_deg": -10, "azimuth_deg": 360, "intensity": 2.5},
    "render": {"width": 64, "height": 48.0, "exposure": 0.5, "gamma": 1.8},
    "time_s": 12.5
  })"),
                                    kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->camera.position, glm::vec3(1.f, 2.f, 3.f));
  EXPECT_EQ(scene->camera.look_at, glm::vec3(4.f, 5.f, 6.5f));
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 40.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 0.5f);
  EXPECT_FLOAT_EQ(scene->camera.far_m, 900.f);
  EXPECT_FLOAT_EQ(scene->sun.elevation_deg, -10.f);
  EXPECT_FLOAT_EQ(scene->sun.azimuth_deg, 360.f);
  EXPECT_FLOAT_EQ(scene->sun.intensity, 2.5f);
  EXPECT_EQ(scene->render.width, 64u);
  EXPECT_EQ(scene->render.height, 48u);  // 48.0 is a whole number
  EXPECT_FLOAT_EQ(scene->render.exposure, 0.5f);
  EXPECT_FLOAT_EQ(scene->render.gamma, 1.8f);
  EXPECT_FLOAT_EQ(scene->time_s, 12.5f);
}

// ---- Validation errors: file name, JSON path, what is wrong, how to fix ----

TEST(SceneErrors, UnknownFieldSuggestsClosest) {
  const std::string message = ParseError(R"({"camera": {"fov_dg": 40}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_dg: unknown field"));
  EXPECT_TRUE(Contains(message, "did you mean 'fov_deg'?"));
}

TEST(SceneErrors, UnknownFieldSuggestsAcrossMissingUnitSuffix) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near": 1}})"), "did you mean 'near_m'?"));
}

TEST(SceneErrors, UnknownFieldWithoutCloseMatchListsAllowedFields) {
  const std::string message = ParseError(R"({"sun": {"colour": [1, 1, 1]}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: sun.colour: unknown field"));
  EXPECT_FALSE(Contains(message, "did you mean"));
  EXPECT_TRUE(Contains(message, "elevation_deg, azimuth_deg, intensity, comment"));
}

TEST(SceneErrors, UnknownTopLevelBlock) {
  const std::string message = ParseError(R"({"camra": {}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camra: unknown field"));
  EXPECT_TRUE(Contains(message, "did you mean 'camera'?"));
}

TEST(SceneErrors, StringForNumber) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": "wide"}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: expected a number, got string \"wide\""));
  EXPECT_TRUE(Contains(message, "allowed: number 1 to 170 deg"));
}

TEST(SceneErrors, BooleanForNumber) {
  EXPECT_TRUE(Contains(ParseError(R"({"sun": {"intensity": true}})"),
                       "sun.intensity: expected a number, got boolean true"));
}

TEST(SceneErrors, OutOfRange) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": 200}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: 200 is out of range"));
  EXPECT_TRUE(Contains(message, "allowed: number 1 to 170 deg (default 55)"));
}

TEST(SceneErrors, AzimuthDoesNotWrap) {
  EXPECT_TRUE(Contains(ParseError(R"({"sun": {"azimuth_deg": 370}})"),
                       "sun.azimuth_deg: 370 is out of range; allowed: number 0 to 360 deg (default 210)"));
  EXPECT_TRUE(
      Contains(ParseError(R"({"sun": {"azimuth_deg": -10}})"), "sun.azimuth_deg: -10 is out of range"));
}

TEST(SceneErrors, OpenLowerBound) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near_m": 0}})"), "camera.near_m: 0 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near_m": 0}})"), "allowed: number > 0 m (default 0.1)"));
  // Positive as a double but 0 as a float: must not slip through as near_m = 0.
  EXPECT_TRUE(
      Contains(ParseError(R"({"camera": {"near_m": 1e-50}})"), "camera.near_m: 1e-50 is out of range"));
}

TEST(SceneErrors, FractionalForInteger) {
  const std::string message = ParseError(R"({"render": {"width": 640.5}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: render.width: 640.5 is not a whole number"));
  EXPECT_TRUE(Contains(message, "; allowed: whole number 16 to 8192 px (default 1280)"));
}

TEST(SceneErrors, IntegerOutOfRange) {
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": -720}})"), "render.height: -720 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": 8193}})"), "render.height: 8193 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": 18446744073709551615}})"),
                       "render.height: 18446744073709551615 is out of range"));
}

TEST(SceneErrors, StringForInteger) {
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"width": "1280"}})"),
                       "render.width: expected an integer, got string \"1280\""));
}

TEST(SceneErrors, Vec3WithTwoElements) {
  const std::string message = ParseError(R"({"camera": {"position": [1, 2]}})");
  EXPECT_TRUE(Contains(
      message, "scenes/x.json: camera.position: expected [x, y, z], got array [1,2] with 2 elements"));
  EXPECT_TRUE(Contains(message, "allowed: 3 finite numbers [x, y, z] in m (default [0, 6, -40])"));
}

TEST(SceneErrors, Vec3NotAnArray) {
  EXPECT_TRUE(
      Contains(ParseError(R"({"camera": {"look_at": 5}})"), "camera.look_at: expected [x, y, z], got 5"));
}

TEST(SceneErrors, Vec3ElementNotANumber) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"position": [1, "2", 3]}})"),
                       "scenes/x.json: camera.position[1]: expected a number, got string \"2\""));
}

TEST(SceneErrors, NonFiniteNumbers) {
  // JSON text cannot spell NaN, but documents built in memory can, and 1e999 parses as infinity.
  json document = {{"camera", {{"fov_deg", std::nan("")}}}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)),
                       "camera.fov_deg: NaN is not a finite 32-bit float; allowed: number 1 to 170 deg"));
  document = {{"time_s", std::numeric_limits<double>::infinity()}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)), "time_s: infinity is not a finite"));
  document = {{"camera", {{"position", {0.0, -std::numeric_limits<double>::infinity(), 0.0}}}}};
  EXPECT_TRUE(
      Contains(ErrorOf(parse_scene(document, kSource)), "camera.position[1]: -infinity is not a finite"));
  // Finite as a double but not as a float.
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"position": [0, 1e300, 0]}})"),
                       "camera.position[1]: 1e+300 is not a finite 32-bit float"));
}

TEST(SceneErrors, BlockNotAnObject) {
  const std::string message = ParseError(R"({"camera": 5})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera: expected an object {...}, got 5"));
  EXPECT_TRUE(Contains(message, "leave it out to use the defaults"));
}

TEST(SceneErrors, TopLevelNotAnObject) {
  const std::string message = ParseError(R"([1, 2])");
  EXPECT_TRUE(Contains(message, "scenes/x.json: (top level): expected a JSON object {...}, got array"));
}

TEST(SceneErrors, CommentMustBeAString) {
  const std::string message = ParseError(R"({"sun": {"comment": 3}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: sun.comment: expected a string, got 3"));
}

TEST(SceneErrors, FarMustExceedNear) {
  const std::string message = ParseError(R"({"camera": {"near_m": 10, "far_m": 5}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.far_m: must be > near_m"));
  EXPECT_TRUE(Contains(message, "got far_m 5 and near_m 10; raise far_m or lower near_m"));
}

TEST(SceneErrors, LookAtMustDifferFromPosition) {
  const std::string message = ParseError(R"({"camera": {"position": [1, 2, 3], "look_at": [1, 2, 3]}})");
  EXPECT_TRUE(Contains(message, "camera.look_at: must be different from position"));
}

TEST(SceneErrors, ReportsEveryProblemOnItsOwnLine) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": 0}, "render": {"gamma": 9}, "tme_s": 1})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: 0 is out of range"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: render.gamma: 9 is out of range"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: tme_s: unknown field; did you mean 'time_s'?"));
}

TEST(SceneErrors, InvalidUtf8DoesNotThrow) {
  json document = {{"camera", {{"fov_deg", "\xff\xfe"}}}, {"\xff", 1}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)), "camera.fov_deg: expected a number"));
}

// ---- Files ----

TEST_F(SceneFileTest, LoadsFileAndRecordsSource) {
  const fs::path path = Write("a.json", R"({"camera": {"fov_deg": 30}})");
  Result<Scene> scene = load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->source, path);
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 30.f);
}

TEST_F(SceneFileTest, MissingFile) {
  const fs::path path = dir_ / "nope.json";
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": file not found; check the path"));
}

TEST_F(SceneFileTest, DirectoryInsteadOfFile) {
  EXPECT_TRUE(Contains(ErrorOf(load_scene(dir_)), dir_.string() + ": is a directory, not a scene file"));
}

TEST_F(SceneFileTest, UnreadableFile) {
  const fs::path path = Write("locked.json", "{}");
  fs::permissions(path, fs::perms::none);
  if (std::ifstream(path).good()) GTEST_SKIP() << "running with permissions that bypass file modes (root)";
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": cannot be opened: Permission denied"));
}

TEST_F(SceneFileTest, MalformedJsonReportsLineAndColumn) {
  const fs::path path = Write("bad.json", "{\n  \"camera\": {\n    \"fov_deg\": 40,\n  }\n}\n");
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": invalid JSON: parse error at line 4, column 3"));
  EXPECT_TRUE(Contains(message, "no comments or trailing commas"));
}

TEST_F(SceneFileTest, EmptyFile) {
  const fs::path path = Write("empty.json", "");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": invalid JSON: parse error at line 1"));
}

TEST_F(SceneFileTest, NumberTooLargeForJsonParser) {
  const fs::path path = Write("huge.json", R"({"time_s": 1e999})");
  EXPECT_TRUE(
      Contains(ErrorOf(load_scene(path)), path.string() + ": invalid JSON: number overflow parsing '1e999'"));
}

TEST_F(SceneFileTest, DuplicateKeyIsAnError) {
  const fs::path path = Write("dup.json", R"({"camera": {"fov_deg": 40, "fov_deg": 50}, "sun": {}})");
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_deg: field appears more than once"));
}

TEST_F(SceneFileTest, ValidationErrorsNameTheFile) {
  const fs::path path = Write("range.json", R"({"render": {"exposure": 0}})");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": render.exposure: 0 is out of range"));
}

// ---- Overrides ----

TEST(ApplyOverride, SetsParsedJsonValue) {
  json document = json::object();
  ASSERT_TRUE(apply_override(document, "camera.fov_deg=40").ok());
  ASSERT_TRUE(apply_override(document, "camera.position=[1, 2, 3]").ok());
  EXPECT_EQ(document["camera"]["fov_deg"], 40);
  EXPECT_EQ(document["camera"]["position"], json::parse("[1, 2, 3]"));
}

TEST(ApplyOverride, NonJsonValueBecomesString) {
  json document = json::object();
  ASSERT_TRUE(apply_override(document, "comment=hello world").ok());
  ASSERT_TRUE(apply_override(document, "sun.comment=").ok());
  EXPECT_EQ(document["comment"], "hello world");
  EXPECT_EQ(document["sun"]["comment"], "");
}

TEST(ApplyOverride, MissingEquals) {
  json document = json::object();
  const Result<void> result = apply_override(document, "camera.fov_deg");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(Contains(result.error().message, "--set camera.fov_deg: missing '='"));
  EXPECT_TRUE(Contains(result.error().message, "expected the form --set path=value"));
}

TEST(ApplyOverride, EmptyPathOrSegment) {
  json document = json::object();
  for (const char* bad : {"=40", " =40", "camera..fov_deg=40", ".fov_deg=1", "camera.=1"}) {
    const Result<void> result = apply_override(document, bad);
    ASSERT_FALSE(result.ok()) << bad;
    EXPECT_TRUE(Contains(result.error().message, "expected the form --set path=value")) << bad;
  }
  EXPECT_EQ(document, json::object());
}

TEST(ApplyOverride, ThroughNonObjectIsAnError) {
  json document = {{"camera", {{"fov_deg", 40}}}};
  const Result<void> result = apply_override(document, "camera.fov_deg.x=1");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(
      Contains(result.error().message,
               "--set camera.fov_deg.x=1: camera.fov_deg is 40, not an object, so it has no field 'x'"));
  EXPECT_TRUE(
      Contains(result.error().message, "set camera.fov_deg as a whole, e.g. --set camera.fov_deg=40"));
}

TEST_F(SceneFileTest, OverrideCreatesMissingBlock) {
  const fs::path path = Write("no_render.json", R"({"camera": {}})");
  const std::vector<std::string> overrides = {"render.width=64"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->render.width, 64u);
  EXPECT_EQ(scene->render.height, 720u);
}

TEST_F(SceneFileTest, OverrideTakesPrecedenceOverFileAndLastOneWins) {
  const fs::path path = Write("fov.json", R"({"camera": {"fov_deg": 30, "near_m": 2}})");
  const std::vector<std::string> overrides = {"camera.fov_deg=40", "camera.fov_deg=45", "time_s=3"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 45.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 2.f);  // untouched fields keep the file's value
  EXPECT_FLOAT_EQ(scene->time_s, 3.f);
}

TEST_F(SceneFileTest, OverrideOfUnknownFieldIsRejectedLikeTheFile) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_dg=40"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_dg: unknown field; did you mean 'fov_deg'?"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_dg=40)"));
}

TEST_F(SceneFileTest, OverrideValueIsValidated) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg=wide", "camera.position=[1,2]"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "camera.fov_deg: expected a number, got string \"wide\""));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_deg=wide)"));
  EXPECT_TRUE(Contains(message, "camera.position: expected [x, y, z], got array [1,2] with 2 elements"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.position=[1,2])"));
}

TEST_F(SceneFileTest, OverrideCreatingObjectInPlaceOfNumberIsRejected) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg.x=1"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_deg: expected a number, got object {\"x\":1}"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_deg.x=1)"));
}

TEST_F(SceneFileTest, MalformedOverrideNamesFileAndExpectedForm) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": --set camera.fov_deg: missing '='"));
  EXPECT_TRUE(Contains(message, "expected the form --set path=value"));
}

TEST_F(SceneFileTest, OverrideThroughNonObjectFails) {
  const fs::path path = Write("s.json", R"({"camera": {"position": [0, 1, 2]}})");
  const std::vector<std::string> overrides = {"camera.position.x=1"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "camera.position is array [0,1,2], not an object"));
  EXPECT_TRUE(Contains(message, "e.g. --set camera.position=[0,1,2]"));
}

// ---- Helpers ----

TEST(JsonFields, ClosestMatch) {
  const std::vector<std::string> fields = {"position", "look_at", "fov_deg", "near_m", "far_m"};
  EXPECT_EQ(closest_match("fov_dge", fields), "fov_deg");
  EXPECT_EQ(closest_match("FOV_DEG", fields), "fov_deg");
  EXPECT_EQ(closest_match("fov", fields), "fov_deg");
  EXPECT_EQ(closest_match("lookat", fields), "look_at");
  EXPECT_EQ(closest_match("colour", fields), "");
}

TEST(JsonFields, BoundsDescribe) {
  EXPECT_EQ(Bounds::between(1, 170).describe(), "1 to 170");
  EXPECT_EQ(Bounds::above(0).describe(), "> 0");
  EXPECT_EQ(Bounds::at_least(0.5).describe(), ">= 0.5");
  EXPECT_EQ(Bounds::any().describe(), "any");
}

// A block using the field kinds the scene does not use yet.
struct Extra {
  bool enabled = false;
  std::string name = "reef";
};
void read_extra(ObjectReader& r, Extra& e) {
  r.flag("enabled", e.enabled, "Switch.");
  r.text("name", e.name, "Label.");
}

TEST(JsonFields, FlagAndText) {
  Diagnostics diag(kSource);
  Extra extra;
  json document = {{"enabled", true}, {"name", "atoll"}};
  ObjectReader reader(document, "extra", diag);
  read_extra(reader, extra);
  reader.finish();
  EXPECT_TRUE(diag.ok());
  EXPECT_TRUE(extra.enabled);
  EXPECT_EQ(extra.name, "atoll");

  document = {{"enabled", "yes"}, {"name", 3}};
  ObjectReader bad(document, "extra", diag);
  read_extra(bad, extra);
  bad.finish();
  const std::string message = diag.to_error().message;
  EXPECT_TRUE(Contains(message, "scenes/x.json: extra.enabled: expected true or false, got string \"yes\""));
  EXPECT_TRUE(Contains(message, "scenes/x.json: extra.name: expected a string, got 3"));

  std::vector<FieldInfo> fields;
  ObjectReader describe("extra", fields);
  read_extra(describe, extra);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[1].path, "extra.name");
  EXPECT_EQ(fields[1].type, "string");
}

// ---- Repository files ----

TEST(SceneRepository, DefaultSceneLoads) {
  const fs::path path = fs::path(LAGOON_SOURCE_DIR) / "scenes" / "default.json";
  Result<Scene> scene = load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_GT(scene->camera.position.y, 1.f);  // above the water, looking out toward the horizon
  EXPECT_GT(scene->camera.far_m, 8000.f);    // horizon from 5 m is ~8 km away
}

// The reference table in the docs is generated from the same declarations the parser uses.
TEST(SceneRepository, DocsFieldReferenceIsUpToDate) {
  const std::string docs = ReadText(fs::path(LAGOON_SOURCE_DIR) / "docs" / "scene-format.md");
  const std::string begin = "<!-- BEGIN FIELD REFERENCE";
  const std::string end = "<!-- END FIELD REFERENCE -->";
  const size_t b = docs.find(begin), e = docs.find(end);
  ASSERT_NE(b, std::string::npos) << "docs/scene-format.md lacks the field reference markers";
  ASSERT_NE(e, std::string::npos);
  const size_t table_start = docs.find('\n', b) + 1;
  const std::string expected = to_markdown_table(scene_fields());
  EXPECT_EQ(docs.substr(table_start, e - table_start), expected)
      << "Paste this table between the markers in docs/scene-format.md:\n"
      << expected;
}

TEST(SceneRepository, DocsExampleIsValid) {
  const std::string docs = ReadText(fs::path(LAGOON_SOURCE_DIR) / "docs" / "scene-format.md");
  const size_t start = docs.find("```json\n");
  ASSERT_NE(start, std::string::npos);
  const size_t end = docs.find("```", start + 8);
  const std::string example = docs.substr(start + 8, end - start - 8);
  const json document = json::parse(example, nullptr, /*allow_exceptions=*/false);
  ASSERT_FALSE(document.is_discarded()) << example;
  Result<Scene> scene = parse_scene(document, "docs example");
  EXPECT_TRUE(scene.ok()) << scene.error().message;
}

}  // namespace
}  // namespace lagoon::scene
