// Control parts on synthetic panels with known parts: which triangles move, how (knob, lever,
// button), about which axis and pivot; each way a part is found (its material's component, the
// connected component, the surface grown around the point, a disc) and the refusals.
#include "core/controls/control_part.h"
#include "core/controls/control_part_edit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A 60 x 40 cm panel facing +z at z = 0 (a box 2 cm thick), in material 0.
Mesh panel() {
  Mesh m = test::box({-0.3f, -0.2f, -0.02f}, {0.3f, 0.2f, 0.0f});
  m.materials.resize(2);
  m.triangleMaterials.assign(m.triangles.size(), 0);
  return m;
}

// Appends `part` in `material`; returns its triangles' indices.
std::vector<int> addPart(Mesh& mesh, const Mesh& part, int material) {
  const int first = static_cast<int>(mesh.triangles.size());
  test::append(mesh, part);
  mesh.triangleMaterials.resize(mesh.triangles.size(), material);
  std::vector<int> triangles(part.triangles.size());
  std::iota(triangles.begin(), triangles.end(), first);
  return triangles;
}

TEST(ControlParts, KnobsOnAPanelTurnAboutTheirAxisOutOfThePanel) {
  Mesh mesh = panel();
  const auto left = addPart(mesh, test::box({-0.12f, -0.02f, 0.0f}, {-0.08f, 0.02f, 0.025f}), 1);
  const auto right = addPart(mesh, test::box({0.08f, -0.02f, 0.0f}, {0.12f, 0.02f, 0.025f}), 1);
  const ControlParts found =
      findControlParts(mesh, {{-0.1f, 0.0f, 0.025f}, {0.1f, 0.0f, 0.025f}});
  ASSERT_EQ(found.parts.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(found.parts[i]);
    const ControlPart& part = *found.parts[i];
    EXPECT_EQ(part.triangles, i == 0 ? left : right);
    EXPECT_EQ(part.motion, ControlMotion::Knob);
    EXPECT_EQ(part.origin, PartOrigin::Material);
    EXPECT_GT(part.axis.dot(Eigen::Vector3f::UnitZ()), 0.99f);  // out of the panel
    EXPECT_NEAR(part.pivot.x(), i == 0 ? -0.1f : 0.1f, 1e-4f);
    EXPECT_NEAR(part.pivot.y(), 0.0f, 1e-4f);
    EXPECT_TRUE(found.warnings[i].empty());
  }
}

// A tall knob near a wall: the wall is nearer its middle than the panel under it, but the knob
// stands on the panel and turns about the panel's normal.
TEST(ControlParts, AKnobTurnsAboutTheNormalOfThePanelItStandsOnNotTheNearestWall) {
  Mesh mesh = panel();
  const auto knob = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.06f}), 1);
  addPart(mesh, test::box({0.029f, -0.1f, 0.0f}, {0.04f, 0.1f, 0.15f}), 0);
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.06f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, knob);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(found.parts[0]->axis.dot(Eigen::Vector3f::UnitZ()), 0.99f);
}

TEST(ControlParts, WithoutMaterialsTheConnectedComponentIsThePart) {
  Mesh mesh = panel();
  const auto knob = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.03f}), 0);
  mesh.triangleMaterials.clear();
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.03f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, knob);
  EXPECT_EQ(found.parts[0]->origin, PartOrigin::Connected);
}

TEST(ControlParts, AKnobFusedIntoTheBodyIsFoundByItsMaterial) {
  Mesh mesh = panel();
  const auto knob = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.03f}), 1);
  // A bridge of the panel's material joins the knob's corner to the panel's: one connected body.
  const int a = mesh.triangles[static_cast<std::size_t>(knob.front())][0];
  mesh.positions.push_back({0.3f, 0.2f, 0.0f});
  mesh.positions.push_back({0.3f, -0.2f, 0.0f});
  mesh.normals.resize(mesh.positions.size(), Eigen::Vector3f::UnitZ());
  const int n = static_cast<int>(mesh.positions.size());
  mesh.triangles.emplace_back(a, n - 2, n - 1);
  mesh.triangleMaterials.push_back(0);
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.03f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, knob);
  EXPECT_EQ(found.parts[0]->origin, PartOrigin::Material);
}

