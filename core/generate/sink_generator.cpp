#include "core/generate/sink_generator.h"

#include <algorithm>
#include <cmath>

#include "core/generate/angles.h"
#include "core/generate/parts.h"
#include "core/generate/shape_builder.h"

namespace sagrid::gen {

namespace {

class SinkBuilder {
 public:
  explicit SinkBuilder(Rng& rng) : m_rng(rng) {}
  GeneratedObject run();

 private:
  void choose();
  void buildCounterAndBasins();
  void buildVesselBasin();
  void buildBasinCavity(const RoundedRect& hole, float topZ, float depth);
  void buildFaucet(const Vec3& base);
  void buildWallFaucet(const Vec3& wallPoint);
  Vec3 buildSpout(const Vec3& start, const Vec3& startDir);
  void buildOutlet(const std::vector<Vec3>& path, float radius);
  void buildLever(const Vec3& hub, const Vec3& axis, const Vec3& armDir, float length);
  void buildTwinHandle(const Vec3& base, float stem);
  void buildDistractors();
  void gt(const std::string& type, const Vec3& p, const Vec3& n, std::size_t t0) {
    m_points.push_back({type, p, n, t0, m_b.triangleCount()});
  }

  Rng& m_rng;
  ShapeBuilder m_b;
  std::vector<GroundTruthPoint> m_points;
  nlohmann::json m_params = nlohmann::json::object();
  std::vector<std::string> m_distractors;

  std::string m_kind, m_shape, m_faucet, m_handle;
  int m_basins = 1;
  float m_reach = 0.15f, m_spoutHeight = 0.25f;
  float m_bodyR = 0.02f, m_tubeR = 0.012f;
  int m_metal = 0, m_handleMat = 0, m_dark = 0, m_counterMat = 0, m_basinMat = 0;
  std::string m_finish;
  int m_sides = 16;
  // Deck geometry for placing the faucet and distractors.
  float m_deckZ = 0, m_faucetX = 0, m_faucetY = 0, m_wallY = 0;
  bool m_wall = false;
  float m_counterHalfW = 0.3f;
  std::vector<Vec2> m_basinCenters;
};

void SinkBuilder::choose() {
  m_kind = sinkKinds()[m_rng.weighted({0.32, 0.26, 0.14, 0.12, 0.1, 0.06})];
  // bare_faucet, counter_sink, vanity, bare_basin, farmhouse, wall_basin

  std::vector<std::string> faucets;
  std::vector<double> weights;
  if (m_kind == "bare_faucet") {
    faucets = {"gooseneck", "straight", "pull_down", "wall_mounted", "bridge", "compact", "arm_metaworld", "square_mixer"};
    weights = {0.15, 0.12, 0.08, 0.08, 0.08, 0.15, 0.17, 0.17};
  } else if (m_kind == "wall_basin") {
    faucets = {"wall_mounted"};
    weights = {1};
  } else if (m_kind == "vanity" || m_kind == "bare_basin") {
    faucets = {"gooseneck", "straight", "compact", "bridge", "wall_mounted", "square_mixer"};
    weights = {0.2, 0.22, 0.22, 0.08, 0.08, 0.2};
  } else {
    faucets = {"gooseneck", "straight", "pull_down", "bridge", "wall_mounted", "compact", "square_mixer"};
    weights = {0.27, 0.13, 0.22, 0.12, 0.07, 0.09, 0.1};
  }
  m_faucet = faucets[m_rng.weighted(weights)];
  m_wall = m_faucet == "wall_mounted";

  std::vector<std::string> handles;
  if (m_faucet == "arm_metaworld") {
    handles = {"arm"};
    weights = {1};
  } else if (m_faucet == "bridge") {
    handles = {"twin_cross", "twin_knob", "twin_lever"};
    weights = {0.45, 0.3, 0.25};
  } else if (m_faucet == "wall_mounted") {
    handles = {"twin_cross", "twin_knob", "twin_lever", "single_top_lever"};
    weights = {0.3, 0.25, 0.2, 0.25};
  } else if (m_faucet == "square_mixer") {
    handles = {"single_top_lever", "joystick"};
    weights = {0.8, 0.2};
  } else if (m_faucet == "compact") {
    handles = {"single_top_lever", "joystick", "side_lever"};
    weights = {0.55, 0.25, 0.2};
  } else {
    handles = {"single_top_lever", "side_lever", "joystick", "twin_cross", "twin_knob"};
    weights = {0.32, 0.22, 0.12, 0.18, 0.16};
  }
  m_handle = handles[m_rng.weighted(weights)];

  m_finish = m_rng.pick(std::vector<std::string>{"chrome", "chrome", "stainless", "brushed_nickel",
                                                  "matte_black", "brass", "white_enamel"});
  m_metal = m_b.material("faucet_" + m_finish, finishNamed(m_rng, m_finish).color);
  m_handleMat = m_rng.chance(0.75) ? m_metal
                                   : m_b.material("handle", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                                                          "red", "blue", "ceramic_white", "matte_black"})).color);
  if (m_faucet == "arm_metaworld" && m_rng.chance(0.6)) {
    m_handleMat = m_b.material("handle_red", finishNamed(m_rng, "red").color);
  }
  m_dark = m_b.material("dark", jitter(m_rng, {0.08f, 0.08f, 0.08f}, 0.04f));
  m_bodyR = m_rng.uniformf(0.014, 0.028);
  m_tubeR = std::min(m_bodyR * 0.9f, m_rng.uniformf(0.008, 0.016));
  m_sides = m_rng.pick(std::vector<int>{8, 12, 16, 24});
  const std::string basinFinish = m_rng.pick(std::vector<std::string>{"stainless", "stainless", "ceramic_white",
                                                                      "granite", "matte_black", "cream"});
  m_basinMat = m_b.material("basin_" + basinFinish, finishNamed(m_rng, basinFinish).color);
  const std::string counterFinish = m_rng.pick(std::vector<std::string>{"granite", "wood", "laminate",
                                                                        "ceramic_white", "matte_black", "dark_grey"});
  m_counterMat = m_b.material("counter_" + counterFinish, finishNamed(m_rng, counterFinish).color);

  if (m_kind == "counter_sink" || m_kind == "farmhouse") m_basins = m_rng.chance(0.35) ? 2 : 1;
  m_shape = (m_kind == "farmhouse") ? "rectangular"
            : m_rng.chance(m_kind == "counter_sink" ? 0.75 : 0.5) ? "rectangular" : "round";
}

