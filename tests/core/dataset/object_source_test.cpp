#include "core/dataset/object_source.h"

#include <gtest/gtest.h>

#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

TEST(ObjectSource, TheLabelsRepositoryThenTheProvenanceBesideTheMeshThenTheFallback) {
  const fs::path dir = test::freshTempDir();
  ObjectLabels labels;
  EXPECT_EQ(objectSource(labels, dir / "mesh.obj", "real-val"), "real-val");
  test::writeFile(dir / "provenance.json", R"({"library": "Scopia", "package": "sweethome3d-furniture"})");
  EXPECT_EQ(objectSource(labels, dir / "mesh.obj", "real-val"), "Scopia");
  labels.object.extra["provenance"] = {{"repo", "owner/name"}};
  EXPECT_EQ(objectSource(labels, dir / "mesh.obj", "real-val"), "owner/name");
  test::writeFile(dir / "provenance.json", "{ not json");
  labels.object.extra.erase("provenance");
  EXPECT_EQ(objectSource(labels, dir / "mesh.obj", "real-val"), "real-val");
}

TEST(ObjectSource, TheUnitsAProvenanceRecordDeclares) {
  const fs::path dir = test::freshTempDir();
  EXPECT_FALSE(declaredMetersPerUnit(dir / "mesh.obj"));  // no record
  test::writeFile(dir / "provenance.json",
                  R"({"library": "Contributions", "meters_per_unit": 0.2799})");
  EXPECT_DOUBLE_EQ(declaredMetersPerUnit(dir / "mesh.obj").value_or(0), 0.2799);
  for (const char* text :
       {R"({"meters_per_unit": null})", R"({"meters_per_unit": 0})", R"({"meters_per_unit": -1})",
        R"({"meters_per_unit": "cm"})", R"({"repo": "owner/name"})", "{ not json", "[1]"}) {
    test::writeFile(dir / "provenance.json", text);
    EXPECT_FALSE(declaredMetersPerUnit(dir / "mesh.obj")) << text;
  }
}

TEST(ObjectSource, TheUpAxisAProvenanceRecordDeclares) {
  const fs::path dir = test::freshTempDir();
  EXPECT_FALSE(declaredUpAxis(dir / "mesh.obj"));
  test::writeFile(dir / "provenance.json", R"({"library": "Scopia", "up": "y"})");
  EXPECT_EQ(declaredUpAxis(dir / "mesh.obj"), UpAxis::Y);
  for (const char* text :
       {R"({"up": "sideways"})", R"({"up": 2})", R"({"library": "Scopia"})", "{ no"}) {
    test::writeFile(dir / "provenance.json", text);
    EXPECT_FALSE(declaredUpAxis(dir / "mesh.obj")) << text;
  }
}

}  // namespace
}  // namespace sagrid
