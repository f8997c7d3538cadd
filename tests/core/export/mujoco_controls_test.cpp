// Controls that turn, in MuJoCo itself (Debian's libmujoco 2.2.2), and RoboCasa's lookups on our
// MJCF exports. Each RoboCasa rule, restated in our words from robocasa/robocasa
// (robocasa/models/fixtures/stove.py and sink.py, read at commits 0c81ff9c and 8f3c96ec):
//  - stove.py, Stove.burner_sites: the site `burner_on_<loc>` is found at "./body/body/site" from
//    the fixture's worldbody, for <loc> in STOVE_LOCATIONS;
//  - stove.py, Stove.knob_joints: the joint `knob_<loc>_joint` at "./body/body/body/joint";
//  - stove.py, Stove.update_state: burner <loc> is lit while its knob joint's angle, taken modulo
//    2 pi, lies in [0.35, 2 pi - 0.35]; a burner without a knob joint is never lit;
//  - sink.py, Sink.handle_joint: the joint `handle_joint` at "./body/body/body/joint", whose
//    "range" attribute get_handle_state reads (range[1]);
//  - sink.py, Sink.water_site: the site `water` at "./body/body/body/site";
//  - sink.py, Sink.get_handle_state: also reads the joints `spout_joint` and `handle_temp_joint`
//    (its range), and says water runs while the handle's angle modulo 2 pi lies in (0.40, pi).
// Depth below the worldbody stands for those paths (mujoco_model.h). Skipped where libmujoco is
// absent; the real objects where ../shared is.
#include <gtest/gtest.h>

#if SAGRID_HAVE_MUJOCO

#include <mujoco/mujoco.h>

#include <cmath>
#include <iostream>
#include <map>
#include <regex>
#include <set>

#include "core/common/atomic_file.h"
#include "core/corpus/wild_pool_corpus.h"
#include "core/dataset/dataset.h"
#include "core/export/control_geometry.h"
#include "core/export/export_objects.h"
#include "core/export/mjcf_export.h"
#include "core/generate/random.h"
#include "core/generate/sink_generator.h"
#include "core/generate/stove_generator.h"
#include "core/labels/labels.h"
#include "mujoco_model.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using test::bodyDepth;
using test::loadModel;
using test::ModelPtr;

constexpr double kTwoPi = 2.0 * M_PI;

std::string name(const mjModel& m, mjtObj type, int id) {
  const char* text = mj_id2name(&m, type, id);
  return text ? text : "";
}

// RoboCasa's flame rule (Stove.update_state).
bool burnerLit(double angle) {
  double a = std::fmod(angle, kTwoPi);
  if (a < 0) a += kTwoPi;
  return a >= 0.35 && a <= kTwoPi - 0.35;
}

// The world positions of a body's visual mesh vertices.
std::vector<Eigen::Vector3d> visualVertices(const mjModel& m, const mjData& d, int body) {
  std::vector<Eigen::Vector3d> out;
  for (int g = 0; g < m.ngeom; ++g) {
    if (m.geom_bodyid[g] != body || m.geom_type[g] != mjGEOM_MESH) continue;
    const int mesh = m.geom_dataid[g];
    const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> rotation(d.geom_xmat + 9 * g);
    const Eigen::Map<const Eigen::Vector3d> origin(d.geom_xpos + 3 * g);
    for (int v = 0; v < m.mesh_vertnum[mesh]; ++v) {
      const float* p = m.mesh_vert + 3 * (m.mesh_vertadr[mesh] + v);
      out.push_back(origin + rotation * Eigen::Vector3d(p[0], p[1], p[2]));
    }
  }
  return out;
}

Eigen::Vector3d centroidOf(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : points) sum += p;
  return points.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(points.size()));
}