void SinkBuilder::buildBasinCavity(const RoundedRect& hole, float topZ, float depth) {
  // Inner surface of the bowl, tapering towards a rounded bottom, with a drain.
  const int corners = m_rng.pick(std::vector<int>{3, 4, 6});
  const float taper = m_rng.uniformf(0.0, 0.15);
  std::vector<RoundedRect> rings;
  const int steps = 4;
  for (int i = 0; i <= steps; ++i) {
    const float t = float(i) / steps;
    RoundedRect r = hole;
    const float shrink = 1.0f - taper * t * t;
    r.half = hole.half * shrink;
    r.radius = std::min(hole.radius * shrink, r.half.minCoeff());
    r.z = topZ - depth * t;
    rings.push_back(r);
  }
  // Rounded floor edge.
  RoundedRect floor = rings.back();
  floor.half -= Vec2::Constant(0.015f);
  floor.radius = std::max(0.0f, floor.radius - 0.015f);
  floor.z -= 0.01f;
  rings.push_back(floor);
  m_b.loft(Affine::Identity(), rings, corners, m_basinMat, false, true);
  m_b.cylinder(translation(hole.center.x(), hole.center.y() + 0.25f * hole.half.y(), floor.z), 0.035f, 0, 0.002f, 20, m_dark);
}

