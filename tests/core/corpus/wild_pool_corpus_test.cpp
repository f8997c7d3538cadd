#include "core/corpus/wild_pool_corpus.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/eval/part_agreement.h"
#include "core/eval/part_truth.h"
#include "core/labels/labels.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// A pool object as the pool lays it out: the mesh, a texture in a sub-folder, look.png and
// provenance.json.
void addPoolObject(const fs::path& pool, const std::string& id, const std::string& repo, const std::string& mesh) {
  fs::create_directories(pool / id / "textures");
  test::writeFile(pool / id / "model.obj", mesh);
  test::writeFile(pool / id / "textures" / "t.png", "png");
  test::writeFile(pool / id / "look.png", "png");
  const nlohmann::json provenance{{"repo", repo}, {"commit", "abc"}, {"path", "assets/model.obj"},
                                  {"kind", "stove"}, {"licence", "CC0"}, {"sha256", sha256Hex(mesh)},
                                  {"bytes", mesh.size()}};
  test::writeFile(pool / id / "provenance.json", provenance.dump());
}

fs::path labelsFolder(const fs::path& root, const std::string& sha) {
  ObjectLabels labels;
  labels.object.id = "a";
  labels.object.mesh = "model.obj";
  labels.object.sha256 = sha;
  labels.object.category = "stove";
  labels.object.up = "y";
  AffordancePoint p;
  p.type = "heatsource";
  p.position = {0.2f, 0.2f, 0.0f};
  p.status = AffordanceStatus::Added;
  labels.affordances.push_back(p);
  fs::create_directories(root / "a");
  writeLabels(root / "a" / "labels.json", labels);
  test::writeFile(root / "split.json", R"({"wild-train": ["owner/one"], "wild-val": ["owner/two"]})");
  return root;
}

TEST(WildPoolCorpus, CuratedObjectsGoToTheirRepositorysSplitWithProvenanceTheRestStayUnlabelled) {
  const fs::path dir = test::freshTempDir();
  addPoolObject(dir / "pool", "a", "owner/one", kTriangle);
  addPoolObject(dir / "pool", "b", "owner/two", kTriangle + "v 0 0 1\n");
  WildCorpusOptions options;
  options.pool = dir / "pool";
  options.out = dir / "out";
  options.labelsDir = labelsFolder(dir / "labels", sha256Hex(kTriangle));
  const WildCorpusSummary summary = buildWildCorpus(options);
  EXPECT_EQ(summary.countsByDataset.at("wild-train"), 1);
  EXPECT_EQ(summary.countsByDataset.at("unlabelled"), 1);
  EXPECT_EQ(summary.countsByCategory.at("stove"), 1);
  const auto train = readDataset(dir / "out" / "wild-train");
  ASSERT_EQ(train.size(), 1u);
  EXPECT_EQ(train[0].id, "a");
  EXPECT_EQ(train[0].category, "stove");
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "wild-train" / "a" / "textures" / "t.png"));
  EXPECT_FALSE(fs::exists(dir / "out" / "wild-train" / "a" / "look.png"));
  const ObjectLabels labels = readLabels(train[0].labels);
  EXPECT_EQ(labels.object.extra["source"], "wild-pool");
  EXPECT_EQ(labels.object.extra["provenance"]["repo"], "owner/one");
  EXPECT_EQ(labels.affordances.size(), 1u);
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "unlabelled" / "b" / "model.obj"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "corpus.json"));
}

TEST(WildPoolCorpus, AChangedMeshIsOneErrorNamingTheObjectAndTheOutputIsLeftAlone) {
  const fs::path dir = test::freshTempDir();
  addPoolObject(dir / "pool", "a", "owner/one", kTriangle);
  WildCorpusOptions options;
  options.pool = dir / "pool";
  options.out = dir / "out";
  options.labelsDir = labelsFolder(dir / "labels", std::string(64, '0'));
  try {
    buildWildCorpus(options);
    FAIL() << "labels of another mesh were accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("wild-pool object a: object.sha256 0000"));
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  // The pool's own record disagrees with its file: named too.
  test::writeFile(dir / "pool" / "a" / "model.obj", kTriangle + "# edited\n");
  try {
    readWildPool(dir / "pool");
    FAIL() << "a changed pool mesh was read";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("wild-pool object a: the mesh's sha256 is"));
  }
}

TEST(WildPoolCorpus, TheSplitNamesEachRepositoryOnce) {
  const fs::path dir = test::freshTempDir();
  const auto file = test::writeFile(dir / "split.json", R"({"wild-train": ["r"], "wild-val": ["r"]})");
  EXPECT_THROW(readWildSplit(file), FileError);
  EXPECT_EQ(readWildSplit(test::writeFile(dir / "ok.json", R"({"wild-train": ["r"], "wild-val": []})")).at("r"),
            "wild-train");
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

// The shipped wild labels against the pool itself (skipped where ../shared is absent): every
// object curated, every sha256 matching its mesh, every repository placed by the split, and the
// counts the dataset README states.
TEST(WildPoolCorpus, TheShippedLabelsCoverThePoolExactly) {
  const fs::path pool = test::sharedDir() / "data" / "wild-pool";
  if (!fs::is_directory(pool)) GTEST_SKIP() << "no " << pool;
  WildCorpusOptions options;
  options.pool = pool;
  options.out = test::freshTempDir() / "wild";
  options.labelsDir = fs::path(SAGRID_SOURCE_DIR) / "resources" / "datasets" / "wild";
  const WildCorpusSummary summary = buildWildCorpus(options);
  EXPECT_TRUE(summary.warnings.empty()) << summary.warnings.front();
  EXPECT_EQ(summary.countsByDataset.count("unlabelled") ? summary.countsByDataset.at("unlabelled") : 0, 0);
  EXPECT_EQ(summary.countsByCategory.at("stove"), 12);
  EXPECT_EQ(summary.countsByCategory.at("sink"), 18);
  EXPECT_EQ(summary.countsByCategory.at("none"), 51);
  EXPECT_EQ(readDataset(options.out / "wild-train").size() + readDataset(options.out / "wild-val").size(), 81u);

  // The hand-marked control parts kept with the labels (part_truth.h) name pool objects whose
  // meshes they were marked on, at toggle buttons: every marked part is measured, none skipped.
  std::vector<DatasetEntry> entries = readDataset(options.out / "wild-train");
  for (auto& e : readDataset(options.out / "wild-val")) entries.push_back(e);
  for (const char* file : {"part_truth.json", "part_truth_first_marks.json"}) {
    SCOPED_TRACE(file);
    const PartTruth truth = readPartTruth(options.labelsDir / file);
    std::size_t marked = 0;
    for (const auto& [id, object] : truth.objects) marked += object.controls.size();
    const PartAgreementReport report = measurePartAgreement(entries, &truth);
    EXPECT_TRUE(report.skipped.empty()) << report.skipped.front();
    EXPECT_EQ(report.objects, truth.objects.size());
    EXPECT_EQ(report.points.size(), marked);
    EXPECT_EQ(marked, 39u);  // as the dataset README states
  }
}

}  // namespace
}  // namespace sagrid
