#include "core/corpus/sweethome3d_corpus.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/io/zip_archive.h"
#include "core/labels/labels.h"
#include "support/sweethome3d_fixture.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;
using ::testing::Contains;
using ::testing::HasSubstr;

SweetHome3dPackageOptions archives(const fs::path& sh3f) {
  SweetHome3dPackageOptions o;
  o.sh3f = {sh3f};
  return o;
}

SweetHome3dCorpusOptions optionsFor(const test::SweetHome3dFixture& f, const fs::path& out,
                                    const fs::path& labels) {
  SweetHome3dCorpusOptions o;
  o.out = out;
  o.sources = locateSweetHome3dSources(archives(f.sh3f));
  o.labelsDir = labels;
  return o;
}

// Shipped labels for the cooker (real-train); the sink stays unlabelled.
fs::path writeShippedLabels(const fs::path& dir, const std::string& cookerSha) {
  fs::create_directories(dir / "test_lib_cooker");
  writeFileAtomic(dir / "split.json", R"({"real-train":["test_lib_cooker"],"real-val":[]})");
  writeFileAtomic(dir / "test_lib_cooker" / "labels.json",
                  test::fixtureLabelsJson("test_lib_cooker", "cooker.obj", cookerSha, "stove"));
  return dir;
}

bool siblingsLeft(const fs::path& out) {
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    const std::string name = e.path().filename().string();
    if (name.rfind("." + out.filename().string() + ".", 0) == 0) return true;
  }
  return false;
}