void SinkBuilder::buildCounterAndBasins() {
  const bool cabinet = m_kind == "vanity" || m_kind == "farmhouse" || m_rng.chance(0.5);
  const float counterW = m_kind == "vanity" ? m_rng.uniformf(0.5, 1.0)
                                            : (m_basins == 2 ? m_rng.uniformf(0.9, 1.5) : m_rng.uniformf(0.6, 1.2));
  const float counterD = m_kind == "vanity" ? m_rng.uniformf(0.42, 0.56) : m_rng.uniformf(0.52, 0.66);
  const float thick = m_rng.uniformf(0.02, 0.05);
  const float topZ = cabinet ? m_rng.uniformf(0.8, 0.92) : thick;
  m_counterHalfW = 0.5f * counterW;
  m_deckZ = topZ;

  // Basin holes, in front of the faucet deck.
  const float basinD = std::min(counterD - 0.16f, m_rng.uniformf(0.32, 0.45));
  const float gap = m_rng.uniformf(0.04, 0.08);
  const float basinW = m_basins == 2 ? std::min(0.5f * (counterW - 0.12f) - 0.5f * gap, m_rng.uniformf(0.3, 0.45))
                                     : std::min(counterW - 0.12f, m_rng.uniformf(0.35, 0.75) * (m_kind == "vanity" ? 0.8f : 1.0f));
  const float cy = -0.5f * counterD + 0.04f + 0.5f * basinD + m_rng.uniformf(0.0, 0.03);
  const float radius = m_shape == "round" ? 0.5f * std::min(basinW, basinD) : m_rng.uniformf(0.005, 0.07);
  std::vector<RoundedRect> holes;
  for (int i = 0; i < m_basins; ++i) {
    RoundedRect h;
    const float cx = m_basins == 2 ? (i == 0 ? -1.0f : 1.0f) * (0.5f * basinW + 0.5f * gap) : 0.0f;
    h.center = Vec2(cx, cy);
    h.half = m_shape == "round" ? Vec2::Constant(0.5f * std::min(basinW, basinD)) : Vec2(0.5f * basinW, 0.5f * basinD);
    if (m_shape == "round" && m_rng.chance(0.4)) h.half = Vec2(0.5f * basinW, 0.5f * basinD);  // oval
    h.radius = std::min(radius, h.half.minCoeff());
    holes.push_back(h);
    m_basinCenters.push_back(h.center);
  }

  // Counter: one cell per basin (a plate with a hole), boxes filling the rest.
  const float cellHalfW = m_basins == 2 ? 0.5f * (basinW + gap) : 0.5f * basinW + 0.03f;
  const float z0 = topZ - thick;
  const bool farm = m_kind == "farmhouse";
  for (int i = 0; i < m_basins; ++i) {
    const float cellX = holes[i].center.x();
    RoundedRect local = holes[i];
    local.center = Vec2(0, holes[i].center.y());
    if (farm) {
      // The apron replaces the counter in front of the basin.
      const float backY = holes[i].center.y() + holes[i].half.y();
      m_b.boxFromTo(Vec3(cellX - cellHalfW, backY, z0), Vec3(cellX + cellHalfW, 0.5f * counterD, topZ), m_counterMat);
    } else {
      m_b.plateWithHole(translation(cellX, 0, 0), Vec2(cellHalfW, 0.5f * counterD), local, z0, topZ,
                        m_rng.pick(std::vector<int>{3, 4, 6}), m_counterMat);
    }
  }
  const float usedHalf = m_basins == 2 ? 2 * cellHalfW * 0.5f + cellHalfW : cellHalfW;
  const float left = -0.5f * counterW, right = 0.5f * counterW;
  const float innerL = m_basins == 2 ? holes[0].center.x() - cellHalfW : -cellHalfW;
  const float innerR = m_basins == 2 ? holes[1].center.x() + cellHalfW : cellHalfW;
  (void)usedHalf;
  if (innerL > left + 1e-4f) m_b.boxFromTo(Vec3(left, -0.5f * counterD, z0), Vec3(innerL, 0.5f * counterD, topZ), m_counterMat, m_rng.pick(std::vector<int>{1, 3}));
  if (innerR < right - 1e-4f) m_b.boxFromTo(Vec3(innerR, -0.5f * counterD, z0), Vec3(right, 0.5f * counterD, topZ), m_counterMat);

  const float depth = m_rng.uniformf(0.12, 0.23) * (m_kind == "vanity" ? 0.7f : 1.0f);
  for (const auto& h : holes) buildBasinCavity(h, topZ, depth);
  if (farm) {
    // Apron front and basin walls standing proud of the cabinet.
    for (const auto& h : holes) {
      const float x0 = h.center.x() - cellHalfW, x1 = h.center.x() + cellHalfW;
      const float frontY = -0.5f * counterD - 0.01f;
      m_b.boxFromTo(Vec3(x0, frontY, topZ - depth - 0.04f), Vec3(x1, h.center.y() - h.half.y(), topZ + 0.002f), m_basinMat);
      m_b.boxFromTo(Vec3(x0, h.center.y() - h.half.y(), z0), Vec3(h.center.x() - h.half.x(), h.center.y() + h.half.y(), topZ),
                    m_basinMat);
      m_b.boxFromTo(Vec3(h.center.x() + h.half.x(), h.center.y() - h.half.y(), z0), Vec3(x1, h.center.y() + h.half.y(), topZ),
                    m_basinMat);
    }
  } else if (m_rng.chance(0.5)) {
    // Drop-in rim around each hole.
    for (const auto& h : holes) {
      RoundedRect local = h;
      local.center = Vec2(0, 0);
      m_b.plateWithHole(translation(h.center.x(), h.center.y(), 0), h.half + Vec2::Constant(0.02f), local, topZ,
                        topZ + 0.004f, 4, m_basinMat);
    }
    m_params["rim"] = "drop_in";
  } else {
    m_params["rim"] = "undermount";
  }

  if (cabinet) {
    const int cab = m_b.material("cabinet", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                                                   "white_enamel", "wood", "laminate", "dark_grey", "pastel_blue"})).color);
    const float plinth = m_rng.uniformf(0.0, 0.1);
    m_b.boxFromTo(Vec3(-0.5f * counterW + 0.01f, -0.5f * counterD + 0.03f, plinth), Vec3(0.5f * counterW - 0.01f, 0.5f * counterD, z0), cab,
                  m_rng.pick(std::vector<int>{1, 2}));
    if (plinth > 0) m_b.boxFromTo(Vec3(-0.5f * counterW + 0.04f, -0.5f * counterD + 0.08f, 0), Vec3(0.5f * counterW - 0.04f, 0.5f * counterD - 0.02f, plinth), m_dark);
    const int doors = counterW > 0.7f ? 2 : 1;
    for (int i = 0; i < doors; ++i) {
      const float w = (counterW - 0.04f) / doors;
      const float x = -0.5f * counterW + 0.02f + (i + 0.5f) * w;
      m_b.box(translation(x, -0.5f * counterD + 0.02f, 0.5f * (plinth + z0) - 0.01f), Vec3(w - 0.006f, 0.02f, z0 - plinth - 0.04f), cab);
      const float hx = x + (doors == 2 ? (i == 0 ? 0.4f : -0.4f) : 0.4f) * w;
      buildBarHandle(m_b, translation(hx, -0.5f * counterD + 0.01f, z0 - 0.12f) * rotationX(kPi / 2) * rotationY(kPi / 2),
                     0.1f, 0.022f, 0.005f, m_metal);
    }
    m_params["cabinet"] = true;
  } else {
    m_params["cabinet"] = false;
  }

  m_faucetY = cy + 0.5f * basinD + m_rng.uniformf(0.035, 0.06);
  m_faucetY = std::min(m_faucetY, 0.5f * counterD - 0.03f);
  m_faucetX = m_basins == 2 && m_rng.chance(0.5) ? holes[m_rng.uniformInt(0, 1)].center.x() : 0.0f;
  if (m_wall || m_rng.chance(0.3)) {
    // Backsplash wall; wall-mounted faucets come out of it.
    const float wallH = m_rng.uniformf(0.1, 0.5);
    const int wallMat = m_rng.chance(0.5) ? m_counterMat : m_b.material("tiles", finishNamed(m_rng, "ceramic_white").color);
    m_b.boxFromTo(Vec3(-0.5f * counterW, 0.5f * counterD, z0), Vec3(0.5f * counterW, 0.5f * counterD + 0.02f, topZ + wallH), wallMat,
                  m_rng.pick(std::vector<int>{1, 4}));
    m_wallY = 0.5f * counterD;
    m_distractors.push_back("backsplash");
    if (m_wall) m_faucetY = m_wallY;
  }
  m_params["counter_width_m"] = roundedToMillimetre(counterW);
}