// The diagonal of their box (the part's size).
double sizeOf(const std::vector<Eigen::Vector3d>& points) {
  Eigen::AlignedBox3d box;
  for (const auto& p : points) box.extend(p);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// Turns each hinge by 0.6 rad (slides by 3 mm) on its own and checks that its body's part turns
// in place (its vertex centroid moves less than a third of its size) and no other body moves.
void expectEveryJointTurnsItsOwnPart(const mjModel& m) {
  const test::DataPtr rest = test::makeData(m);
  mj_forward(&m, rest.get());
  for (int j = 0; j < m.njnt; ++j) {
    if (m.jnt_type[j] != mjJNT_HINGE && m.jnt_type[j] != mjJNT_SLIDE) continue;
    const std::string joint = name(m, mjOBJ_JOINT, j);
    if (joint.rfind("spout", 0) == 0) continue;  // locked
    SCOPED_TRACE(joint);
    const int body = m.jnt_bodyid[j];
    const test::DataPtr turned = test::makeData(m);
    turned->qpos[m.jnt_qposadr[j]] = m.jnt_type[j] == mjJNT_HINGE ? 0.6 : 0.003;
    mj_forward(&m, turned.get());
    for (int b = 1; b < m.nbody; ++b) {
      if (b == body) continue;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned->xpos[3 * b + k], rest->xpos[3 * b + k], 1e-9);
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(turned->xquat[4 * b + k], rest->xquat[4 * b + k], 1e-9);
    }
    const auto before = visualVertices(m, *rest, body);
    const double size = sizeOf(before);
    const double moved = (centroidOf(visualVertices(m, *turned, body)) - centroidOf(before)).norm();
    if (size > 0) {
      EXPECT_LT(moved, size / 3.0) << "size " << size;
    }
  }
}

struct Lookups {
  std::map<std::string, int> burners;  // burner_on_<loc> sites at ./body/body/site -> <loc> joint or -1
  std::set<std::string> jointsAtDepth3;
  std::set<std::string> sitesAtDepth3;
};

Lookups robocasaLookups(const mjModel& m) {
  Lookups out;
  for (int j = 0; j < m.njnt; ++j)
    if (bodyDepth(m, m.jnt_bodyid[j]) == 3) out.jointsAtDepth3.insert(name(m, mjOBJ_JOINT, j));
  for (int s = 0; s < m.nsite; ++s) {
    const std::string site = name(m, mjOBJ_SITE, s);
    const int depth = bodyDepth(m, m.site_bodyid[s]);
    if (depth == 3) out.sitesAtDepth3.insert(site);
    if (depth == 2 && site.rfind("burner_on_", 0) == 0) {
      const std::string loc = site.substr(10);
      out.burners[loc] = mj_name2id(&m, mjOBJ_JOINT, ("knob_" + loc + "_joint").c_str());
    }
  }
  return out;
}

struct Exported {
  ObjectLabels labels;
  SimulatorExport result;
  std::string xml;
};

Exported exportObject(const fs::path& labelsPath, const fs::path& mesh, const fs::path& out) {
  ExportOptions options;
  options.collision = CollisionMode::Hull;
  Exported e{readLabels(labelsPath), {}, {}};
  e.result = exportMjcf(e.labels, mesh, out, options, labelsPath);
  e.xml = readFileBytes(e.result.mainFile);
  return e;
}

// Generated stoves with turning knobs, at least one per burner, and `minBurners` burners.
std::vector<gen::GeneratedObject> knobStoves(int count, int minBurners = 1) {
  std::vector<gen::GeneratedObject> stoves;
  for (std::uint64_t seed = 1; static_cast<int>(stoves.size()) < count && seed < 200; ++seed) {
    gen::Rng rng(seed);
    gen::GeneratedObject stove = gen::generateStove(rng);
    const auto& g = stove.generator;
    if (g.value("knobs", 0) >= g.value("burners", 1) && g.value("burners", 1) >= minBurners &&
        g.value("knob_style", "") != "printed" &&
        g.value("controls", "").find("touch") == std::string::npos)
      stoves.push_back(std::move(stove));
  }
  return stoves;
}