TEST(SweetHome3dCorpus, ExtractsSelectedObjectsIntoDatasets) {
  const fs::path dir = test::freshTempDir();
  const auto f = test::writeSweetHome3dFixture(dir / "in");
  const fs::path labels = writeShippedLabels(dir / "labels", sha256Hex(f.cookerObj));
  const fs::path out = dir / "corpus";
  const CorpusSummary s = buildSweetHome3dCorpus(optionsFor(f, out, labels));

  ASSERT_EQ(s.objects.size(), 4u);  // the chair is not selected
  EXPECT_EQ(s.objects[0].id, "test_lib_cooker");
  EXPECT_EQ(s.objects[1].id, "test_lib_sink");
  EXPECT_EQ(s.objects[2].id, "test_lib_oven");
  EXPECT_EQ(s.objects[3].id, "test_lib_cooker_2");  // "Test-Lib#Cooker" collides
  EXPECT_EQ(s.objects[0].role, CorpusRole::Stove);
  EXPECT_EQ(s.objects[1].role, CorpusRole::Sink);
  EXPECT_EQ(s.objects[2].role, CorpusRole::None);
  EXPECT_EQ(s.countsByRole.at("stove"), 2);
  EXPECT_EQ(s.countsByDataset.at("real-train"), 1);
  EXPECT_EQ(s.countsByDataset.at("unlabelled"), 2);
  EXPECT_EQ(s.countsByDataset.at("distractors"), 1);
  EXPECT_EQ(s.countsByDataset.count("real-val"), 0u);

  // Bytes exactly as shipped, archive-relative names kept inside the object folder.
  const fs::path cooker = out / "real-train" / "test_lib_cooker";
  EXPECT_EQ(readFileBytes(cooker / "cooker.obj"), f.cookerObj);
  EXPECT_EQ(readFileBytes(cooker / "cooker.mtl"), f.cookerMtl);
  EXPECT_EQ(readFileBytes(cooker / "textures" / "cooker.png"), f.cookerTexture);
  EXPECT_EQ(readLabels(cooker / "labels.json").affordances.size(), 1u);
  const fs::path sink = out / "unlabelled" / "test_lib_sink";
  EXPECT_EQ(readFileBytes(sink / "sink.obj"), f.sinkObj);
  EXPECT_EQ(readFileBytes(sink / "sink.mtl"), f.sinkMtl);
  EXPECT_EQ(readFileBytes(sink / "sink.jpg"), f.sinkTexture);
  EXPECT_FALSE(fs::exists(sink / "labels.json"));
  // The "../shared.mtl" and absolute references are refused, not followed.
  EXPECT_FALSE(fs::exists(sink / ".." / "shared.mtl"));
  EXPECT_FALSE(fs::exists(out / "unlabelled" / "shared.mtl"));
  EXPECT_THAT(s.warnings, Contains(HasSubstr("test_lib_sink: refused reference '../shared.mtl'")));
  EXPECT_THAT(s.warnings, Contains(HasSubstr("refused reference '/home/someone/steel.png'")));

  const json p = json::parse(readFileBytes(cooker / "provenance.json"));
  EXPECT_EQ(p["package"], "sweethome3d-furniture");
  EXPECT_TRUE(p["package_version"].is_null());  // an explicit archive outside /usr/share
  EXPECT_EQ(p["library"], "TestLib");
  EXPECT_EQ(p["library_name"], "Test biblioth\xc3\xa8que \xc3\xa9");
  EXPECT_EQ(p["catalog_id"], "Test Lib#cooker");
  EXPECT_EQ(p["name"], "Cooker");
  EXPECT_EQ(p["category"], "Kitchen");
  EXPECT_EQ(p["creator"], "Alice");
  EXPECT_EQ(p["license"], "Public domain");
  EXPECT_EQ(p["path_in_archive"], "testlib/cooker/cooker.obj");
  EXPECT_EQ(p["catalog_size_cm"]["depth"], 50.0);
  EXPECT_EQ(p["mesh_sha256"], sha256Hex(f.cookerObj));
  EXPECT_EQ(p["role"], "stove");
  EXPECT_EQ(p["up"], "y");
  EXPECT_NEAR(p["meters_per_unit"].get<double>(), 0.01, 1e-9);
  EXPECT_FALSE(p.contains("model_rotation"));
  const json sp = json::parse(readFileBytes(sink / "provenance.json"));
  EXPECT_EQ(sp["name"], "Kitchen sink");  // continuation line joined
  EXPECT_NEAR(sp["meters_per_unit"].get<double>(), 1.0, 1e-9);

  const fs::path oven = out / "distractors" / "test_lib_oven";
  const json op = json::parse(readFileBytes(oven / "provenance.json"));
  EXPECT_EQ(op["model_rotation"], json({1, 0, 0, 0, 0, 1, 0, -1, 0}));
  EXPECT_NEAR(op["meters_per_unit"].get<double>(), 0.1, 1e-9);
  const ObjectLabels ol = readLabels(oven / "labels.json");
  EXPECT_EQ(ol.object.category, "none");
  EXPECT_EQ(ol.object.up, "y");
  EXPECT_EQ(ol.object.mesh, "oven.obj");
  EXPECT_EQ(ol.object.sha256, sha256Hex(f.ovenObj));
  EXPECT_TRUE(ol.affordances.empty());
  EXPECT_EQ(ol.reviewState, ReviewState::Done);
  EXPECT_NEAR(metersPerUnit(ol), 0.1, 1e-9);

  // Every dataset reads back through readDataset with existing meshes.
  const auto train = readDataset(out / "real-train");
  ASSERT_EQ(train.size(), 1u);
  EXPECT_EQ(train[0].id, "test_lib_cooker");
  EXPECT_EQ(train[0].category, "stove");
  EXPECT_EQ(train[0].mesh, out / "real-train" / "test_lib_cooker" / "cooker.obj");
  EXPECT_TRUE(fs::exists(train[0].labels));
  const auto distractors = readDataset(out / "distractors");
  ASSERT_EQ(distractors.size(), 1u);
  EXPECT_EQ(distractors[0].category, "none");
  EXPECT_TRUE(fs::exists(distractors[0].mesh));
  EXPECT_EQ(readDataset(out / "unlabelled").size(), 2u);
  EXPECT_TRUE(readDataset(out / "real-val").empty());

  const json corpus = json::parse(readFileBytes(out / "corpus.json"));
  EXPECT_EQ(corpus["counts_by_role"]["sink"], 1);
  EXPECT_EQ(corpus["counts_by_library"]["TestLib"]["stove"], 2);
  EXPECT_EQ(corpus["objects"].size(), 4u);
  EXPECT_FALSE(siblingsLeft(out));
}