void SinkBuilder::buildVesselBasin() {
  // A free-standing bowl (or wall-hung basin) with a deck at the back for the faucet.
  const float w = m_rng.uniformf(0.3, 0.6), d = m_rng.uniformf(0.28, 0.45);
  const float h = m_rng.uniformf(0.1, 0.2);
  const float wall = m_rng.uniformf(0.008, 0.02);
  const bool round = m_shape == "round";
  const float deck = (m_wall || m_faucet == "bridge") ? m_rng.uniformf(0.02, 0.04) : m_rng.uniformf(0.07, 0.11);
  const float r = round ? 0.5f * std::min(w, d) : m_rng.uniformf(0.01, 0.06);
  RoundedRect outerBottom{Vec2(0, 0), Vec2(0.5f * w, 0.5f * d) * m_rng.uniformf(0.75, 1.0), 0, 0};
  outerBottom.radius = round ? outerBottom.half.minCoeff() : r;
  RoundedRect outerTop{Vec2(0, 0), Vec2(0.5f * w, 0.5f * d), r, h};
  RoundedRect innerTop{Vec2(0, -0.5f * deck), Vec2(0.5f * w - wall, 0.5f * (d - deck) - wall), 0, h};
  innerTop.radius = std::min(round ? innerTop.half.minCoeff() : std::max(0.0f, r - wall), innerTop.half.minCoeff());
  RoundedRect innerBottom = innerTop;
  innerBottom.half *= 0.8f;
  innerBottom.radius *= 0.8f;
  innerBottom.z = wall + 0.01f;
  m_b.loft(Affine::Identity(), {outerBottom, outerTop, innerTop, innerBottom}, m_rng.pick(std::vector<int>{4, 6, 8}), m_basinMat,
           true, true);
  m_b.cylinder(translation(innerBottom.center.x(), innerBottom.center.y(), innerBottom.z), 0.025f, 0, 0.002f, 16, m_dark);
  m_basinCenters.push_back(innerTop.center);
  m_deckZ = h;
  m_faucetX = 0;
  m_faucetY = 0.5f * d - 0.5f * deck;
  m_counterHalfW = 0.5f * w;
  if (m_wall || m_kind == "wall_basin") {
    const float wallH = h + m_rng.uniformf(0.15, 0.4);
    m_b.boxFromTo(Vec3(-0.5f * w - 0.05f, 0.5f * d, -0.05f), Vec3(0.5f * w + 0.05f, 0.5f * d + 0.02f, wallH),
                  m_b.material("wall", finishNamed(m_rng, "ceramic_white").color), m_rng.pick(std::vector<int>{1, 4}));
    m_wallY = 0.5f * d;
    if (m_wall) m_faucetY = m_wallY;
  }
}

void SinkBuilder::buildOutlet(const std::vector<Vec3>& path, float radius) {
  const std::size_t t0 = m_b.triangleCount();
  m_b.tube(path, radius, m_sides, m_metal);
  const Vec3 end = path.back();
  const Vec3 dir = (path.back() - path[path.size() - 2]).normalized();
  // Aerator: a short, slightly wider ring at the mouth.
  m_b.lathe(alignZTo(end - dir * 0.012f, dir), {{radius * 1.08f, 0}, {radius * 1.08f, 0.012f}, {0, 0.0121f}}, m_sides, m_dark);
  gt("fluidsource", end + dir * 0.0001f, dir, t0);
}

// Spout from `start` leaving in direction `startDir` (usually up), shaped by the faucet type.
// Returns the outlet point.
Vec3 SinkBuilder::buildSpout(const Vec3& start, const Vec3& startDir) {
  const Vec3 fwd(0, -1, 0);
  std::vector<Vec3> path;
  if (m_faucet == "gooseneck" || m_faucet == "pull_down" || m_faucet == "bridge" || m_faucet == "compact") {
    // Rise, arch over towards the front, end pointing down.
    const float a = 0.5f * m_reach;
    const float rise = std::max(0.0f, m_spoutHeight - a - start.z() + m_deckZ);
    const Vec3 top = start + startDir * rise;
    path.push_back(start);
    if (rise > 0.002f) path.push_back(top);
    const int steps = 14;
    for (int i = 1; i <= steps; ++i) {
      const float th = kPi * i / steps;
      path.push_back(top + Vec3(0, 0, a * std::sin(th)) + fwd * (a - a * std::cos(th)));
    }
    const float drop = m_rng.uniformf(0.0, 0.04);
    if (drop > 0.004f) path.push_back(path.back() + Vec3(0, 0, -drop));
    if (m_faucet == "pull_down") {
      // The spout hose ends in a thicker spray head.
      m_b.tube(path, m_tubeR, m_sides, m_metal);
      const Vec3 headTop = path.back();
      const float headR = std::max(m_tubeR * 1.4f, m_rng.uniformf(0.016, 0.024));
      const float headL = m_rng.uniformf(0.05, 0.085);
      std::vector<Vec3> head = {headTop, headTop + Vec3(0, 0, -headL)};
      buildOutlet(head, headR);
      return head.back();
    }
  } else {
    // Straight: a column, then an (almost) horizontal spout ending in a short bend down.
    const float tilt = m_rng.uniformf(-0.25, 0.05);
    path.push_back(start);
    const Vec3 end = start + (fwd + Vec3(0, 0, tilt)).normalized() * m_reach;
    const Vec3 mid = 0.5f * (start + end) + Vec3(0, 0, m_rng.uniformf(0, 0.02));
    path.push_back(mid);
    path.push_back(end);
    path.push_back(end + Vec3(0, -0.01f, -0.02f));
    path.push_back(end + Vec3(0, -0.012f, -0.035f));
  }
  buildOutlet(path, m_tubeR);
  return path.back();
}

void SinkBuilder::buildLever(const Vec3& hub, const Vec3& axis, const Vec3& armDir, float length) {
  // Hub cylinder, then an arm; the grip is the middle of the arm.
  m_b.cylinder(alignZTo(hub, axis), m_bodyR * 0.85f, 0, m_rng.uniformf(0.012, 0.022), m_sides, m_metal);
  const std::size_t t0 = m_b.triangleCount();
  const Vec3 a = hub + axis * 0.012f;
  const Vec3 b = a + armDir.normalized() * length;
  const float thick = m_rng.uniformf(0.005, 0.009);
  if (m_rng.chance(0.5)) {
    m_b.tube({a, 0.5f * (a + b) + axis * 0.004f, b}, thick, 8, m_handleMat);
  } else {
    Affine f = alignZTo(0.5f * (a + b), b - a);
    m_b.box(f, Vec3(thick * 2.5f, thick * 1.4f, length), m_handleMat, thick * 0.5f, 1);
  }
  gt("togglebutton", 0.5f * (a + b), axis, t0);
}

