#include "core/curation/prediction_seed.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/labels/labels.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

void predicted(const fs::path& file, const std::string& mesh) {
  ObjectLabels labels;
  labels.object.id = "x";
  labels.object.mesh = mesh;
  labels.object.category = "stove";
  AffordancePoint p;
  p.type = "heatsource";
  labels.affordances = {p};
  fs::create_directories(file.parent_path());
  writeLabels(file, labels);
}

TEST(PredictionSeed, AnnotatesOutputIsWrittenBesideItsMeshesInsideTheRootOnly) {
  const fs::path dir = test::freshTempDir();
  fs::create_directories(dir / "data" / "x");
  test::writeFile(dir / "data" / "x" / "mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  predicted(dir / "pred" / "x" / "labels.json", "../../data/x/mesh.obj");
  const auto beside = [](const fs::path& mesh) { return mesh.parent_path() / "labels.json"; };
  EXPECT_EQ(seedPredictions(dir / "pred", dir / "data", beside), 1u);
  const ObjectLabels seeded = readLabels(dir / "data" / "x" / "labels.json");
  EXPECT_EQ(seeded.object.mesh, "mesh.obj");
  EXPECT_EQ(seeded.affordances.size(), 1u);
  predicted(dir / "pred" / "y" / "labels.json", "../../../outside/mesh.obj");
  EXPECT_THROW(seedPredictions(dir / "pred", dir / "data", beside), FileError);
}

}  // namespace
}  // namespace sagrid