TEST(MujocoControls, EveryBurnerOfGeneratedStovesHasItsKnobJoint) {
  for (const auto& stove : knobStoves(3)) {
    const auto dir = test::freshTempDir();
    const fs::path labelsPath = test::writeGeneratedObject(dir / "in", stove, "stove");
    const Exported e = exportObject(labelsPath, dir / "in" / "mesh.obj", dir / "out");
    SCOPED_TRACE(stove.generator.dump());
    const ModelPtr model = loadModel(e.result.mainFile);
    ASSERT_TRUE(model);
    const Lookups lookups = robocasaLookups(*model);
    EXPECT_EQ(lookups.burners.size(), e.labels.ofType("heatsource").size());
    for (const auto& [loc, joint] : lookups.burners) {
      EXPECT_GE(joint, 0) << "burner_on_" << loc << " has no knob_" << loc << "_joint";
      if (joint >= 0) {
        EXPECT_EQ(bodyDepth(*model, model->jnt_bodyid[joint]), 3);
        EXPECT_EQ(model->jnt_type[joint], mjJNT_HINGE);
      }
    }
    // Every knob is a joint: one hinge per toggle point.
    int hinges = 0;
    for (int j = 0; j < model->njnt; ++j) hinges += model->jnt_type[j] == mjJNT_HINGE;
    EXPECT_EQ(hinges, static_cast<int>(e.labels.ofType("togglebutton").size()));
    expectEveryJointTurnsItsOwnPart(*model);
  }
}

// A 1 N m torque on each knob paired with a burner (1 N on a button's press, which drives its
// switch's knob joint, mjcf_controls.h), for 1 s from rest: exactly its burner lights by RoboCasa's
// flame rule; left alone, none lights. Returns {knobs turned, buttons pressed}.
std::pair<int, int> expectEachKnobLightsOnlyItsBurner(const mjModel& model) {
  const Lookups lookups = robocasaLookups(model);
  // Left alone for 1 s, nothing lights: no key sinks in under its weight.
  {
    const test::DataPtr data = test::makeData(model);
    for (int i = 0; i < static_cast<int>(1.0 / model.opt.timestep); ++i) mj_step(&model, data.get());
    for (const auto& [loc, joint] : lookups.burners)
      if (joint >= 0) {
        EXPECT_FALSE(burnerLit(data->qpos[model.jnt_qposadr[joint]])) << loc << " at rest";
      }
  }
  int turned = 0, pressed = 0;
  for (const auto& [loc, joint] : lookups.burners) {
    if (joint < 0) continue;  // a burner without a knob (the export warns): RoboCasa never lights it
    SCOPED_TRACE(loc);
    EXPECT_EQ(model.jnt_type[joint], mjJNT_HINGE);
    const int press = mj_name2id(&model, mjOBJ_JOINT, ("knob_" + loc + "_press_joint").c_str());
    const int pushed = press >= 0 ? press : joint;
    const test::DataPtr data = test::makeData(model);
    const int steps = static_cast<int>(1.0 / model.opt.timestep);
    for (int i = 0; i < steps; ++i) {
      data->qfrc_applied[model.jnt_dofadr[pushed]] = 1.0;
      mj_step(&model, data.get());
    }
    std::set<std::string> lit;
    for (const auto& [other, otherJoint] : lookups.burners)
      if (otherJoint >= 0 && burnerLit(data->qpos[model.jnt_qposadr[otherJoint]])) lit.insert(other);
    EXPECT_EQ(lit, std::set<std::string>{loc})
        << "knob angle " << data->qpos[model.jnt_qposadr[joint]] << ", pushed joint at "
        << data->qpos[model.jnt_qposadr[pushed]];
    ++(press >= 0 ? pressed : turned);
  }
  return {turned, pressed};
}

TEST(MujocoControls, TorqueOnOneKnobLightsExactlyItsBurner) {
  const auto stoves = knobStoves(1, 3);
  ASSERT_EQ(stoves.size(), 1u);
  const auto dir = test::freshTempDir();
  const fs::path labelsPath = test::writeGeneratedObject(dir / "in", stoves[0], "stove");
  const Exported e = exportObject(labelsPath, dir / "in" / "mesh.obj", dir / "out");
  const ModelPtr model = loadModel(e.result.mainFile);
  ASSERT_TRUE(model);
  const Lookups lookups = robocasaLookups(*model);
  ASSERT_GE(lookups.burners.size(), 2u);
  for (const auto& [loc, joint] : lookups.burners) EXPECT_GE(joint, 0) << loc;
  EXPECT_EQ(expectEachKnobLightsOnlyItsBurner(*model),
            std::make_pair(static_cast<int>(lookups.burners.size()), 0));
}