void SinkBuilder::buildTwinHandle(const Vec3& base, float stem) {
  // Escutcheon, stem and a cross, knob or small lever handle.
  m_b.cylinder(translation(base), m_bodyR * 1.3f, 0, 0.008f, m_sides, m_metal);
  m_b.cylinder(translation(base), m_bodyR * 0.55f, 0, stem, m_sides, m_metal);
  const Vec3 top = base + Vec3(0, 0, stem);
  const std::size_t t0 = m_b.triangleCount();
  if (m_handle == "twin_cross") {
    const float arm = m_rng.uniformf(0.025, 0.045);
    const float phase = m_rng.uniformf(0, kPi / 2);
    m_b.cylinder(translation(top), 0.012f, 0, 0.02f, m_sides, m_handleMat);
    for (int i = 0; i < 4; ++i) {
      const float ang = phase + i * kPi / 2;
      const Vec3 d(std::cos(ang), std::sin(ang), 0);
      m_b.tube({top + Vec3(0, 0, 0.01f), top + Vec3(0, 0, 0.012f) + d * arm}, 0.005f, 8, m_handleMat);
      m_b.lathe(translation(top + Vec3(0, 0, 0.012f) + d * arm), {{0, -0.006f}, {0.007f, -0.004f}, {0.007f, 0.004f}, {0, 0.006f}}, 10,
                m_handleMat);
    }
    gt("togglebutton", top + Vec3(0, 0, 0.011f), Vec3::UnitZ(), t0);
  } else if (m_handle == "twin_knob") {
    KnobShape k = randomKnob(m_rng, 1.0f);
    k.radius = m_rng.uniformf(0.015, 0.025);
    k.depth = m_rng.uniformf(0.02, 0.035);
    const Vec3 c = buildKnob(m_b, translation(top), k, m_handleMat, m_metal);
    gt("togglebutton", c, Vec3::UnitZ(), t0);
  } else {  // twin_lever: a short lever pointing outwards
    const float len = m_rng.uniformf(0.04, 0.07);
    const Vec3 outward = base.x() >= m_faucetX ? Vec3(1, 0, 0) : Vec3(-1, 0, 0);
    const Vec3 a = top;
    const Vec3 b = top + (outward + Vec3(0, 0, 0.2f)).normalized() * len;
    m_b.cylinder(translation(top - Vec3(0, 0, 0.002f)), 0.011f, 0, 0.014f, m_sides, m_handleMat);
    m_b.tube({a + Vec3(0, 0, 0.007f), b + Vec3(0, 0, 0.007f)}, 0.006f, 8, m_handleMat);
    gt("togglebutton", 0.5f * (a + b) + Vec3(0, 0, 0.007f), Vec3::UnitZ(), t0);
  }
}