TEST(SweetHome3dCorpus, ShippedLabelShaMismatchNamesObjectAndWritesNothing) {
  const fs::path dir = test::freshTempDir();
  const auto f = test::writeSweetHome3dFixture(dir / "in");
  const fs::path labels = writeShippedLabels(dir / "labels", std::string(64, '0'));
  const fs::path out = dir / "corpus";
  try {
    buildSweetHome3dCorpus(optionsFor(f, out, labels));
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("test_lib_cooker"));
    EXPECT_THAT(e.what(), HasSubstr("does not match"));
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(siblingsLeft(out));

  // An earlier corpus survives a failed rebuild untouched, and a good rebuild replaces it.
  buildSweetHome3dCorpus(optionsFor(f, out, dir / "no-labels"));
  EXPECT_EQ(readDataset(out / "unlabelled").size(), 3u);
  EXPECT_THROW(buildSweetHome3dCorpus(optionsFor(f, out, labels)), FileError);
  EXPECT_EQ(readDataset(out / "unlabelled").size(), 3u);
  EXPECT_FALSE(siblingsLeft(out));
  writeShippedLabels(dir / "labels", sha256Hex(f.cookerObj));
  buildSweetHome3dCorpus(optionsFor(f, out, labels));
  EXPECT_EQ(readDataset(out / "unlabelled").size(), 2u);
}

TEST(SweetHome3dCorpus, RefusesToReplaceAFolderThatIsNotACorpus) {
  const fs::path dir = test::freshTempDir();
  const auto f = test::writeSweetHome3dFixture(dir / "in");
  fs::create_directories(dir / "mine");
  writeFileAtomic(dir / "mine" / "notes.txt", "keep");
  EXPECT_THROW(buildSweetHome3dCorpus(optionsFor(f, dir / "mine", {})), FileError);
  EXPECT_EQ(readFileBytes(dir / "mine" / "notes.txt"), "keep");
}

TEST(SweetHome3dCorpus, PackageLookupErrorsAreClear) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THROW(locateSweetHome3dSources(archives(dir / "missing.sh3f")), FileError);
  // Not installed and a broken cached .deb: one error naming it, before any download.
  fs::create_directories(dir / "debs");
  writeFileAtomic(dir / "debs" / "sweethome3d-furniture_1.0_all.deb", "not a deb");
  SweetHome3dPackageOptions options;
  options.debCache = dir / "debs";
  options.installedRoot = dir / "root";
  try {
    locateSweetHome3dSources(options);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("sweethome3d-furniture_1.0_all.deb"));
  }
  // An archive that is not a furniture library.
  writeStoredZip(dir / "other.sh3f", {{"readme.txt", "hi"}});
  SweetHome3dCorpusOptions o;
  o.out = dir / "out";
  o.sources = locateSweetHome3dSources(archives(dir / "other.sh3f"));
  try {
    buildSweetHome3dCorpus(o);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("PluginFurnitureCatalog.properties"));
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(SweetHome3dCorpus, MetersPerUnitMatchesSortedDimensions) {
  EXPECT_NEAR(estimateMetersPerUnit({60, 50, 90}, {0.9, 0.6, 0.5}), 1.0, 1e-12);
  // One dimension off (a protruding handle) does not move the median.
  EXPECT_NEAR(estimateMetersPerUnit({60, 50, 90}, {60, 50, 120}), 0.01, 1e-12);
  // A flat mesh side carries no scale.
  EXPECT_NEAR(estimateMetersPerUnit({60, 1, 60}, {0.6, 0, 0.6}), 1.0, 1e-12);
  EXPECT_EQ(estimateMetersPerUnit({}, {1, 1, 1}), 0.0);
  const auto extent = objVertexExtent("# c\nv 1 2 3\nvn 0 0 1\nvt 5 5\nv -1 4 3.5\nf 1 2 1\n");
  EXPECT_EQ(extent, (std::vector<double>{2, 2, 0.5}));
}

}  // namespace
}  // namespace sagrid
