// The curated data a guarded update refuses to learn from or be judged on: labels far outside
// their mesh, one mesh labelled twice in disagreement, a held-out object that is also training
// data; sound data passes. Generated stoves stand in for curated objects.
#include "core/training/curated_data_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/dataset/labels_mesh.h"
#include "core/mesh/mesh_import.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Sets {
  fs::path train, heldOut;
};

Sets generatedSets() {
  const fs::path dir = test::freshTempDir();
  gen::generateDataset({{"stove", 2, 41}}, gen::MeshFormat::Obj, dir / "train");
  gen::generateDataset({{"stove", 2, 42}}, gen::MeshFormat::Obj, dir / "held-out");
  return {dir / "train", dir / "held-out"};
}

// Changes the labels of the first object of `dir`; returns its labels file.
template <typename Change>
fs::path changeFirstLabels(const fs::path& dir, Change change) {
  const fs::path file = readDataset(dir).front().labels;
  ObjectLabels labels = readLabels(file);
  change(labels);
  writeLabels(file, labels);
  return file;
}

// Copies the first object of `from` into `to` as a new object of its manifest (the same mesh
// bytes; its category read from its labels).
fs::path copyFirstObject(const fs::path& from, const fs::path& to) {
  const DatasetEntry entry = readDataset(from).front();
  const std::string id = "copy_of_" + entry.id;
  fs::copy(entry.labels.parent_path(), to / id, fs::copy_options::recursive);
  const nlohmann::json line = {{"id", id},
                               {"labels", id + "/labels.json"},
                               {"mesh", id + "/" + entry.mesh.filename().string()}};
  std::ofstream(to / "manifest.jsonl", std::ios::app) << line.dump() << "\n";
  return to / id / "labels.json";
}

Eigen::AlignedBox3f readMeshBounds(const fs::path& labelsFile) {
  const ObjectLabels labels = readLabels(labelsFile);
  return importMesh(meshForLabels(labels, labelsFile), ImportOptions(upAxisOrZ(labels.object.up))).bounds();
}

TEST(CuratedDataCheck, SoundDataHasNoProblem) {
  const Sets sets = generatedSets();
  EXPECT_TRUE(curatedDataProblems({{sets.train}, sets.heldOut, {}}).empty());
  EXPECT_NO_THROW(requireSoundCuratedData({{sets.train}, sets.heldOut, {}}));
}

TEST(CuratedDataCheck, LabelsFarOutsideTheirMeshAreNamed) {
  const Sets sets = generatedSets();
  // Labels written in centimetres for a mesh in metres.
  const fs::path file = changeFirstLabels(sets.train, [](ObjectLabels& l) {
    for (auto& p : l.affordances) p.position *= 100.0f;
  });
  const auto problems = curatedDataProblems({{sets.train}, sets.heldOut, {}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr(file.string()));
  EXPECT_THAT(problems[0], HasSubstr("outside its mesh"));
  try {
    requireSoundCuratedData({{sets.train}, sets.heldOut, {}});
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("nothing was trained and the current model stays"));
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
  }
}

TEST(CuratedDataCheck, OneMeshLabelledTwiceInDisagreementIsNamed) {
  const Sets sets = generatedSets();
  const fs::path copy = copyFirstObject(sets.train, sets.train);
  ObjectLabels labels = readLabels(copy);
  // A point moved by a third of the object's size (generated files come in various units).
  const Eigen::Vector3f size = readMeshBounds(copy).sizes();
  labels.affordances.front().position += size / 3;
  writeLabels(copy, labels);
  auto problems = curatedDataProblems({{sets.train}, sets.heldOut, {}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr(copy.string()));
  EXPECT_THAT(problems[0], HasSubstr("differently"));
  EXPECT_THAT(problems[0], HasSubstr("no counterpart"));

  labels.affordances.pop_back();
  writeLabels(copy, labels);
  problems = curatedDataProblems({{sets.train}, sets.heldOut, {}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr(" points vs "));

  labels.object.category = "none";
  writeLabels(copy, labels);
  EXPECT_THAT(curatedDataProblems({{sets.train}, {}, {}}).front(), HasSubstr("category stove vs none"));
}

TEST(CuratedDataCheck, AHeldOutObjectThatIsAlsoTrainingDataIsNamed) {
  const Sets sets = generatedSets();
  const fs::path copy = copyFirstObject(sets.train, sets.heldOut);
  const auto problems = curatedDataProblems({{sets.train}, sets.heldOut, {}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr(copy.string()));
  EXPECT_THAT(problems[0], HasSubstr("one held out and one trained on"));
  // The same copy inside the training data alone is no problem: the labels agree.
  EXPECT_TRUE(curatedDataProblems({{sets.train, sets.heldOut}, {}, {}}).empty());
}

}  // namespace
}  // namespace sagrid