TEST(ControlParts, ALeverTurnsAboutItsHeldEnd) {
  Mesh mesh = panel();
  // A tap body (a post) and a lever from its top reaching 10 cm towards -y.
  addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.1f}), 0);
  const auto lever = addPart(mesh, test::box({-0.008f, -0.12f, 0.1f}, {0.008f, 0.0f, 0.115f}), 1);
  const ControlParts found = findControlParts(mesh, {{0.0f, -0.06f, 0.115f}});
  ASSERT_TRUE(found.parts[0]);
  const ControlPart& part = *found.parts[0];
  EXPECT_EQ(part.triangles, lever);
  EXPECT_EQ(part.motion, ControlMotion::Lever);
  EXPECT_NEAR(part.pivot.y(), 0.0f, 1e-3f);  // the end over the post
  EXPECT_GT(std::abs(part.axis.x()), 0.99f);  // across the lever, level
  // A positive turn lifts the free end.
  const Eigen::Vector3f tip(0.0f, -0.12f, 0.1075f);
  const Eigen::Vector3f lift = part.axis.cross(tip - part.pivot);
  EXPECT_GT(lift.z(), 0.0f);
}

TEST(ControlParts, AFlatPadIsAButtonPressedIntoThePanel) {
  Mesh mesh = panel();
  const auto pad = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.003f}), 1);
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.003f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, pad);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Button);
  EXPECT_LT(found.parts[0]->axis.z(), -0.99f);
}

// A key drawn as a flat quad level with the panel's top, as some in-the-wild stoves have it: what
// holds it is beside it, not under it, so "out of the panel" says nothing; the key is pressed
// into the panel along its thin direction whether its quad is one-sided (facing up, or wound
// facing down) or two-sided.
TEST(ControlParts, AFlatKeyLevelWithThePanelIsPressedIntoIt) {
  const auto quad = [](bool up) {
    Mesh q;
    q.positions = {{-0.02f, -0.02f, 0.0f}, {0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.0f}, {-0.02f, 0.02f, 0.0f}};
    if (up) q.triangles = {{0, 1, 2}, {0, 2, 3}};
    else q.triangles = {{0, 2, 1}, {0, 3, 2}};
    return q;
  };
  for (int sides : {1, 2}) {
    SCOPED_TRACE(sides);
    Mesh mesh = panel();
    std::vector<int> key = addPart(mesh, quad(true), 1);
    if (sides == 2) {
      const auto back = addPart(mesh, quad(false), 1);
      key.insert(key.end(), back.begin(), back.end());
    }
    EXPECT_LT(pressDirection(mesh, key).z(), -0.99f);
  }
}

// A panel of 2 cm cells whose vertex at the point is raised: a bump of the panel's own surface.
Mesh bumpyPanel(float bump) {
  Mesh m;
  const int n = 21;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float x = -0.2f + 0.02f * i, y = -0.2f + 0.02f * j;
      const bool centre = i == n / 2 && j == n / 2;
      m.positions.push_back({x, y, centre ? bump : 0.0f});
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      m.triangles.emplace_back(a, a + 1, a + n + 1);
      m.triangles.emplace_back(a, a + n + 1, a + n);
    }
  m.computeVertexNormals();
  return m;
}

TEST(ControlParts, AFusedBumpIsGrownAndAPrintedKeyGetsADisc) {
  // A second control 12 cm away sets the grow radius (0.45 x 12 = 5.4 cm).
  const std::vector<Eigen::Vector3f> points{{0.0f, 0.0f, 0.02f}, {0.12f, 0.0f, 0.0f}};
  const ControlParts bumped = findControlParts(bumpyPanel(0.02f), points);
  ASSERT_TRUE(bumped.parts[0]);
  EXPECT_EQ(bumped.parts[0]->origin, PartOrigin::Grown);
  EXPECT_EQ(bumped.parts[0]->triangles.size(), 6u);  // the fan around the raised vertex
  const ControlParts flat = findControlParts(bumpyPanel(0.0f), points);
  ASSERT_TRUE(flat.parts[0]);
  EXPECT_EQ(flat.parts[0]->origin, PartOrigin::Disc);
  EXPECT_TRUE(flat.parts[0]->triangles.empty());
  EXPECT_GT(flat.parts[0]->radius, 0.0f);
  EXPECT_NE(flat.warnings[0].find("printed"), std::string::npos);
}

