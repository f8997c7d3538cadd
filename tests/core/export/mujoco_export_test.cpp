// The MJCF export in MuJoCo itself (Debian's libmujoco 2.2.2): the export loads, MuJoCo's visual
// face count equals ours for the real objects (MuJoCo reads only the first o/g group of an OBJ,
// which lost 1,026 of the LIBERO stove's 1,038 triangles), a small box dropped on each heat
// source comes to rest on the surface after 1.5 s, and a small sphere dropped into a sink basin
// stays in it (the decomposition keeps the basin open). Skipped only where libmujoco is absent.
#include <gtest/gtest.h>

#include "core/export/mjcf_export.h"
#include "core/labels/labels.h"

#if SAGRID_HAVE_MUJOCO

#include <mujoco/mujoco.h>

#include "mujoco_model.h"

#include <cstring>
#include <iostream>
#include <memory>

#include "core/common/atomic_file.h"
#include "core/export/export_objects.h"
#include "core/generate/random.h"
#include "core/generate/sink_generator.h"
#include "core/generate/stove_generator.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh_import.h"
#include "support/analytic_meshes.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

using test::loadModel;
using test::ModelPtr;

int visualFaces(const mjModel& m) {
  int faces = 0;
  for (int i = 0; i < m.nmesh; ++i) {
    if (std::strncmp(mj_id2name(&m, mjOBJ_MESH, i), "visual_", 7) == 0) faces += m.mesh_facenum[i];
  }
  return faces;
}

// The exported model plus one free body, written beside the export so its mesh paths resolve.
fs::path sceneWithProbe(const SimulatorExport& exported, const std::string& probeGeom,
                        const Eigen::Vector3f& start) {
  std::string xml = readFileBytes(exported.mainFile);
  const std::string probe = "    <body name=\"probe\" pos=\"" + std::to_string(start.x()) + " " +
                            std::to_string(start.y()) + " " + std::to_string(start.z()) +
                            "\"><freejoint/>" + probeGeom + "</body>\n";
  xml.insert(xml.rfind("  </worldbody>"), probe);
  const fs::path scene = exported.root / "probe_scene.xml";
  writeFileAtomic(scene, xml);
  return scene;
}

struct Rest {
  Eigen::Vector3f position;
  float speed;
};

Rest simulate(const mjModel& model, double seconds) {
  const test::DataPtr data = test::makeData(model);
  const int steps = static_cast<int>(seconds / model.opt.timestep);
  for (int i = 0; i < steps; ++i) mj_step(&model, data.get());
  const int body = mj_name2id(&model, mjOBJ_BODY, "probe");
  const mjtNum* p = data->xpos + 3 * body;
  // The probe's free joint (the object's controls have joints of their own).
  const mjtNum* v = data->qvel + model.jnt_dofadr[model.body_jntadr[body]];
  return {Eigen::Vector3f(p[0], p[1], p[2]),
          static_cast<float>(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]))};
}

// Drops a 4 cm box 5 cm above each heat source and expects it resting on the surface there.
void expectBoxesRestOnHeatSources(const ObjectLabels& labels, const fs::path& mesh,
                                  const fs::path& out, const ExportOptions& options = {}) {
  const SimulatorExport exported = exportMjcf(labels, mesh, out, options);
  constexpr float kHalf = 0.02f;
  for (const auto* heat : labels.ofType("heatsource")) {
    const Eigen::Vector3f target = heat->position;  // these test objects are z-up metres
    SCOPED_TRACE(testing::Message() << "heat source at " << target.transpose());
    const fs::path scene =
        sceneWithProbe(exported, "<geom type=\"box\" size=\"0.02 0.02 0.02\" mass=\"0.2\"/>",
                       target + Eigen::Vector3f(0, 0, 0.05f + kHalf));
    const ModelPtr model = loadModel(scene);
    ASSERT_TRUE(model);
    const Rest rest = simulate(*model, 1.5);
    std::cout << "box on heat source " << target.transpose() << ": rests " << std::showpos
              << (rest.position.z() - target.z() - kHalf) * 1000 << std::noshowpos
              << " mm from the surface, "
              << (rest.position.head<2>() - target.head<2>()).norm() * 1000 << " mm aside, speed "
              << rest.speed << " m/s (" << exported.collisionParts << " collision parts)\n";
    EXPECT_NEAR(rest.position.z(), target.z() + kHalf, 0.012f);
    // On this burner: not fallen through, off the stove or slid away (measured: <= 2 mm aside).
    EXPECT_LT((rest.position.head<2>() - target.head<2>()).norm(), 0.03f);
    EXPECT_LT(rest.speed, 0.05f);
  }
}

TEST(MujocoExport, RealObjectsLoadWithEveryTriangle) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP() << "no ../shared/data/real-dev beside the repository";
  for (const char* name : {"libero__flat_stove", "libero__basin_faucet", "libero__faucet_knob"}) {
    SCOPED_TRACE(name);
    const fs::path labelsPath = test::realDevDir() / name / "labels.json";
    const auto dir = test::freshTempDir();
    ExportOptions options;  // the face count does not depend on the collision parts
    options.collision = CollisionMode::Hull;
    const auto results = exportObjects(labelsPath, "mjcf", dir, options);
    ASSERT_EQ(results.size(), 1u);
    const ModelPtr model = loadModel(results[0].mainFile);
    ASSERT_TRUE(model);
    const Mesh mesh = importMesh(test::realDevDir() / name / "mesh.obj");
    EXPECT_EQ(visualFaces(*model), static_cast<int>(mesh.triangleCount()));
    const int object = mj_name2id(model.get(), mjOBJ_BODY, "object");
    ASSERT_GE(object, 0);
    std::cout << name << ": MuJoCo visual faces " << visualFaces(*model) << ", imported triangles "
              << mesh.triangleCount() << ", collision parts " << results[0].collisionParts
              << ", mass " << model->body_mass[object] << " kg\n";
    EXPECT_EQ(results[0].visualTriangles, static_cast<int>(mesh.triangleCount()));
    EXPECT_GT(results[0].collisionParts, 0);
    EXPECT_NEAR(model->body_mass[object], results[0].massKg, 1e-5 * results[0].massKg);
    // The figure of issue 12: the LIBERO stove has 1,038 triangles in many o/g groups.
    if (std::string(name) == "libero__flat_stove") EXPECT_EQ(visualFaces(*model), 1038);
  }
}