void SinkBuilder::buildFaucet(const Vec3& base) {
  const Vec3 up = Vec3::UnitZ();
  const bool twin = m_handle.rfind("twin", 0) == 0;
  const float spread = m_rng.uniformf(0.07, 0.12);

  if (m_faucet == "arm_metaworld") {
    // Meta-World faucet: a base, a column, a head, and a long arm handle; often no spout.
    float headTop = 0, headR = 0;
    if (m_rng.chance(0.5)) {  // disc base, thin column, wide head (LIBERO's faucet)
      const float discR = m_rng.uniformf(0.03, 0.05), discH = m_rng.uniformf(0.004, 0.015);
      const float colR = m_rng.uniformf(0.008, 0.02), colH = m_rng.uniformf(0.05, 0.1);
      headR = m_rng.uniformf(0.022, 0.036);
      const float headH = m_rng.uniformf(0.025, 0.045);
      const int seg = m_rng.pick(std::vector<int>{16, 24, 32});
      m_b.cylinder(translation(base), discR, 0, discH, seg, m_metal);
      m_b.cylinder(translation(base), colR, discH, discH + colH, seg, m_metal);
      m_b.cylinder(translation(base), headR, discH + colH, discH + colH + headH, seg, m_metal);
      headTop = discH + colH + 0.5f * headH;
    } else {  // thick base column and a smaller head
      const float baseR = m_rng.uniformf(0.03, 0.05), baseH = m_rng.uniformf(0.07, 0.12);
      m_b.cylinder(translation(base), baseR, 0, baseH, m_rng.pick(std::vector<int>{16, 24, 32}), m_metal);
      headR = baseR * m_rng.uniformf(0.6, 0.8);
      const float headH = m_rng.uniformf(0.025, 0.045);
      m_b.cylinder(translation(base + Vec3(0, 0, baseH)), headR, 0, headH, 24, m_metal);
      headTop = baseH + 0.5f * headH;
    }
    const float armL = m_rng.uniformf(0.08, 0.16);
    const float armR = m_rng.uniformf(0.008, 0.018);
    const Vec3 dir = Vec3(0, -1, 0);
    const std::size_t t0 = m_b.triangleCount();
    const Vec3 a = base + Vec3(0, 0, headTop) + dir * (headR * 0.8f);
    const Vec3 b = a + dir * armL;
    m_b.tube({a, b}, armR, 12, m_handleMat, true, false);
    std::vector<Vec2> dome;  // rounded (capsule) end
    for (int i = 0; i <= 6; ++i) {
      const float t = 0.5f * kPi * i / 6;
      dome.push_back({armR * std::cos(t), armR * std::sin(t)});
    }
    m_b.lathe(alignZTo(b, dir), dome, 12, m_handleMat);
    gt("togglebutton", 0.5f * (a + b), up, t0);
    if (m_rng.chance(0.45)) {
      // A short spout on the opposite side.
      const Vec3 sp = base + Vec3(0, 0, headTop) + Vec3(0, headR * 0.9f, 0);
      buildOutlet({sp, sp + Vec3(0, 0.05f, 0), sp + Vec3(0, 0.07f, -0.015f), sp + Vec3(0, 0.075f, -0.03f)}, 0.009f);
      m_params["spout"] = true;
    } else {
      m_params["spout"] = false;
    }
    return;
  }

  if (m_faucet == "square_mixer") {
    // A modern square mixer (LIBERO's basin faucet): box body on a plate, a flat box spout with
    // the outlet on its underside near the tip, a flat lever on top.
    const float bw = m_rng.uniformf(0.025, 0.05), bd = m_rng.uniformf(0.025, 0.05), bh = m_rng.uniformf(0.06, 0.13);
    const float bevel = m_rng.chance(0.6) ? m_rng.uniformf(0.001, 0.005) : 0.0f;
    m_b.box(translation(base + Vec3(0, 0, 0.004f)), Vec3(bw * 1.3f, bd * 1.3f, 0.008f), m_metal, bevel * 0.5f, 1);
    m_b.box(translation(base + Vec3(0, 0, 0.5f * bh)), Vec3(bw, bd, bh), m_metal, bevel, 2);
    const float zs = bh * m_rng.uniformf(0.55, 0.85);
    const float spoutW = bw * m_rng.uniformf(0.5, 0.95), spoutH = m_rng.uniformf(0.012, 0.025);
    const float len = m_reach;
    const std::size_t t0 = m_b.triangleCount();
    m_b.box(translation(base + Vec3(0, -0.5f * bd - 0.5f * len + 0.002f, zs)), Vec3(spoutW, len + 0.004f, spoutH), m_metal,
            std::min(bevel, 0.3f * spoutH), 2);
    const Vec3 outlet = base + Vec3(0, -0.5f * bd - len + std::min(0.015f, 0.3f * len), zs - 0.5f * spoutH);
    m_b.cylinder(translation(outlet), std::min(0.4f * spoutW, 0.01f), -0.0015f, 0.0005f, 16, m_dark);
    gt("fluidsource", outlet - Vec3(0, 0, 0.0015f), -up, t0);
    const std::size_t t1 = m_b.triangleCount();
    if (m_handle == "joystick") {
      const Vec3 a = base + Vec3(0, 0, bh), b = a + Vec3(0, 0.015f, m_rng.uniformf(0.03, 0.06));
      m_b.tube({a, b}, m_rng.uniformf(0.004, 0.007), 8, m_handleMat);
      gt("togglebutton", 0.5f * (a + b), up, t1);
    } else {
      const float leverL = m_rng.uniformf(0.04, 0.09), leverW = bw * m_rng.uniformf(0.5, 1.0);
      const float tilt = m_rng.uniformf(-0.15, 0.3);
      const float sign = m_rng.chance(0.7) ? 1.0f : -1.0f;  // towards the back, or over the spout
      m_b.box(translation(base + Vec3(0, 0, bh + 0.006f)), Vec3(bw * 0.8f, bd * 0.8f, 0.012f), m_metal, 0.001f, 1);
      const Affine lever = translation(base + Vec3(0, 0, bh + 0.012f)) * rotationX(sign * tilt) *
                           translation(0, sign * (0.5f * leverL - 0.3f * bd), 0.004f);
      m_b.box(lever, Vec3(leverW, leverL, m_rng.uniformf(0.006, 0.012)), m_handleMat, 0.002f, 1);
      gt("togglebutton", lever * Vec3(0, 0, 0), up, t1);
    }
    return;
  }

  // Deck escutcheon and body column.
  const float bodyH = m_faucet == "compact" ? m_rng.uniformf(0.05, 0.09)
                      : m_faucet == "straight" ? m_rng.uniformf(0.07, 0.2)
                                               : m_rng.uniformf(0.03, 0.09);
  Vec3 spoutStart;
  if (m_faucet == "bridge") {
    const float riser = m_rng.uniformf(0.05, 0.1);
    const float bridgeZ = riser * m_rng.uniformf(0.5, 0.8);
    for (float sx : {-1.0f, 1.0f}) {
      buildTwinHandle(base + Vec3(sx * spread, 0, 0), riser);
    }
    m_b.tube({base + Vec3(-spread, 0, bridgeZ), base + Vec3(spread, 0, bridgeZ)}, m_bodyR * 0.55f, m_sides, m_metal);
    m_b.cylinder(translation(base + Vec3(0, 0, bridgeZ - 0.015f)), m_bodyR * 0.7f, 0, 0.03f, m_sides, m_metal);
    spoutStart = base + Vec3(0, 0, bridgeZ + 0.015f);
  } else {
    if (m_rng.chance(0.6)) m_b.cylinder(translation(base), m_bodyR * 1.35f, 0, 0.006f, m_sides, m_metal);
    if (m_rng.chance(0.7)) {
      m_b.cylinder(translation(base), m_bodyR, 0, bodyH, m_sides, m_metal);
    } else {
      m_b.box(translation(base + Vec3(0, 0, 0.5f * bodyH)), Vec3(2 * m_bodyR, 2 * m_bodyR, bodyH), m_metal, 0.004f, 2);
    }
    spoutStart = base + Vec3(0, 0, bodyH);
    if (twin) {
      for (float sx : {-1.0f, 1.0f}) buildTwinHandle(base + Vec3(sx * spread, 0, 0), m_rng.uniformf(0.02, 0.05));
    }
  }
  const Vec3 outlet = buildSpout(spoutStart, up);
  (void)outlet;

  if (m_handle == "single_top_lever") {
    // On top of the body; the arm points back or forward, tilted up.
    const Vec3 hub = base + Vec3(0, 0, bodyH + (m_faucet == "gooseneck" || m_faucet == "pull_down" ? 0.0f : 0.0f));
    const bool back = m_rng.chance(0.6);
    const Vec3 dir = Vec3(0, back ? 1.0f : -1.0f, m_rng.uniformf(0.1, 0.6));
    // Gooseneck spouts start at the top: put the lever just behind, on a short collar.
    const Vec3 h = (m_faucet == "compact" || m_faucet == "straight") ? Vec3(hub + Vec3(0, m_bodyR * 0.3f, 0))
                                                                      : Vec3(base + Vec3(0, m_bodyR * 1.2f, bodyH * 0.75f));
    const Vec3 axis = (m_faucet == "compact" || m_faucet == "straight") ? up : Vec3(0, 1, 0.3f).normalized();
    buildLever(h, axis, dir, m_rng.uniformf(0.045, 0.1));
  } else if (m_handle == "side_lever") {
    const float sx = m_rng.chance(0.7) ? 1.0f : -1.0f;
    const Vec3 hub = base + Vec3(sx * m_bodyR * 0.9f, 0, bodyH * 0.6f);
    buildLever(hub, Vec3(sx, 0, 0), Vec3(sx * 0.3f, 0.2f, 1.0f), m_rng.uniformf(0.04, 0.08));
  } else if (m_handle == "joystick") {
    const Vec3 hub = base + Vec3(0, m_bodyR * 0.2f, bodyH) + (m_faucet == "compact" || m_faucet == "straight" ? Vec3(Vec3::Zero()) : Vec3(0, m_bodyR * 1.1f, -0.3f * bodyH));
    const Vec3 axis = (m_faucet == "compact" || m_faucet == "straight") ? up : Vec3(0, 1, 0.4f).normalized();
    m_b.cylinder(alignZTo(hub, axis), m_bodyR * 0.75f, 0, 0.01f, m_sides, m_metal);
    const std::size_t t0 = m_b.triangleCount();
    const float len = m_rng.uniformf(0.035, 0.07);
    const Vec3 tipDir = (axis + Vec3(0, 0.25f, 0)).normalized();
    const Vec3 a = hub + axis * 0.01f, b = a + tipDir * len;
    m_b.tube({a, b}, m_rng.uniformf(0.004, 0.007), 8, m_handleMat);
    m_b.lathe(translation(b), {{0, -0.008f}, {0.008f, -0.004f}, {0.008f, 0.004f}, {0, 0.008f}}, 12, m_handleMat);
    gt("togglebutton", 0.5f * (a + b), axis, t0);
  }
}

