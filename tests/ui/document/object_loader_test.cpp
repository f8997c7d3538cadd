// Opening an object in the GUI: a new object's up axis is the one its provenance.json declares
// (the Sweet Home 3D corpus writes its catalogs' y) and is not detected; without one it is
// detected from the geometry; a labelled object keeps its labels' axis. The units the record
// declares are known from the start, flagged as declared.
#include "ui/document/object_loader.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/annotate/units_record.h"
#include "support/test_paths.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

void writeBox(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 0.5\nv 2 0 0.5\nv 2 1 0.5\n"
                         "v 0 1 0.5\nf 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n";
}

TEST(ObjectLoader, ANewObjectTakesTheUpAxisItsProvenanceDeclares) {
  const fs::path dir = test::freshTempDir();
  writeBox(dir / "detected" / "box.obj");
  const auto detected =
      openDocument(dir / "detected" / "box.obj", dir / "detected" / "labels.json");
  EXPECT_TRUE(detected->labels().object.upConfidence.has_value());

  writeBox(dir / "declared" / "box.obj");
  std::ofstream(dir / "declared" / "provenance.json")
      << R"({"library": "Contributions", "up": "x"})";
  const auto declared =
      openDocument(dir / "declared" / "box.obj", dir / "declared" / "labels.json");
  EXPECT_EQ(declared->labels().object.up, "x");
  EXPECT_FALSE(declared->labels().object.upConfidence.has_value());

  // Labels beside the mesh decide over the record.
  ObjectLabels labels;
  labels.object.id = "box";
  labels.object.mesh = "box.obj";
  labels.object.up = "z";
  writeLabels(dir / "declared" / "labels.json", labels);
  const auto labelled =
      openDocument(dir / "declared" / "box.obj", dir / "declared" / "labels.json");
  EXPECT_EQ(labelled->labels().object.up, "z");
}

TEST(ObjectLoader, ANewObjectTakesTheUnitsItsProvenanceDeclares) {
  const fs::path dir = test::freshTempDir();
  writeBox(dir / "unknown" / "box.obj");
  const auto unknown = openDocument(dir / "unknown" / "box.obj", dir / "unknown" / "labels.json");
  EXPECT_FALSE(unknown->unitsKnown());

  writeBox(dir / "declared" / "box.obj");
  std::ofstream(dir / "declared" / "provenance.json")
      << R"({"library": "Contributions", "meters_per_unit": 0.01})";
  const auto declared =
      openDocument(dir / "declared" / "box.obj", dir / "declared" / "labels.json");
  EXPECT_TRUE(declared->unitsKnown());
  EXPECT_NEAR(declared->metersPerUnit(), 0.01, 1e-7);
  EXPECT_EQ(declared->labels().object.extra.value(kUnitsDeclaredByField, std::string()),
            "provenance.json");

  // Labels beside the mesh decide over the record.
  ObjectLabels labels;
  labels.object.id = "box";
  labels.object.mesh = "box.obj";
  writeLabels(dir / "declared" / "labels.json", labels);
  const auto labelled =
      openDocument(dir / "declared" / "box.obj", dir / "declared" / "labels.json");
  EXPECT_FALSE(labelled->unitsKnown());
}

TEST(ObjectLoader, AnObjectInAFolderOfItsOwnIsNamedAfterTheFolder) {
  const fs::path dir = test::freshTempDir();
  writeBox(dir / "bettinelli_frigo" / "frigo.obj");
  writeBox(dir / "lucapresidente_frigo" / "frigo.obj");
  EXPECT_EQ(openDocument(dir / "bettinelli_frigo" / "frigo.obj",
                         dir / "bettinelli_frigo" / "labels.json")->labels().object.id,
            "bettinelli_frigo");
  EXPECT_EQ(openDocument(dir / "lucapresidente_frigo" / "frigo.obj",
                         dir / "lucapresidente_frigo" / "labels.json")->labels().object.id,
            "lucapresidente_frigo");
  // Several meshes in one folder, each with its own labels file: named after the mesh.
  writeBox(dir / "loose" / "stove.obj");
  EXPECT_EQ(openDocument(dir / "loose" / "stove.obj", dir / "loose" / "stove.labels.json")
                ->labels().object.id,
            "stove");
}

}  // namespace
}  // namespace sagrid::ui