TEST(ControlParts, APointInsideALargeKnobOpenAtItsBaseNamesIt) {
  // A knob 12 x 12 x 10 cm (larger than a small part of this panel may be), open at its base; its
  // point labelled at its centre, inside it. A point on the panel beside it gets no such part.
  Mesh mesh = panel();
  Mesh knob = test::box({-0.06f, -0.06f, 0.0f}, {0.06f, 0.06f, 0.1f});
  knob.triangles.erase(std::remove_if(knob.triangles.begin(), knob.triangles.end(),
                                      [&](const Eigen::Vector3i& t) {
                                        for (int c = 0; c < 3; ++c)
                                          if (knob.positions[static_cast<std::size_t>(t[c])].z() > 0.0f)
                                            return false;
                                        return true;
                                      }),
                       knob.triangles.end());
  const auto triangles = addPart(mesh, knob, 1);
  const ControlParts inside = findControlParts(mesh, {{0.0f, 0.0f, 0.05f}, {0.2f, 0.1f, 0.0f}});
  ASSERT_TRUE(inside.parts[0]);
  EXPECT_EQ(inside.parts[0]->triangles, triangles);
  EXPECT_NE(inside.parts[0]->origin, PartOrigin::Grown);
  EXPECT_TRUE(!inside.parts[1] || inside.parts[1]->triangles != triangles);
  // On its top, outside it, the knob is too large to be taken whole.
  const ControlParts onTop = findControlParts(mesh, {{0.0f, 0.0f, 0.1f}, {0.2f, 0.1f, 0.0f}});
  ASSERT_TRUE(onTop.parts[0]);
  EXPECT_NE(onTop.parts[0]->triangles, triangles);
}

TEST(ControlParts, AKnobBesideABlockTurnsAboutThePanelNotTheBlock) {
  // A knob on a panel with a block against one of its sides (a bezel, a rail): the panel it
  // stands on is where most of its contact faces, so it turns about up, not a slant of the two.
  Mesh mesh = panel();
  addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.03f}), 1);
  addPart(mesh, test::box({0.02f, -0.04f, 0.0f}, {0.06f, 0.04f, 0.02f}), 0);
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.03f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(found.parts[0]->axis.z(), 0.999f);
}