void SinkBuilder::buildWallFaucet(const Vec3& wallPoint) {
  // Wall plate, a horizontal spout out of the wall, handles on the plate.
  const float plateW = m_handle.rfind("twin", 0) == 0 ? m_rng.uniformf(0.2, 0.28) : m_rng.uniformf(0.06, 0.1);
  m_b.box(translation(wallPoint + Vec3(0, -0.004f, 0)), Vec3(plateW, 0.008f, m_rng.uniformf(0.05, 0.08)), m_metal, 0.003f, 2);
  const Vec3 start = wallPoint + Vec3(0, -0.008f, 0);
  const float bodyL = 0.04f;
  m_b.cylinder(alignZTo(start, Vec3(0, -1, 0)), m_bodyR, 0, bodyL, m_sides, m_metal);
  std::vector<Vec3> path = {start + Vec3(0, -bodyL * 0.5f, 0), start + Vec3(0, -m_reach, -0.01f),
                            start + Vec3(0, -m_reach - 0.012f, -0.03f), start + Vec3(0, -m_reach - 0.014f, -0.045f)};
  buildOutlet(path, m_tubeR);
  if (m_handle == "single_top_lever") {
    buildLever(start + Vec3(0, -0.5f * bodyL, m_bodyR * 0.9f), Vec3::UnitZ(), Vec3(0, 0.3f, 1.0f), m_rng.uniformf(0.04, 0.08));
  } else {
    for (float sx : {-1.0f, 1.0f}) {
      const Vec3 p = start + Vec3(sx * 0.4f * plateW, 0, 0);
      // Twin handles on the wall: build upright then their axis is the wall normal.
      const Affine frame = alignZTo(p, Vec3(0, -1, 0));
      const std::size_t t0 = m_b.triangleCount();
      if (m_handle == "twin_knob") {
        KnobShape k = randomKnob(m_rng, 1.0f);
        k.radius = m_rng.uniformf(0.015, 0.024);
        k.depth = m_rng.uniformf(0.02, 0.035);
        const Vec3 c = buildKnob(m_b, frame, k, m_handleMat, m_metal);
        gt("togglebutton", c, Vec3(0, -1, 0), t0);
      } else if (m_handle == "twin_cross") {
        m_b.cylinder(frame, 0.011f, 0, 0.03f, m_sides, m_handleMat);
        for (int i = 0; i < 4; ++i) {
          const float ang = i * kPi / 2 + kPi / 4;
          const Vec3 d = frame.linear() * Vec3(std::cos(ang), std::sin(ang), 0);
          const Vec3 c = frame * Vec3(0, 0, 0.022f);
          m_b.tube({c, c + d * 0.035f}, 0.005f, 8, m_handleMat);
        }
        gt("togglebutton", frame * Vec3(0, 0, 0.022f), Vec3(0, -1, 0), t0);
      } else {
        m_b.cylinder(frame, 0.012f, 0, 0.02f, m_sides, m_handleMat);
        const Vec3 a = frame * Vec3(0, 0, 0.02f);
        const Vec3 b = a + Vec3(sx * 0.02f, 0, 0.045f);
        m_b.tube({a, b}, 0.006f, 8, m_handleMat);
        gt("togglebutton", 0.5f * (a + b), Vec3(0, -1, 0), t0);
      }
    }
  }
}

