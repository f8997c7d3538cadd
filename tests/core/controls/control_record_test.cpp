// The control record of labels.json: written in the mesh file's frame, read back the same, and
// every malformed field refused with the file and field named.
#include "core/controls/control_record.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

ControlRecord lever() {
  ControlRecord record;
  record.part.triangles = {3, 4, 5, 9, 10};
  record.part.motion = ControlMotion::Lever;
  record.part.origin = PartOrigin::Material;
  record.part.axis = Eigen::Vector3f(1, 0, 0);
  record.part.pivot = Eigen::Vector3f(0.1f, -0.2f, 0.3f);
  record.part.radius = 0.05f;
  record.drives = 2;
  return record;
}

TEST(ControlRecord, RoundTripsInAYUpFile) {
  AffordancePoint point;
  writeControlRecord(point, lever(), UpAxis::Y);
  const nlohmann::json& json = point.extra[kControlField];
  EXPECT_EQ(json["joint"], "hinge");
  EXPECT_EQ(json["part"]["triangles"], nlohmann::json::parse("[[3, 3], [9, 2]]"));
  // z-up (0.1, -0.2, 0.3) is y-up (0.1, 0.3, 0.2).
  EXPECT_EQ(json["pivot"], nlohmann::json::parse("[0.1, 0.3, 0.2]"));
  const auto back = readControlRecord(point, UpAxis::Y, "labels.json");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->part.triangles, lever().part.triangles);
  EXPECT_EQ(back->part.motion, ControlMotion::Lever);
  EXPECT_EQ(back->part.origin, PartOrigin::Material);
  EXPECT_TRUE(back->part.pivot.isApprox(lever().part.pivot, 1e-6f));
  EXPECT_TRUE(back->part.axis.isApprox(lever().part.axis, 1e-6f));
  EXPECT_EQ(back->drives, 2);
  EXPECT_FALSE(back->confirmed);
  EXPECT_FALSE(json.contains("confirmed"));  // annotate's records do not say it
  EXPECT_FALSE(readControlRecord(AffordancePoint(), UpAxis::Z, "labels.json"));
  // The curator's record says so and reads back so, a marked part with it.
  ControlRecord curators = lever();
  curators.confirmed = true;
  curators.part.origin = PartOrigin::Marked;
  writeControlRecord(point, curators, UpAxis::Y);
  EXPECT_EQ(point.extra[kControlField]["confirmed"], true);
  EXPECT_TRUE(readControlRecord(point, UpAxis::Y, "labels.json")->confirmed);
  EXPECT_EQ(readControlRecord(point, UpAxis::Y, "labels.json")->part.origin, PartOrigin::Marked);
}

TEST(ControlRecord, MalformedRecordsNameTheFileAndField) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"motion", R"({"motion": "twist"})"},
      {"part.triangles", R"({"motion": "knob", "part": {"origin": "grown", "triangles": [[5, 2], [4, 1]]}, "axis": [0,0,1], "pivot": [0,0,0]})"},
      {"part.origin", R"({"motion": "knob", "part": {"origin": "glued", "triangles": []}, "axis": [0,0,1], "pivot": [0,0,0]})"},
      {"axis", R"({"motion": "knob", "part": {"origin": "grown", "triangles": []}, "axis": [0,0,0], "pivot": [0,0,0]})"},
      {"pivot", R"({"motion": "knob", "part": {"origin": "grown", "triangles": []}, "axis": [0,0,1], "pivot": [0,"x",0]})"},
      {"drives", R"({"motion": "knob", "part": {"origin": "grown", "triangles": []}, "axis": [0,0,1], "pivot": [0,0,0], "drives": -4})"},
      {"confirmed", R"({"motion": "knob", "part": {"origin": "marked", "triangles": []}, "axis": [0,0,1], "pivot": [0,0,0], "confirmed": "yes"})"},
  };
  for (const auto& [field, text] : cases) {
    SCOPED_TRACE(field);
    AffordancePoint point;
    point.extra[kControlField] = nlohmann::json::parse(text);
    try {
      readControlRecord(point, UpAxis::Z, "obj/labels.json");
      ADD_FAILURE() << "accepted";
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("obj/labels.json"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("control." + field), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sagrid
