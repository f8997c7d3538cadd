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

}  // namespace
}  // namespace sagrid
