// Training reads each object in the frame its labels were written in: the same stove written as a
// z-up OBJ and as a y-up OBJ (labels object.up "y", as Sweet Home 3D files are) gives the same
// training statistics. Before, features of every OBJ were computed z-up, so a y-up OBJ's targets
// (mapped from y-up) fell beside its voxels.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/dataset/dataset.h"
#include "core/features/feature_pipeline.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

DatasetTrainingResult trainTiny(const fs::path& data, const fs::path& out) {
  DatasetTrainingOptions o;
  o.dataDir = data;
  o.modelName = "stove.heatsource";
  o.architecture = "[3,1,4]";
  o.features.resolution = 16;
  o.features.views = 6;
  o.outDir = out;
  o.training.epochs = 1;
  o.training.batchSize = 1;
  return trainFromDataset(o);
}

TEST(LabelledUpAxis, YUpObjTrainsLikeItsZUpCopy) {
  const fs::path dir = test::freshTempDir("labelled_up_axis");
  gen::generateDataset({{"stove", 1, 31}}, gen::MeshFormat::Obj, dir / "zup");
  const auto entries = readDataset(dir / "zup");
  ASSERT_EQ(entries.size(), 1u);
  // The y-up copy: the same files with vertex positions and normals turned y-up, the labels'
  // points turned with them.
  const fs::path object = dir / "yup" / entries[0].id;
  fs::create_directories(object);
  for (const auto& file : fs::directory_iterator(entries[0].mesh.parent_path()))
    if (file.path().extension() != ".obj" && file.path().filename() != "labels.json")
      fs::copy_file(file.path(), object / file.path().filename());
  std::ifstream in(entries[0].mesh);
  std::ofstream out(object / entries[0].mesh.filename());
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string tag;
    float x, y, z;
    if ((line.rfind("v ", 0) == 0 || line.rfind("vn ", 0) == 0) && (fields >> tag >> x >> y >> z)) {
      const Eigen::Vector3f p = zUpToFile({x, y, z}, UpAxis::PosY);
      std::string rest;  // vertex colours, when the generator wrote them
      std::getline(fields, rest);
      out << tag << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << rest << '\n';
    } else {
      out << line << '\n';
    }
  }
  out.close();
  ObjectLabels labels = readLabels(entries[0].labels);
  for (auto& a : labels.affordances) a.position = zUpToFile(a.position, UpAxis::PosY);
  labels.object.up = "y";
  labels.object.mesh = entries[0].mesh.filename().string();
  labels.object.sha256.clear();
  writeLabels(object / "labels.json", labels);

  const auto z = trainTiny(dir / "zup", dir / "out-z");
  const auto y = trainTiny(dir / "yup", dir / "out-y");
  // The mean feature at the training targets, on the channels that depend on the geometry alone
  // (the rendered ones move with the last digits of the vertex positions on this tiny grid).
  const auto names = featureChannelNames(FeatureOptions{});
  ASSERT_EQ(z.card.affordanceFeatureMean.size(), names.size());
  ASSERT_EQ(y.card.affordanceFeatureMean.size(), names.size());
  int compared = 0;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (names[c] != "height" && names[c] != "radial" && names[c].rfind("occupancy", 0) != 0)
      continue;
    ++compared;
    EXPECT_NEAR(z.card.affordanceFeatureMean[c], y.card.affordanceFeatureMean[c], 0.02)
        << names[c];
  }
  EXPECT_EQ(compared, 4);
}

}  // namespace
}  // namespace sagrid