TEST(MujocoExport, BoxRestsOnTheLiberoStoveBurner) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP() << "no ../shared/data/real-dev beside the repository";
  const fs::path labelsPath = test::realDevDir() / "libero__flat_stove" / "labels.json";
  expectBoxesRestOnHeatSources(readLabels(labelsPath), labelsPath.parent_path() / "mesh.obj",
                               test::freshTempDir());
}

// The body's collision with its knobs in place (--no-controls). Cut away, seed 3's knob strip
// (8 mm below its grate) and grate fall into one convex part at 64 voxels, sloped 4.6 degrees,
// and its boxes come to rest 7 and 9 cm aside (a limitation of the decomposition's resolution,
// measured here with the default export).
TEST(MujocoExport, BoxRestsOnEveryBurnerOfGeneratedStoves) {
  ExportOptions options;
  options.articulatedControls = false;
  for (std::uint64_t seed : {3u, 11u}) {
    SCOPED_TRACE(seed);
    gen::Rng rng(seed);
    const gen::GeneratedObject stove = gen::generateStove(rng);
    const auto dir = test::freshTempDir();
    const fs::path labelsPath = test::writeGeneratedObject(dir / "in", stove, "stove");
    expectBoxesRestOnHeatSources(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out",
                                 options);
  }
}

TEST(MujocoExport, SphereStaysInSinkBasin) {
  gen::Rng rng(5);
  gen::GeneratedObject sink = gen::generateSink(rng);
  for (int i = 0; sink.generator.value("basins", 0) < 1 && i < 20; ++i)
    sink = gen::generateSink(rng);
  ASSERT_GE(sink.generator.value("basins", 0), 1);
  const auto dir = test::freshTempDir();
  const fs::path labelsPath = test::writeGeneratedObject(dir / "in", sink, "sink");
  const ObjectLabels labels = readLabels(labelsPath);
  const auto sources = labels.ofType("fluidsource");
  ASSERT_FALSE(sources.empty());
  const Eigen::Vector3f outlet = sources.front()->position;
  // The basin floor below the outlet, where the water lands.
  const SurfaceScene scene(sink.mesh);
  const auto floor =
      scene.intersect(outlet - Eigen::Vector3f(0, 0, 0.005f), -Eigen::Vector3f::UnitZ());
  ASSERT_TRUE(floor);
  const SimulatorExport exported = exportMjcf(labels, dir / "in" / "mesh.obj", dir / "out");
  constexpr float kRadius = 0.015f;
  const fs::path probe =
      sceneWithProbe(exported, "<geom type=\"sphere\" size=\"0.015\" mass=\"0.05\"/>",
                     outlet - Eigen::Vector3f(0, 0, 0.03f));
  const ModelPtr model = loadModel(probe);
  ASSERT_TRUE(model);
  const Rest rest = simulate(*model, 1.5);
  std::cout << "sphere in the sink: rests " << (rest.position.z() - floor->position.z()) * 1000
            << " mm above the basin floor below the outlet (centre; radius 15 mm), "
            << exported.collisionParts << " collision parts\n";
  // In the basin: near its floor, far below the rim a hull over the basin would hold it at.
  EXPECT_GT(rest.position.z(), floor->position.z() - 0.01f);
  EXPECT_LT(rest.position.z(), floor->position.z() + kRadius + 0.03f);
  EXPECT_TRUE(sink.mesh.bounds().contains(rest.position));
}

// An id holding markup characters still gives well-formed MJCF (issue 14): MuJoCo parses it and
// the model keeps the name.
TEST(MujocoExport, MarkupInTheIdStaysWellFormed) {
  const auto dir = test::freshTempDir();
  const fs::path labelsPath = test::writeAnalyticStove(dir / "in", "<x a=\"1\">&'y");
  ExportOptions options;
  options.collision = CollisionMode::None;
  const auto exported =
      exportMjcf(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out", options);
  const ModelPtr model = loadModel(exported.mainFile);
  ASSERT_TRUE(model);
  EXPECT_STREQ(model->names, "<x a=\"1\">&'y");  // MuJoCo keeps the model name first
}

TEST(MujocoExport, FlatMeshLoadsAsVisualOnly) {
  const auto dir = test::freshTempDir();
  const fs::path labelsPath = test::writeLabelledObject(
      dir / "in", test::quadZ({0, 0}, {0.4f, 0.3f}, 0.0f),
      {test::affordance("heatsource", {0.2f, 0.15f, 0.0f})}, "plate", "stove");
  const auto exported = exportMjcf(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out");
  const ModelPtr model = loadModel(exported.mainFile);
  ASSERT_TRUE(model);
  EXPECT_EQ(visualFaces(*model), 2);
  EXPECT_FALSE(exported.warnings.empty());
}

}  // namespace
}  // namespace sagrid

#else

TEST(MujocoExport, SkippedWithoutLibmujoco) {
  GTEST_SKIP() << "libmujoco-dev is not installed (packaging/install_deps.sh installs it)";
}

#endif