TEST(ControlParts, AKnobIsJudgedRoundOrLongAcrossThePanelItStandsOn) {
  // A flat square knob cap with its grip bar in another material standing through its middle: the
  // surface nearest the cap's centre is the bar's side, and across that way the cap looks four
  // times longer than high (a lever). Across the panel it stands on it is round: a knob turning
  // about the panel's normal.
  Mesh mesh = panel();
  mesh.materials.resize(3);
  const auto cap = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.01f}), 1);
  addPart(mesh, test::box({-0.001f, -0.02f, 0.0f}, {0.001f, 0.02f, 0.025f}), 2);
  const ControlParts found = findControlParts(mesh, {{0.012f, 0.012f, 0.01f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, cap);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(std::abs(found.parts[0]->axis.z()), 0.999f);
}

TEST(ControlParts, AGripTurnsWithWhatHoldsItNotAsALever) {
  // A knob's grip bar in its own material, 6 cm long, laid across the middle of the knob's round
  // face (a disc 7 cm across on the panel): it is long, but held alike at both ends, so no end of
  // it is a pivot; it turns with the disc that holds it, about the disc's axis (the panel's
  // normal), not lifting about a level axis as a lever would.
  Mesh mesh = panel();
  mesh.materials.resize(3);
  addPart(mesh, test::cylinder(0.035f, 0.012f, 24), 2);
  const auto bar = addPart(mesh, test::box({-0.03f, -0.006f, 0.012f}, {0.03f, 0.006f, 0.03f}), 1);
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.03f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->triangles, bar);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(std::abs(found.parts[0]->axis.z()), std::cos(2.0f * static_cast<float>(M_PI) / 180.0f))
      << found.parts[0]->axis.transpose();
  EXPECT_NEAR(found.parts[0]->pivot.x(), 0.0f, 1e-3f);  // its middle, not an end
  // A bar through a round pipe lying along x on the panel turns about the pipe's axis, which is
  // neither the panel's normal nor any of the bar's own directions: what holds it decides. Its
  // corners stand clear of the pipe (a low-poly bar): it touches the pipe between them.
  Mesh piped = panel();
  piped.materials.resize(3);
  const Eigen::Matrix3f alongX =
      Eigen::AngleAxisf(static_cast<float>(M_PI) / 2.0f, Eigen::Vector3f::UnitY()).toRotationMatrix();
  addPart(piped, test::cylinder(0.02f, 0.2f, 48, alongX, {-0.1f, 0.0f, 0.02f}), 2);
  addPart(piped, test::box({-0.005f, -0.03f, 0.017f}, {0.005f, 0.03f, 0.023f}), 1);
  const ControlParts throughPipe = findControlParts(piped, {{0.0f, 0.028f, 0.023f}});
  ASSERT_TRUE(throughPipe.parts[0]);
  EXPECT_EQ(throughPipe.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(std::abs(throughPipe.parts[0]->axis.x()), std::cos(5.0f * static_cast<float>(M_PI) / 180.0f))
      << throughPipe.parts[0]->axis.transpose();
  EXPECT_NEAR(throughPipe.parts[0]->pivot.y(), 0.0f, 1e-3f);  // the pipe's, not an end
  // The same bar held at one end only (reaching out over the panel from a post) stays a lever.
  Mesh held = panel();
  held.materials.resize(3);
  addPart(held, test::box({-0.035f, -0.01f, 0.0f}, {-0.025f, 0.01f, 0.012f}), 2);
  addPart(held, test::box({-0.03f, -0.006f, 0.012f}, {0.03f, 0.006f, 0.03f}), 1);
  const ControlParts lever = findControlParts(held, {{0.0f, 0.0f, 0.03f}});
  ASSERT_TRUE(lever.parts[0]);
  EXPECT_EQ(lever.parts[0]->motion, ControlMotion::Lever);
}

TEST(ControlParts, ALongPartWithANonFiniteCornerTouchingNothingIsNoError) {
  // A bar floating over the panel (so its faces are looked at between its corners), one corner
  // not a number: a part or a site, never a crash.
  Mesh mesh = panel();
  mesh.materials.resize(2);
  const auto bar = addPart(mesh, test::box({-0.03f, -0.005f, 0.05f}, {0.03f, 0.005f, 0.06f}), 1);
  mesh.positions[static_cast<std::size_t>(mesh.triangles[static_cast<std::size_t>(bar[0])][0])].x() =
      std::numeric_limits<float>::quiet_NaN();
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.06f}});
  ASSERT_EQ(found.parts.size(), 1u);
  if (found.parts[0]) EXPECT_FALSE(found.parts[0]->triangles.empty());
}