// A stove with touch keys: each key paired with a burner slides on its press joint and drives a
// switch whose knob joint RoboCasa reads; pressing a key lights exactly its burner, and RoboCasa
// setting a knob's angle (Stove.set_knob_state) pulls its key in.
TEST(MujocoControls, APressedKeyLightsExactlyItsBurner) {
  for (std::uint64_t seed = 1; seed < 300; ++seed) {
    gen::Rng rng(seed);
    const gen::GeneratedObject stove = gen::generateStove(rng);
    if (stove.generator.value("controls", "") != "touch") continue;
    const auto dir = test::freshTempDir();
    const fs::path labelsPath = test::writeGeneratedObject(dir / "in", stove, "stove");
    const Exported e = exportObject(labelsPath, dir / "in" / "mesh.obj", dir / "out");
    if (e.xml.find("_press_joint") == std::string::npos) continue;
    SCOPED_TRACE(stove.generator.dump());
    const ModelPtr model = loadModel(e.result.mainFile);
    ASSERT_TRUE(model);
    const auto [turned, pressed] = expectEachKnobLightsOnlyItsBurner(*model);
    EXPECT_GT(pressed, 0);
    // RoboCasa turns a knob on by setting its angle; the key follows into the panel.
    const Lookups lookups = robocasaLookups(*model);
    for (const auto& [loc, joint] : lookups.burners) {
      const int press = mj_name2id(model.get(), mjOBJ_JOINT, ("knob_" + loc + "_press_joint").c_str());
      if (press < 0) continue;
      EXPECT_EQ(bodyDepth(*model, model->jnt_bodyid[joint]), 3);
      const test::DataPtr data = test::makeData(*model);
      data->qpos[model->jnt_qposadr[joint]] = 1.0;
      for (int i = 0; i < static_cast<int>(0.5 / model->opt.timestep); ++i) mj_step(model.get(), data.get());
      EXPECT_GT(data->qpos[model->jnt_qposadr[press]], 0.5 * kButtonTravel) << loc;
      EXPECT_TRUE(burnerLit(data->qpos[model->jnt_qposadr[joint]])) << loc;
    }
    expectEveryJointTurnsItsOwnPart(*model);
    return;
  }
  FAIL() << "no generated touch stove with a key paired with a burner in 300 seeds";
}

TEST(MujocoControls, GeneratedSinksRunWaterFromTheirHandle) {
  int exported = 0;
  for (std::uint64_t seed = 1; exported < 3 && seed < 50; ++seed) {
    gen::Rng rng(seed);
    const gen::GeneratedObject sink = gen::generateSink(rng);
    SCOPED_TRACE(sink.generator.dump());
    const auto dir = test::freshTempDir();
    const fs::path labelsPath = test::writeGeneratedObject(dir / "in", sink, "sink");
    const Exported e = exportObject(labelsPath, dir / "in" / "mesh.obj", dir / "out");
    if (e.labels.ofType("togglebutton").empty() || e.labels.ofType("fluidsource").empty()) continue;
    ++exported;
    const ModelPtr model = loadModel(e.result.mainFile);
    ASSERT_TRUE(model);
    const Lookups lookups = robocasaLookups(*model);
    EXPECT_TRUE(lookups.sitesAtDepth3.count("water"));
    for (const char* joint : {"handle_joint", "handle_temp_joint", "spout_joint"})
      EXPECT_TRUE(lookups.jointsAtDepth3.count(joint)) << joint << "\n" << e.xml.substr(e.xml.find("<worldbody>"));
    EXPECT_TRUE(std::regex_search(e.xml, std::regex("<joint name=\"handle_joint\"[^>]* range=\"")));
    expectEveryJointTurnsItsOwnPart(*model);
    // A torque on the handle opens it past 0.40 rad: water runs.
    const int handle = mj_name2id(model.get(), mjOBJ_JOINT, "handle_joint");
    const test::DataPtr data = test::makeData(*model);
    for (int i = 0; i < static_cast<int>(1.0 / model->opt.timestep); ++i) {
      data->qfrc_applied[model->jnt_dofadr[handle]] = 1.0;
      mj_step(model.get(), data.get());
    }
    const double angle = data->qpos[model->jnt_qposadr[handle]];
    EXPECT_GT(angle, 0.40);
    EXPECT_LT(angle, M_PI);
  }
  EXPECT_EQ(exported, 3);
}

