#include "core/generate/wall_fixtures.h"

#include <algorithm>

#include "core/generate/angles.h"
#include "core/generate/parts.h"
#include "core/generate/shape_builder.h"

namespace sagrid::gen {

namespace {

// The object's extent the fixtures are placed against.
struct Wall {
  float left = 0, right = 0;  // x extent of the object
  float backY = 0, frontY = 0;
  float floorZ = 0, topZ = 0;  // lowest and highest point of the object
  float width() const { return right - left; }
  float centerX() const { return 0.5f * (left + right); }
};

class FixtureBuilder {
 public:
  FixtureBuilder(Rng& rng, const Wall& wall, int basins)
      : m_rng(rng), m_wall(wall), m_basins(basins) {}

  Mesh build(std::vector<std::string>& names) {
    const bool shelf = m_rng.chance(0.4);
    // The mirror starts above the faucet's top; a shelf needs room under it.
    const float bottom =
        m_wall.topZ + (shelf ? m_rng.uniformf(0.08, 0.3) : m_rng.uniformf(0.03, 0.3));
    const float height = m_rng.uniformf(0.4, 1.0);
    const float width = std::max(0.3f, m_wall.width() * m_rng.uniformf(0.5, 1.05));
    const bool cabinet = m_rng.chance(0.2);
    const float depth = cabinet ? m_rng.uniformf(0.1, 0.16) : m_rng.uniformf(0.006, 0.02);
    const bool pair = m_basins == 2 && !cabinet && m_rng.chance(0.4);
    const int frameMat = m_b.material(
        "fixture_frame",
        finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                               "wood", "matte_black", "white_enamel", "chrome", "dark_grey"}))
            .color);
    const bool framed = !cabinet && m_rng.chance(0.5);
    if (pair) {
      const float each = 0.5f * width * m_rng.uniformf(0.7, 0.95);
      for (float side : {-0.25f, 0.25f})
        mirror(m_wall.centerX() + side * width, each, bottom, height, depth, false, framed,
               frameMat);
      names.push_back("mirror_pair");
    } else {
      mirror(m_wall.centerX(), width, bottom, height, depth, cabinet, framed, frameMat);
      names.push_back(cabinet ? "mirror_cabinet" : framed ? "framed_mirror" : "mirror");
    }
    const float front = m_wall.backY - depth;
    if (m_rng.chance(0.55)) names.push_back(light(width, bottom + height, front));
    if (shelf) {
      this->shelf(width, bottom, front);
      names.push_back("shelf");
    }
    if (m_rng.chance(0.35)) {
      backPanel(bottom + height);
      names.push_back("back_panel");
    }
    if (m_rng.chance(0.3)) {
      towelBar();
      names.push_back("towel_bar");
    }
    return std::move(m_b).build();
  }

 private:
  void mirror(float cx, float width, float bottom, float height, float depth, bool cabinet,
              bool framed, int frameMat) {
    const int glass = m_b.material("mirror", jitter(m_rng, {0.66f, 0.7f, 0.74f}, 0.12f));
    const float x0 = cx - 0.5f * width, x1 = cx + 0.5f * width, y1 = m_wall.backY;
    if (cabinet) {
      // A mirror cabinet: the box, its mirrored door a few millimetres proud.
      m_b.boxFromTo(Vec3(x0, y1 - depth, bottom), Vec3(x1, y1, bottom + height), frameMat);
      m_b.boxFromTo(Vec3(x0 + 0.01f, y1 - depth - 0.004f, bottom + 0.01f),
                    Vec3(x1 - 0.01f, y1 - depth, bottom + height - 0.01f), glass);
      return;
    }
    m_b.boxFromTo(Vec3(x0, y1 - depth, bottom), Vec3(x1, y1, bottom + height), glass);
    if (!framed) return;
    const float band = m_rng.uniformf(0.015, 0.06);
    const float proud = depth + m_rng.uniformf(0.005, 0.025);
    const float y0 = y1 - proud;
    m_b.boxFromTo(Vec3(x0 - band, y0, bottom - band), Vec3(x1 + band, y1, bottom), frameMat);
    m_b.boxFromTo(Vec3(x0 - band, y0, bottom + height), Vec3(x1 + band, y1, bottom + height + band),
                  frameMat);
    m_b.boxFromTo(Vec3(x0 - band, y0, bottom), Vec3(x0, y1, bottom + height), frameMat);
    m_b.boxFromTo(Vec3(x1, y0, bottom), Vec3(x1 + band, y1, bottom + height), frameMat);
  }

  // A light bar along the mirror's top, or one to three wall lamps whose arms reach forward like
  // spouts.
  std::string light(float mirrorWidth, float mirrorTop, float mirrorFront) {
    const int metal = m_b.material(
        "lamp_metal", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                             "chrome", "brushed_nickel", "matte_black", "brass"}))
                          .color);
    const int shade = m_b.material("lamp_shade", jitter(m_rng, {0.93f, 0.92f, 0.88f}, 0.05f));
    const float y1 = m_wall.backY;
    if (m_rng.chance(0.5)) {
      const float w = mirrorWidth * m_rng.uniformf(0.3, 1.0), d = m_rng.uniformf(0.05, 0.14),
                  h = m_rng.uniformf(0.02, 0.06);
      const float z0 = m_rng.chance(0.5) ? mirrorTop + m_rng.uniformf(0.0, 0.04)
                                         : mirrorTop - h - m_rng.uniformf(0.01, 0.05);
      const float back = z0 > mirrorTop ? y1 : mirrorFront;
      m_b.box(translation(m_wall.centerX(), back - 0.5f * d, z0 + 0.5f * h), Vec3(w, d, h),
              m_rng.chance(0.5) ? metal : shade, 0.3f * h, 2);
      return "light_bar";
    }
    const int lamps = m_rng.uniformInt(1, 3);
    const float spread = mirrorWidth * m_rng.uniformf(0.25, 0.45);
    const float reach = m_rng.uniformf(0.08, 0.22), rise = m_rng.uniformf(-0.03, 0.06);
    const float z = mirrorTop + m_rng.uniformf(-0.06, 0.08);
    const float radius = m_rng.uniformf(0.03, 0.07), length = m_rng.uniformf(0.05, 0.1);
    for (int i = 0; i < lamps; ++i) {
      const float x = lamps == 1 ? m_wall.centerX()
                                 : m_wall.centerX() + spread * (2.0f * i / (lamps - 1) - 1.0f);
      const Vec3 a(x, y1, z), b(x, y1 - reach, z + rise);
      m_b.cylinder(alignZTo(a, Vec3(0, -1, 0)), 0.03f, 0, 0.01f, 16, metal);
      m_b.tube({a, b}, m_rng.uniformf(0.005, 0.01), 10, metal);
      // The shade opens downwards around the bulb.
      m_b.lathe(translation(b - Vec3(0, 0, length)),
                {{radius, 0}, {0.45f * radius, length}, {0, length}}, 20, shade);
    }
    return "wall_lamps";
  }

  void shelf(float mirrorWidth, float mirrorBottom, float mirrorFront) {
    const int mat = m_b.material(
        "shelf", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{"ceramic_white", "wood",
                                                                        "chrome", "stainless"}))
                     .color);
    const float w = mirrorWidth * m_rng.uniformf(0.6, 1.0), d = m_rng.uniformf(0.08, 0.15),
                thick = m_rng.uniformf(0.008, 0.025);
    const float top =
        std::max(m_wall.topZ + thick + 0.005f, mirrorBottom - m_rng.uniformf(0.0, 0.02));
    const float y1 = m_wall.backY;
    m_b.boxFromTo(Vec3(m_wall.centerX() - 0.5f * w, y1 - d, top - thick),
                  Vec3(m_wall.centerX() + 0.5f * w, y1, top), mat);
    const int bottles = m_rng.uniformInt(0, 3);
    for (int i = 0; i < bottles; ++i) {
      const int colour =
          m_b.material("bottle_" + std::to_string(i),
                       finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                              "blue", "red", "ceramic_white", "cream", "chrome"}))
                           .color);
      const float r = m_rng.uniformf(0.015, 0.035), h = m_rng.uniformf(0.06, 0.18);
      const float x = m_wall.centerX() + m_rng.uniformf(-0.45, 0.45) * w;
      const float y = std::min(y1 - d + r + 0.005f, mirrorFront - r - 0.002f);
      const Vec3 base(x, std::max(y, y1 - d + r), top);
      m_b.cylinder(translation(base), r, 0, h, 16, colour);
      if (m_rng.chance(0.4)) {
        // A pump with a nozzle pointing forward: a soap dispenser.
        const Vec3 p = base + Vec3(0, 0, h);
        m_b.tube(
            {p, p + Vec3(0, 0, 0.03f), p + Vec3(0, -0.03f, 0.03f), p + Vec3(0, -0.035f, 0.022f)},
            0.004f, 8, colour);
      }
    }
  }

  void backPanel(float mirrorTop) {
    const int tiles = m_b.material(
        "wall_tiles", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                             "ceramic_white", "cream", "pastel_blue", "dark_grey"}))
                          .color);
    const float w = m_wall.width() * m_rng.uniformf(1.0, 1.3);
    const float z0 = m_wall.floorZ + (m_wall.topZ - m_wall.floorZ) * m_rng.uniformf(0.5, 0.85);
    const float z1 = mirrorTop + m_rng.uniformf(0.05, 0.3);
    m_b.boxFromTo(Vec3(m_wall.centerX() - 0.5f * w, m_wall.backY, z0),
                  Vec3(m_wall.centerX() + 0.5f * w, m_wall.backY + 0.012f, z1), tiles,
                  m_rng.pick(std::vector<int>{1, 4}));
  }

  // A bar on two stand-offs, in front of a cabinet or beside a basin.
  void towelBar() {
    const int metal = m_b.material(
        "towel_bar", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                            "chrome", "brushed_nickel", "matte_black"}))
                         .color);
    const float r = m_rng.uniformf(0.007, 0.014), standoff = m_rng.uniformf(0.04, 0.07);
    const float height = m_wall.topZ - m_wall.floorZ;
    Vec3 a, b, out;
    if (height > 0.6f) {
      const float half = std::min(0.45f * m_wall.width(), m_rng.uniformf(0.15, 0.35));
      const float z = m_wall.floorZ + height * m_rng.uniformf(0.25, 0.6);
      out = Vec3(0, -standoff, 0);
      a = Vec3(m_wall.centerX() - half, m_wall.frontY, z);
      b = Vec3(m_wall.centerX() + half, m_wall.frontY, z);
    } else {
      const float side = m_rng.chance(0.5) ? 1.0f : -1.0f;
      const float x = side > 0 ? m_wall.right : m_wall.left;
      const float half = m_rng.uniformf(0.1, 0.2);
      const float yc = 0.5f * (m_wall.backY + m_wall.frontY);
      const float z = m_wall.floorZ + height * m_rng.uniformf(0.2, 0.8);
      out = Vec3(side * standoff, 0, 0);
      a = Vec3(x, yc - half, z);
      b = Vec3(x, yc + half, z);
    }
    m_b.tube({a, a + out}, 0.6f * r, 8, metal);
    m_b.tube({b, b + out}, 0.6f * r, 8, metal);
    m_b.tube({a + out, b + out}, r, 12, metal);
  }

  Rng& m_rng;
  Wall m_wall;
  int m_basins = 1;
  ShapeBuilder m_b;
};

}  // namespace

bool acceptsWallFixtures(const GeneratedObject& object) {
  return object.category == "sink" &&
         object.generator.value("kind", std::string()) != "bare_faucet";
}

std::vector<std::string> addWallFixtures(GeneratedObject& object, Rng& rng) {
  const Eigen::AlignedBox3f box = object.mesh.bounds();
  if (box.isEmpty()) return {};
  Wall wall;
  wall.left = box.min().x();
  wall.right = box.max().x();
  wall.frontY = box.min().y();
  wall.backY = box.max().y();
  wall.floorZ = box.min().z();
  wall.topZ = box.max().z();
  std::vector<std::string> names;
  FixtureBuilder builder(rng, wall, object.generator.value("basins", 1));
  object.mesh.append(builder.build(names));
  std::sort(names.begin(), names.end());
  object.generator["wall_fixtures"] = names;
  return names;
}

}  // namespace sagrid::gen