TEST(ControlParts, ARoundHandleOnItsSideTurnsAboutItsOwnAxisNotThePanels) {
  // A round valve handle, 4 cm across and 3 cm deep, lying on its side on the panel (as on a
  // pipe): it touches the panel, whose normal is up, but it is a body of revolution about x.
  Mesh mesh = panel();
  const Eigen::Matrix3f onItsSide =
      Eigen::AngleAxisf(static_cast<float>(M_PI) / 2.0f, Eigen::Vector3f::UnitY()).toRotationMatrix();
  addPart(mesh, test::cylinder(0.02f, 0.03f, 48, onItsSide, {-0.015f, 0.0f, 0.02f}), 1);
  const ControlParts found = findControlParts(mesh, {{0.015f, 0.0f, 0.02f}});
  ASSERT_TRUE(found.parts[0]);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Knob);
  EXPECT_GT(std::abs(found.parts[0]->axis.x()), std::cos(3.0f * static_cast<float>(M_PI) / 180.0f))
      << found.parts[0]->axis.transpose();
  // Leaning only 15 degrees off the panel's normal, the panel's normal stands: a fit's nudge of a
  // few degrees is not worth more than the plane the knob stands on.
  Mesh leaning = panel();
  const Eigen::Matrix3f lean =
      Eigen::AngleAxisf(15.0f * static_cast<float>(M_PI) / 180.0f, Eigen::Vector3f::UnitY()).toRotationMatrix();
  addPart(leaning, test::cylinder(0.02f, 0.015f, 48, lean, {0.0f, 0.0f, 0.0055f}), 1);
  const ControlParts nudged = findControlParts(leaning, {Eigen::Vector3f(0.0f, 0.0f, 0.0055f) + 0.015f * (lean * Eigen::Vector3f::UnitZ())});
  ASSERT_TRUE(nudged.parts[0]);
  EXPECT_EQ(nudged.parts[0]->motion, ControlMotion::Knob);
  EXPECT_LT(std::abs(nudged.parts[0]->axis.dot(lean * Eigen::Vector3f::UnitZ())), 0.99f)
      << nudged.parts[0]->axis.transpose();
}

TEST(ControlParts, ALargeHandleOnASmallBodyIsStillItsPart) {
  // A faucet's lever handle holding more than a quarter of the object's surface (here 46 %): a
  // part, not refused; only a part that would take most of the object is.
  Mesh mesh = test::box({0.0f, 0.0f, 0.0f}, {0.06f, 0.06f, 0.06f});
  mesh.materials.resize(2);
  mesh.triangleMaterials.assign(mesh.triangles.size(), 0);
  const auto handle = addPart(mesh, test::box({0.03f, 0.015f, 0.06f}, {0.17f, 0.045f, 0.09f}), 1);
  const ControlParts found = findControlParts(mesh, {{0.1f, 0.03f, 0.075f}});
  ASSERT_TRUE(found.parts[0]) << found.warnings[0];
  EXPECT_EQ(found.parts[0]->triangles, handle);
  EXPECT_EQ(found.parts[0]->motion, ControlMotion::Lever);
  // A handle three times as long would hold most of the object's surface: refused.
  Mesh body = test::box({0.0f, 0.0f, 0.0f}, {0.06f, 0.06f, 0.06f});
  body.materials.resize(2);
  body.triangleMaterials.assign(body.triangles.size(), 0);
  addPart(body, test::box({0.03f, 0.015f, 0.06f}, {0.45f, 0.045f, 0.09f}), 1);
  const ControlParts most = findControlParts(body, {{0.2f, 0.03f, 0.075f}});
  EXPECT_TRUE(!most.parts[0] || most.parts[0]->triangles.empty() ||
              most.parts[0]->origin == PartOrigin::Disc)
      << toString(most.parts[0]->origin);
}

TEST(ControlParts, NoPointsAndNoSurfaceAreNotErrors) {
  EXPECT_TRUE(findControlParts(panel(), {}).parts.empty());
  const ControlParts none = findControlParts(Mesh(), {{0, 0, 0}});
  ASSERT_EQ(none.parts.size(), 1u);
  EXPECT_FALSE(none.parts[0]);
  EXPECT_FALSE(none.warnings[0].empty());
}

TEST(ControlParts, DescribeAGivenPartIgnoresTrianglesTheMeshLacks) {
  Mesh mesh = panel();
  auto knob = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.03f}), 1);
  knob.push_back(100000);
  knob.push_back(-3);
  const ControlPart part = describeControlPart(mesh, knob, PartOrigin::Grown);
  EXPECT_EQ(part.triangles.size(), 12u);
  EXPECT_EQ(part.motion, ControlMotion::Knob);
}