// Every curated real stove and sink with its true labels: the wild pool (its curated labels in
// resources/datasets/wild) and real-dev. Each exports, loads, has a joint for every toggle
// button point and turns each in place; on stoves, a torque on each knob paired with a burner
// lights exactly that burner.
TEST(MujocoControls, SlowEveryCuratedRealControlIsAJointThatTurnsInPlace) {
  const fs::path pool = test::sharedDir() / "data" / "wild-pool";
  if (!fs::is_directory(pool) || !fs::is_directory(test::realDevDir()))
    GTEST_SKIP() << "no ../shared/data beside the repository";
  WildCorpusOptions corpus;
  corpus.pool = pool;
  const fs::path dir = test::freshTempDir();
  corpus.out = dir / "wild";
  corpus.labelsDir = fs::path(SAGRID_SOURCE_DIR) / "resources" / "datasets" / "wild";
  buildWildCorpus(corpus);
  std::vector<fs::path> objects;
  for (const char* set : {"wild-train", "wild-val"})
    for (const auto& entry : readDataset(corpus.out / set)) objects.push_back(entry.labels);
  for (const auto& entry : fs::directory_iterator(test::realDevDir()))
    if (fs::exists(entry.path() / "labels.json")) objects.push_back(entry.path() / "labels.json");
  int toggles = 0, joints = 0, tested = 0, burners = 0, turned = 0, pressed = 0;
  for (const auto& labelsPath : objects) {
    const ObjectLabels labels = readLabels(labelsPath);
    if (labels.object.category != "stove" && labels.object.category != "sink") continue;
    SCOPED_TRACE(labelsPath);
    const fs::path out = dir / "export" / std::to_string(tested);
    ExportOptions options;
    options.collision = CollisionMode::Hull;
    const auto results = exportObjects(labelsPath, "mjcf", out, options);
    ASSERT_EQ(results.size(), 1u);
    const ModelPtr model = loadModel(results[0].mainFile);
    ASSERT_TRUE(model);
    ++tested;
    const int points = static_cast<int>(labels.ofType("togglebutton").size());
    // Bodies on joints with geoms (not the spouts, not a button's switch): one per control.
    int moving = 0;
    for (int b = 1; b < model->nbody; ++b)
      if (model->body_jntnum[b] > 0 && model->body_geomnum[b] > 0) ++moving;
    std::cout << labelsPath.parent_path().filename().string() << ": " << points
              << " toggle points, " << moving << " joints\n";
    toggles += points, joints += moving;
    EXPECT_EQ(moving, points);
    expectEveryJointTurnsItsOwnPart(*model);
    if (labels.object.category == "stove") {
      const Lookups lookups = robocasaLookups(*model);
      burners += static_cast<int>(lookups.burners.size());
      const auto [byKnob, byButton] = expectEachKnobLightsOnlyItsBurner(*model);
      turned += byKnob, pressed += byButton;
    }
  }
  std::cout << tested << " curated real stoves and sinks: " << joints << " joints for " << toggles
            << " toggle button points; of " << burners << " stove burners " << turned
            << " light from their turned knob alone, " << pressed
            << " from their pressed button alone\n";
  EXPECT_GE(tested, 30);
}

}  // namespace
}  // namespace sagrid

#endif
