#include "core/labels/labels.h"

#include <sys/stat.h>

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

const char* kValid = R"({
  "schema": "sagrid.labels/1",
  "object": {"id": "stove_01", "mesh": "mesh.glb", "sha256": "abc", "category": "stove",
             "up": "y", "units": "cm", "meters_per_unit": 0.01, "vendor": {"sku": 7}},
  "affordances": [
    {"type": "heatsource", "position": [0.1, 0.2, 0.3], "normal": [0, 0, 1],
     "status": "accepted", "confidence": 0.87, "source": "stove.heatsource@1a2b",
     "radius": 0.05, "notes": ["front left"]},
    {"type": "togglebutton", "position": [1, 2, 3], "status": "added", "source": "human"}],
  "review": {"state": "done", "updated": "2026-11-21T10:00:00Z", "reviewer": "ana"},
  "license": "CC-BY"
})";

fs::path writeText(const fs::path& dir, const std::string& text, const std::string& name = "labels.json") {
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The message of the FileError thrown by readLabels on `text`, or "" if it parsed.
std::string errorFor(const std::string& text) {
  const fs::path path = writeText(test::freshTempDir("err"), text);
  try {
    readLabels(path);
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_THAT(std::string(e.what()), HasSubstr(path.string()));
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

std::string withReplaced(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

TEST(Labels, ReadsCurrentSchema) {
  const auto labels = readLabels(writeText(test::freshTempDir(), kValid));
  EXPECT_EQ(labels.object.id, "stove_01");
  EXPECT_EQ(labels.object.mesh, "mesh.glb");
  EXPECT_EQ(labels.object.sha256, "abc");
  EXPECT_EQ(labels.object.category, "stove");
  EXPECT_EQ(labels.object.up, "y");
  ASSERT_EQ(labels.affordances.size(), 2u);
  const auto& a = labels.affordances[0];
  EXPECT_EQ(a.type, "heatsource");
  EXPECT_TRUE(a.position.isApprox(Eigen::Vector3f(0.1f, 0.2f, 0.3f)));
  ASSERT_TRUE(a.normal.has_value());
  EXPECT_TRUE(a.normal->isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_EQ(a.status, AffordanceStatus::Accepted);
  ASSERT_TRUE(a.confidence.has_value());
  EXPECT_FLOAT_EQ(*a.confidence, 0.87f);
  EXPECT_EQ(a.source, "stove.heatsource@1a2b");
  EXPECT_FALSE(labels.affordances[1].normal.has_value());
  EXPECT_FALSE(labels.affordances[1].confidence.has_value());
  EXPECT_EQ(labels.affordances[1].status, AffordanceStatus::Added);
  EXPECT_EQ(labels.reviewState, ReviewState::Done);
  EXPECT_EQ(labels.reviewUpdated, "2026-11-21T10:00:00Z");
  EXPECT_EQ(labels.ofType("togglebutton").size(), 1u);
  EXPECT_EQ(labels.ofType("fluidsource").size(), 0u);
  EXPECT_DOUBLE_EQ(metersPerUnit(labels), 0.01);
}

TEST(Labels, RewriteKeepsUnknownFieldsEverywhere) {
  const fs::path dir = test::freshTempDir();
  auto labels = readLabels(writeText(dir, kValid));
  labels.affordances[0].position = Eigen::Vector3f(4, 5, 6);
  const fs::path out = dir / "out.json";
  writeLabels(out, labels);

  const json written = json::parse(readFileBytes(out));
  EXPECT_EQ(written["license"], "CC-BY");
  EXPECT_EQ(written["object"]["units"], "cm");
  EXPECT_EQ(written["object"]["meters_per_unit"], 0.01);
  EXPECT_EQ(written["object"]["vendor"]["sku"], 7);
  EXPECT_EQ(written["affordances"][0]["radius"], 0.05);
  EXPECT_EQ(written["affordances"][0]["notes"][0], "front left");
  EXPECT_EQ(written["affordances"][0]["position"][2], 6.0);
  EXPECT_EQ(written["review"]["reviewer"], "ana");
  EXPECT_EQ(written["schema"], kLabelsSchema);

  // A second round trip is a fixed point.
  const auto again = readLabels(out);
  EXPECT_EQ(toJson(again), written);
  EXPECT_FALSE(fs::exists(dir / "out.json.tmp"));
}

TEST(Labels, SixUpAxesAndTheDetectionConfidenceRoundTrip) {
  const fs::path dir = test::freshTempDir();
  auto labels = readLabels(writeText(dir, withReplaced("\"up\": \"y\"", "\"up\": \"-x\", \"up_confidence\": 0.25")));
  EXPECT_EQ(labels.object.up, "-x");
  ASSERT_TRUE(labels.object.upConfidence.has_value());
  EXPECT_DOUBLE_EQ(*labels.object.upConfidence, 0.25);
  EXPECT_FALSE(labels.object.extra.contains("up_confidence"));  // a field, not an unknown extra
  const fs::path out = dir / "out.json";
  writeLabels(out, labels);
  const json written = json::parse(readFileBytes(out));
  EXPECT_EQ(written["object"]["up"], "-x");
  EXPECT_EQ(written["object"]["up_confidence"], 0.25);
  // Given or format-fixed axes carry no confidence.
  labels.object.upConfidence.reset();
  EXPECT_FALSE(toJson(labels)["object"].contains("up_confidence"));
  EXPECT_THAT(errorFor(withReplaced("\"up\": \"y\"", "\"up\": \"y\", \"up_confidence\": \"high\"")),
              HasSubstr("object.up_confidence"));
}

TEST(Labels, WriteIsAtomicAndFailsCleanlyForMissingFolder) {
  const fs::path dir = test::freshTempDir();
  ObjectLabels labels;
  labels.object.id = "x";
  labels.object.category = "sink";
  EXPECT_THROW(writeLabels(dir / "nope" / "labels.json", labels), FileError);
  EXPECT_FALSE(fs::exists(dir / "nope"));
  writeLabels(dir / "labels.json", labels);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "no temporary file left behind";
  EXPECT_EQ(readLabels(dir / "labels.json").object.id, "x");
}

TEST(Labels, ReadsRealDevSimplerForm) {
  const fs::path path = test::realDevDir() / "libero__flat_stove" / "labels.json";
  if (!fs::exists(path)) GTEST_SKIP() << "no real-dev data at " << path;
  const auto labels = readLabels(path);
  EXPECT_EQ(labels.object.id, "flat_stove");
  EXPECT_EQ(labels.object.category, "stove");
  EXPECT_EQ(labels.object.mesh, "mesh.obj");
  EXPECT_EQ(labels.object.up, "z");
  ASSERT_EQ(labels.affordances.size(), 2u);
  EXPECT_EQ(labels.affordances[0].type, "heatsource");
  EXPECT_TRUE(labels.affordances[0].position.isApprox(Eigen::Vector3f(0.15f, 0.0f, 0.022f)));
  EXPECT_EQ(labels.affordances[0].status, AffordanceStatus::Accepted);
  EXPECT_EQ(labels.affordances[0].extra["name"], "site:burner");
  EXPECT_EQ(labels.extra["gt_quality"], "annotated");
  EXPECT_DOUBLE_EQ(metersPerUnit(labels), 1.0);

  // Rewriting converts to the current schema and keeps the extra keys.
  const fs::path out = test::freshTempDir() / "labels.json";
  writeLabels(out, labels);
  const json written = json::parse(readFileBytes(out));
  EXPECT_EQ(written["schema"], kLabelsSchema);
  EXPECT_EQ(written["units"], "m");
  EXPECT_EQ(written["affordances"][1]["name"], "body:button(knob mesh centroid)");
  EXPECT_EQ(readLabels(out).affordances[1].type, "togglebutton");
}

TEST(Labels, AllRealDevFilesRead) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  int count = 0;
  for (const auto& entry : fs::directory_iterator(test::realDevDir())) {
    if (!fs::exists(entry.path() / "labels.json")) continue;
    const auto labels = readLabels(entry.path() / "labels.json");
    EXPECT_FALSE(labels.affordances.empty()) << entry.path();
    EXPECT_FALSE(labels.object.category.empty()) << entry.path();
    ++count;
  }
  EXPECT_EQ(count, 3);
}

TEST(LabelsErrors, MissingFileAndDirectory) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THROW(readLabels(dir / "none.json"), FileError);
  EXPECT_THROW(readLabels(dir), FileError);
}

TEST(LabelsErrors, NotJsonOrEmpty) {
  EXPECT_THAT(errorFor(""), HasSubstr("is empty"));
  EXPECT_THAT(errorFor("{\"schema\": "), HasSubstr("is not valid JSON"));
  EXPECT_THAT(errorFor("[1, 2]"), HasSubstr("top level"));
}

TEST(LabelsErrors, InvalidUtf8) {
  std::string text = withReplaced("\"CC-BY\"", "\"CC\xff\xfe-BY\"");
  EXPECT_THAT(errorFor(text), HasSubstr("not valid UTF-8"));
  // Overlong encoding of '/' and a lone surrogate are ill-formed too.
  EXPECT_THAT(errorFor(withReplaced("\"CC-BY\"", "\"\xc0\xaf\"")), HasSubstr("UTF-8"));
  EXPECT_THAT(errorFor(withReplaced("\"CC-BY\"", "\"\xed\xa0\x80\"")), HasSubstr("UTF-8"));
  // Well-formed multi-byte text is fine.
  EXPECT_EQ(errorFor(withReplaced("\"CC-BY\"", "\"Herd \xe2\x80\x94 K\xc3\xbc" "che \xf0\x9f\x94\xa5\"")), "");
}

TEST(LabelsErrors, WrongTypesNameTheField) {
  EXPECT_THAT(errorFor(withReplaced("[0.1, 0.2, 0.3]", "\"up\"")),
              HasSubstr("field 'affordances[0].position' must be an array of 3 numbers, got a string"));
  EXPECT_THAT(errorFor(withReplaced("[0.1, 0.2, 0.3]", "[0.1, 0.2]")),
              HasSubstr("affordances[0].position"));
  EXPECT_THAT(errorFor(withReplaced("[1, 2, 3]", "[1, \"2\", 3]")),
              HasSubstr("affordances[1].position"));
  EXPECT_THAT(errorFor(withReplaced("\"id\": \"stove_01\"", "\"id\": 5")),
              HasSubstr("field 'object.id' must be a string, got a number"));
  EXPECT_THAT(errorFor(withReplaced("0.87", "\"high\"")), HasSubstr("affordances[0].confidence"));
  EXPECT_THAT(errorFor(withReplaced("\"accepted\"", "\"maybe\"")),
              HasSubstr("affordances[0].status' has unknown value 'maybe'"));
  EXPECT_THAT(errorFor(withReplaced("\"up\": \"y\"", "\"up\": \"w\"")), HasSubstr("object.up"));
  EXPECT_THAT(errorFor(withReplaced("\"state\": \"done\"", "\"state\": 1")), HasSubstr("review.state"));
  EXPECT_THAT(errorFor(withReplaced("\"affordances\": [", "\"affordances\": {\"a\": 1}, \"x\": [")),
              HasSubstr("field 'affordances' must be an array"));
  EXPECT_THAT(errorFor(withReplaced("\"sagrid.labels/1\"", "\"sagrid.labels/9\"")),
              HasSubstr("unsupported version"));
}

TEST(LabelsErrors, MissingFieldsNameTheField) {
  EXPECT_THAT(errorFor(withReplaced("\"type\": \"heatsource\", ", "")),
              HasSubstr("field 'affordances[0].type' is missing"));
  EXPECT_THAT(errorFor(withReplaced("\"position\": [1, 2, 3], ", "")),
              HasSubstr("field 'affordances[1].position' is missing"));
  EXPECT_THAT(errorFor(withReplaced("\"status\": \"added\", ", "")),
              HasSubstr("field 'affordances[1].status' is missing"));
  EXPECT_THAT(errorFor(withReplaced("\"category\": \"stove\",", "")),
              HasSubstr("field 'object.category' is missing"));
  EXPECT_THAT(errorFor(R"({"schema": "sagrid.labels/1", "object": {"id": "a", "category": "b"}})"),
              HasSubstr("field 'affordances' is missing"));
  EXPECT_THAT(errorFor(R"({"affordances": []})"), HasSubstr("field 'object' is missing"));
  EXPECT_THAT(errorFor(R"({"object": {"id": "a"}, "affordances": []})"),
              HasSubstr("field 'schema' is missing"));
}

TEST(Labels, StatusAndReviewStrings) {
  for (auto s : {AffordanceStatus::Predicted, AffordanceStatus::Accepted, AffordanceStatus::Edited,
                 AffordanceStatus::Added}) {
    EXPECT_EQ(parseAffordanceStatus(toString(s)), s);
  }
  for (auto s : {ReviewState::Unreviewed, ReviewState::Done, ReviewState::Skipped}) {
    EXPECT_EQ(parseReviewState(toString(s)), s);
  }
  EXPECT_FALSE(parseAffordanceStatus("Accepted").has_value());
  EXPECT_EQ(currentUtcTimestamp().size(), 20u);
  EXPECT_EQ(currentUtcTimestamp().back(), 'Z');
}

// Issue 14, numbers validated where they enter: each of these files read without error and
// then became inf in URDF/MJCF, null in metadata.json, or crashed the viewport.
TEST(LabelsHostile, NumbersOutOfRangeNameTheFileAndField) {
  const fs::path bad = fs::path(SAGRID_TEST_DATA_DIR) / "bad";
  const std::pair<const char*, const char*> cases[] = {
      {"labels_number_overflow.json", "number overflow"},
      {"labels_position_minus_1e308.json", "field 'affordances[0].position' holds -1e+308"},
      {"labels_position_1e39.json", "field 'affordances[0].position' holds 1e+39"},
      {"labels_meters_per_unit_zero.json", "field 'object.meters_per_unit' is 0;"},
      {"labels_meters_per_unit_negative.json", "field 'object.meters_per_unit' is -1;"},
      {"labels_meters_per_unit_1e308.json", "field 'object.meters_per_unit' is 1e+308;"},
      {"labels_meters_per_unit_string.json",
       "field 'object.meters_per_unit' must be a number, got a string"},
  };
  for (const auto& [name, expected] : cases) {
    const fs::path path = bad / name;
    try {
      readLabels(path);
      ADD_FAILURE() << name << " was accepted";
    } catch (const FileError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << e.what();
      EXPECT_THAT(e.what(), HasSubstr(expected)) << name;
    }
  }
}

TEST(LabelsHostile, ConfidencesMustBeProbabilities) {
  json j = json::parse(kValid);
  j["affordances"][0]["confidence"] = 7.5;
  EXPECT_THAT(errorFor(j.dump()), HasSubstr("'affordances[0].confidence' is 7.5"));
  j = json::parse(kValid);
  j["object"]["up_confidence"] = -0.5;
  EXPECT_THAT(errorFor(j.dump()), HasSubstr("'object.up_confidence' is -0.5"));
}

// A million nested arrays crashed export and render (recursive copy); refused at parse.
TEST(LabelsHostile, DeepNestingIsRefusedBeforeParsing) {
  const std::string deep = R"({"schema": "sagrid.labels/1", "x": )" + std::string(1000000, '[') +
                           std::string(1000000, ']') + "}";
  EXPECT_THAT(errorFor(deep), HasSubstr("nests arrays and objects more than 64 levels deep"));
  // Brackets inside strings do not count.
  json j = json::parse(kValid);
  j["license"] = std::string(200, '[');
  EXPECT_EQ(errorFor(j.dump()), "");
}

// 200,000 points made render hang (20,000 took 8 s and 1.7 GB).
TEST(LabelsHostile, TooManyPointsIsAClearError) {
  json j = json::parse(kValid);
  json point = j["affordances"][1];
  j["affordances"] = json::array();
  for (int i = 0; i < 200000; ++i) j["affordances"].push_back(point);
  EXPECT_THAT(errorFor(j.dump()), HasSubstr("field 'affordances' holds 200000 points; at most "
                                            "1000 per object are supported"));
}

TEST(LabelsHostile, FifoAsLabelsIsRefusedAtOnce) {
  const fs::path fifo = test::freshTempDir() / "labels.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    readLabels(fifo);
    FAIL() << "a FIFO was read";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("FIFO"));
  }
}

}  // namespace
}  // namespace sagrid