TEST(ControlPartEdit, GrowAddsTheNeighboursAndShrinkTakesThemBack) {
  const Mesh mesh = bumpyPanel(0.02f);  // the fan of 6 triangles around the raised vertex
  const ControlParts found = findControlParts(mesh, {{0.0f, 0.0f, 0.02f}, {0.12f, 0.0f, 0.0f}});
  ASSERT_TRUE(found.parts[0]);
  const std::vector<int> fan = found.parts[0]->triangles;
  const std::vector<int> grown = grownPart(mesh, fan);
  EXPECT_GT(grown.size(), fan.size());
  EXPECT_TRUE(std::includes(grown.begin(), grown.end(), fan.begin(), fan.end()));
  EXPECT_EQ(shrunkPart(mesh, grown), fan);
  EXPECT_EQ(shrunkPart(mesh, fan), fan);  // all border: kept, never emptied
  EXPECT_TRUE(grownPart(mesh, {}).empty());
}

TEST(ControlPartEdit, TheBrushTakesTheConnectedSurfaceAroundTheClickAndNothingBehindIt) {
  // A separate knob on a panel: a brush larger than the knob takes the knob and not the panel.
  Mesh mesh = panel();
  const auto knob = addPart(mesh, test::box({-0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.03f}), 1);
  int top = -1;
  for (int t : knob) {
    const auto& tri = mesh.triangles[std::size_t(t)];
    if (mesh.positions[std::size_t(tri[0])].z() > 0.029f && mesh.positions[std::size_t(tri[1])].z() > 0.029f &&
        mesh.positions[std::size_t(tri[2])].z() > 0.029f)
      top = t;
  }
  ASSERT_GE(top, 0);
  EXPECT_EQ(brushedPart(mesh, {}, top, {0.0f, 0.0f, 0.03f}, 0.2f, true), knob);
  // Taken away again, the part is empty; a click off the mesh changes nothing.
  EXPECT_TRUE(brushedPart(mesh, knob, top, {0.0f, 0.0f, 0.03f}, 0.2f, false).empty());
  EXPECT_EQ(brushedPart(mesh, knob, -1, {0.0f, 0.0f, 0.03f}, 0.2f, false), knob);

  // A fused panel: the brush takes the triangles whose corners all lie within its radius, more
  // with a larger one, and the clicked triangle even when it is larger than the brush.
  const Mesh flat = bumpyPanel(0.0f);
  const Eigen::Vector3f hit(0.005f, 0.001f, 0.0f);
  int clicked = -1;
  for (std::size_t t = 0; t < flat.triangles.size() && clicked < 0; ++t) {
    const auto& tri = flat.triangles[t];
    Eigen::Vector3f c = (flat.positions[std::size_t(tri[0])] + flat.positions[std::size_t(tri[1])] +
                         flat.positions[std::size_t(tri[2])]) / 3.0f;
    if ((c - hit).norm() < 0.01f) clicked = static_cast<int>(t);
  }
  ASSERT_GE(clicked, 0);
  const auto small = brushedPart(flat, {}, clicked, hit, 0.001f, true);
  EXPECT_EQ(small, std::vector<int>{clicked});
  const auto middle = brushedPart(flat, {}, clicked, hit, 0.05f, true);
  const auto large = brushedPart(flat, {}, clicked, hit, 0.1f, true);
  EXPECT_GT(middle.size(), 4u);
  EXPECT_GT(large.size(), middle.size());
  for (int t : middle)
    for (int v : flat.triangles[std::size_t(t)]) {
      if (t != clicked) {
        EXPECT_LE((flat.positions[std::size_t(v)] - hit).norm(), 0.05f);
      }
    }
  // Brushing the middle away from the large one leaves a ring.
  const auto ring = brushedPart(flat, large, clicked, hit, 0.05f, false);
  EXPECT_EQ(ring.size(), large.size() - middle.size());
  // One welded surface kept for many edits (as the GUI keeps one per mesh): no edit changes it,
  // so the same click gives the same part after other edits.
  const PartEditSurface surface(flat);
  const auto first = brushedPart(surface, {}, clicked, hit, 0.05f, true);
  EXPECT_EQ(first, middle);
  EXPECT_EQ(brushedPart(surface, large, clicked, hit, 0.05f, false), ring);
  EXPECT_GT(grownPart(surface, first).size(), first.size());
  EXPECT_LT(shrunkPart(surface, large).size(), large.size());
  EXPECT_EQ(brushedPart(surface, {}, clicked, hit, 0.05f, true), first);
}

}  // namespace
}  // namespace sagrid