void SinkBuilder::buildDistractors() {
  if (m_kind == "bare_faucet" || m_kind == "wall_basin") return;
  const float side = m_rng.chance(0.5) ? 1.0f : -1.0f;
  const float x = m_faucetX + side * m_rng.uniformf(0.16, 0.3);
  if (std::abs(x) > m_counterHalfW - 0.03f) return;
  const Vec3 p(x, m_faucetY, m_deckZ);
  if (m_rng.chance(0.3)) {
    // Soap dispenser: a short pump with a bent nozzle.
    m_b.cylinder(translation(p), 0.018f, 0, 0.006f, 16, m_metal);
    m_b.cylinder(translation(p), 0.01f, 0, 0.05f, 12, m_metal);
    m_b.tube({p + Vec3(0, 0, 0.05f), p + Vec3(0, 0, 0.062f), p + Vec3(0, -0.03f, 0.062f), p + Vec3(0, -0.035f, 0.055f)}, 0.004f, 8,
             m_metal);
    m_distractors.push_back("soap_dispenser");
  } else if (m_rng.chance(0.25) && m_kind != "vanity") {
    // Side sprayer resting in its base.
    m_b.cylinder(translation(p), 0.02f, 0, 0.015f, 16, m_metal);
    m_b.lathe(translation(p + Vec3(0, 0, 0.015f)), {{0, 0}, {0.017f, 0}, {0.015f, 0.05f}, {0.012f, 0.06f}, {0, 0.06f}}, 16, m_handleMat);
    m_distractors.push_back("side_sprayer");
  }
}

GeneratedObject SinkBuilder::run() {
  choose();
  m_reach = m_faucet == "compact" ? m_rng.uniformf(0.05, 0.11)
            : m_faucet == "square_mixer" ? m_rng.uniformf(0.04, 0.1)
            : m_faucet == "wall_mounted" ? m_rng.uniformf(0.12, 0.26)
                                         : m_rng.uniformf(0.1, 0.26);
  m_spoutHeight = m_faucet == "compact" ? m_rng.uniformf(0.08, 0.14)
                  : m_faucet == "straight" ? m_rng.uniformf(0.1, 0.25)
                                           : m_rng.uniformf(0.2, 0.45);
  if (m_kind == "bare_faucet") {
    m_deckZ = 0;
    m_faucetX = 0;
    m_faucetY = 0;
    if (m_wall) m_wallY = 0.0f;
    else if (m_rng.chance(0.35)) {
      // A small deck plate under a bare faucet.
      const float w = m_rng.uniformf(0.08, 0.25), d = m_rng.uniformf(0.06, 0.1);
      const int deckMat = m_rng.chance(0.5) ? m_metal : m_counterMat;
      m_b.box(translation(0, 0, 0.005f), Vec3(w, d, 0.01f), deckMat, 0.002f, 1);
      m_deckZ = 0.01f;
      m_distractors.push_back("deck_plate");
    }
  } else if (m_kind == "bare_basin" || m_kind == "wall_basin") {
    buildVesselBasin();
    if (m_wall && m_kind == "bare_basin" && m_wallY == 0) m_wall = false, m_faucet = "straight";
  } else {
    buildCounterAndBasins();
  }
  if (m_wall) {
    const float z = m_deckZ + m_rng.uniformf(0.12, 0.3);
    buildWallFaucet(Vec3(m_faucetX, m_faucetY, z));
    m_spoutHeight = z - m_deckZ;
  } else {
    buildFaucet(Vec3(m_faucetX, m_faucetY, m_deckZ));
  }
  buildDistractors();

  int handles = 0;
  for (const auto& p : m_points) handles += p.type == "togglebutton";
  m_params["kind"] = m_kind;
  m_params["basins"] = (m_kind == "bare_faucet") ? 0 : m_basins;
  m_params["basin_shape"] = m_kind == "bare_faucet" ? "none" : m_shape;
  m_params["faucet"] = m_faucet;
  m_params["handle"] = m_handle;
  m_params["handles"] = handles;
  m_params["reach_m"] = roundedToMillimetre(m_reach);
  m_params["spout_height_m"] = roundedToMillimetre(m_spoutHeight);
  m_params["finish"] = m_finish;
  std::sort(m_distractors.begin(), m_distractors.end());
  m_params["distractors"] = m_distractors;

  return makeGeneratedObject("sink", std::move(m_b).build(), std::move(m_points), m_params);
}

}  // namespace

const std::vector<std::string>& sinkKinds() {
  static const std::vector<std::string> v = {"bare_faucet", "counter_sink", "vanity",
                                             "bare_basin", "farmhouse", "wall_basin"};
  return v;
}
const std::vector<std::string>& sinkBasinShapes() {
  static const std::vector<std::string> v = {"rectangular", "round"};
  return v;
}
const std::vector<std::string>& faucetTypes() {
  static const std::vector<std::string> v = {"gooseneck", "straight", "pull_down", "wall_mounted",
                                             "bridge", "compact", "arm_metaworld", "square_mixer"};
  return v;
}
const std::vector<std::string>& faucetHandleTypes() {
  static const std::vector<std::string> v = {"single_top_lever", "side_lever", "joystick",
                                             "twin_cross", "twin_knob", "twin_lever", "arm"};
  return v;
}

GeneratedObject generateSink(Rng& rng) { return SinkBuilder(rng).run(); }

}  // namespace sagrid::gen
