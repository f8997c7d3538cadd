#include "core/generate/stove_generator.h"

#include <algorithm>
#include <cmath>

#include "core/generate/angles.h"
#include "core/generate/parts.h"
#include "core/generate/printed_controls.h"
#include "core/generate/shape_builder.h"
#include "core/generate/texture_painter.h"

namespace sagrid::gen {

namespace {

struct Burner {
  Vec2 center;
  float radius;
};

struct Rect2 {
  float x0, x1, y0, y1;
  float width() const { return x1 - x0; }
  float depth() const { return y1 - y0; }
  Vec2 at(float u, float v) const { return {x0 + u * width(), y0 + v * depth()}; }
};

int burnerCountOf(const std::string& layout) {
  if (layout == "single") return 1;
  if (layout == "row2" || layout == "column2") return 2;
  if (layout == "row3" || layout == "triangle3") return 3;
  if (layout == "grid2x2" || layout == "offgrid4") return 4;
  if (layout == "four_plus_centre") return 5;
  return 6;  // grid2x3
}

// Places burners in the cooking region; radii fill a share of each cell.
std::vector<Burner> layoutBurners(Rng& rng, const std::string& layout, const Rect2& region) {
  std::vector<Burner> burners;
  const float fill = rng.uniformf(0.62, 0.86);
  const bool varied = rng.chance(0.6);  // real cooktops mix small and large burners
  auto add = [&](float u, float v, float cellW, float cellD) {
    float r = 0.5f * std::min(cellW * region.width(), cellD * region.depth()) * fill;
    if (varied) r *= rng.uniformf(0.78, 1.0);
    burners.push_back({region.at(u, v), r});
  };
  if (layout == "single") {
    add(0.5f, 0.5f, 1, 1);
  } else if (layout == "row2") {
    add(0.25f, 0.5f, 0.5f, 1);
    add(0.75f, 0.5f, 0.5f, 1);
  } else if (layout == "column2") {
    add(0.5f, 0.25f, 1, 0.5f);
    add(0.5f, 0.75f, 1, 0.5f);
  } else if (layout == "row3") {
    for (int i = 0; i < 3; ++i) add((i + 0.5f) / 3, 0.5f, 1.0f / 3, 1);
  } else if (layout == "triangle3") {
    const bool backSingle = rng.chance(0.5);
    add(0.25f, backSingle ? 0.27f : 0.73f, 0.5f, 0.54f);
    add(0.75f, backSingle ? 0.27f : 0.73f, 0.5f, 0.54f);
    add(0.5f, backSingle ? 0.75f : 0.25f, 0.5f, 0.5f);
  } else if (layout == "grid2x2") {
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) add(0.25f + 0.5f * i, 0.25f + 0.5f * j, 0.5f, 0.5f);
  } else if (layout == "offgrid4") {
    // Staggered rows and unequal sizes, as on many gas hobs.
    const float shift = rng.uniformf(-0.08, 0.08);
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const float u = 0.26f + 0.48f * i + (j == 1 ? shift : -shift);
        const float v = 0.26f + 0.48f * j + rng.uniformf(-0.04, 0.04);
        add(u, v, rng.uniformf(0.36, 0.5), rng.uniformf(0.36, 0.5));
      }
    }
  } else if (layout == "four_plus_centre") {
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) add(0.16f + 0.68f * i, 0.25f + 0.5f * j, 0.3f, 0.5f);
    add(0.5f, 0.5f, 0.36f, rng.uniformf(0.6, 0.9));
  } else {  // grid2x3
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) add((i + 0.5f) / 3, 0.25f + 0.5f * j, 1.0f / 3, 0.5f);
  }
  return burners;
}

struct Palette {
  int body, top, burner, burnerDark, trim, knob, knobAccent, glass, handle, foot;
  std::string finishName;
};

class StoveBuilder {
 public:
  StoveBuilder(Rng& rng, const StoveOptions& options) : m_rng(rng), m_options(options) {}
  GeneratedObject run();

 private:
  void choose();
  void buildBody();
  void buildHotPlateOrCooktopBody(float height);
  void buildRangeBody();
  void buildCounterBlock();
  void buildGlassSlab();
  void splitPrintedControlArea();
  void buildBurners();
  void buildCoil(const Burner& burner);
  void buildGas(const Burner& burner, bool ownGrate);
  void buildRaisedPlate(const Burner& burner);
  void buildGlassTop();
  void buildControls();
  void addKnob(const Affine& frame, float maxRadius, float maxDepth);
  void addTouchButton(const Affine& frame, float radius);
  int mat(const std::string& name, const Vec3& color) { return m_b.material(name, color); }
  void gt(const std::string& type, const Vec3& p, const Vec3& n, std::size_t t0) {
    m_points.push_back({type, p, n, t0, m_b.triangleCount()});
  }

  Rng& m_rng;
  StoveOptions m_options;
  ShapeBuilder m_b;
  std::vector<GroundTruthPoint> m_points;
  nlohmann::json m_params = nlohmann::json::object();
  std::vector<std::string> m_extras;

  std::string m_kind, m_layout, m_look, m_controls;
  float m_width = 0.6f, m_depth = 0.5f, m_topZ = 0.05f;
  Rect2 m_top{};     // the whole top surface
  Rect2 m_region{};  // where burners go
  Rect2 m_strip{};   // where top-mounted controls go
  bool m_stripOnSide = false;
  std::vector<Burner> m_burners;
  int m_knobCount = 0;
  Palette m_pal{};
  KnobShape m_knobShape;
  // Front face used by front-panel controls: y plane, z and x extent.
  float m_frontY = 0, m_frontZ0 = 0, m_frontZ1 = 0;
  // Back panel (ranges with a backguard): front face plane and extent.
  bool m_hasBackPanel = false;
  float m_backY = 0, m_backZ0 = 0, m_backZ1 = 0, m_backTilt = 0;
};

void StoveBuilder::choose() {
  static const std::vector<std::string> kinds = stoveKinds();
  m_kind = kinds[m_rng.weighted({0.26, 0.24, 0.14, 0.2, 0.16})];
  if (m_options.glassSlab) m_kind = "glass_slab";

  // Layouts allowed by kind, then a width that fits the burner count.
  std::vector<std::string> layouts;
  std::vector<double> weights;
  if (m_kind == "hot_plate") {
    layouts = {"single", "row2", "column2"};
    weights = {0.55, 0.3, 0.15};
  } else if (m_kind == "cooktop" || m_kind == "hob_in_counter" || m_kind == "glass_slab") {
    layouts = {"single", "row2", "column2", "row3", "triangle3", "grid2x2", "offgrid4",
               "four_plus_centre", "grid2x3"};
    weights = {0.06, 0.08, 0.1, 0.08, 0.1, 0.22, 0.14, 0.12, 0.1};
  } else {
    layouts = {"triangle3", "grid2x2", "offgrid4", "four_plus_centre", "grid2x3", "row3"};
    weights = {0.08, 0.34, 0.2, 0.18, 0.14, 0.06};
  }
  m_layout = layouts[m_rng.weighted(weights)];
  const int n = burnerCountOf(m_layout);

  if (m_kind == "hot_plate") {
    m_width = n == 1 ? m_rng.uniformf(0.24, 0.4) : m_rng.uniformf(0.4, 0.62);
    m_depth = m_rng.uniformf(0.18, 0.36);
    if (m_layout == "column2") std::swap(m_width, m_depth), m_depth = std::max(m_depth, 0.4f);
  } else if (m_kind == "range_freestanding" || m_kind == "range_slide_in") {
    const float minW = n >= 5 ? 0.75f : 0.5f;
    m_width = m_rng.uniformf(minW, n >= 5 ? 1.2 : 0.92);
    m_depth = m_rng.uniformf(0.56, 0.7);
  } else {
    const float perBurner = (m_layout == "column2" || m_layout == "single") ? 0.3f
                            : (n <= 4)                                       ? 0.5f
                                                                              : 0.72f;
    m_width = m_rng.uniformf(perBurner, perBurner + 0.25f);
    m_depth = m_rng.uniformf(0.4, 0.56);
    if (m_layout == "single") m_depth = m_rng.uniformf(0.35, 0.5);
  }

  // Burner look: glass zones need a glass top; coil and gas suit enamel or steel.
  m_look = stoveBurnerLooks()[m_rng.weighted({0.24, 0.3, 0.22, 0.24})];
  if (m_kind == "glass_slab") m_look = "glass_zone";

  // Control placement allowed by kind.
  std::vector<std::string> places;
  if (m_kind == "hot_plate") {
    places = {"top_beside", "front_panel", "side", "touch", "top_front_strip"};
    weights = {0.4, 0.28, 0.1, 0.1, 0.12};
  } else if (m_kind == "cooktop") {
    places = {"top_front_strip", "top_beside", "front_panel", "touch"};
    weights = {0.3, 0.2, 0.25, 0.25};
  } else if (m_kind == "hob_in_counter") {
    places = {"front_panel", "top_front_strip", "touch", "top_beside"};
    weights = {0.3, 0.25, 0.3, 0.15};
  } else if (m_kind == "glass_slab") {
    places = {"printed"};
    weights = {1.0};
  } else if (m_kind == "range_freestanding") {
    places = {"front_panel", "back_panel", "top_front_strip", "touch"};
    weights = {0.4, 0.42, 0.1, 0.08};
  } else {
    places = {"front_panel", "top_front_strip", "touch"};
    weights = {0.6, 0.25, 0.15};
  }
  m_controls = places[m_rng.weighted(weights)];
  if (m_controls == "side" && n > 2) m_controls = "top_beside";

  int extra = 0;
  if (m_kind == "range_freestanding" || m_kind == "range_slide_in") {
    extra = m_rng.weighted({0.3, 0.35, 0.25, 0.1});
  } else if (m_kind == "hob_in_counter") {
    extra = m_rng.weighted({0.6, 0.3, 0.1});
  } else {
    extra = m_rng.weighted({0.82, 0.18});
  }
  if (m_controls == "side") extra = 0;
  m_knobCount = n + extra;
  if (m_controls == "printed") {
    // Touch panels: one symbol per zone up to a +/- pair per zone, a power and a lock symbol.
    m_knobCount =
        std::clamp(m_rng.pick(std::vector<int>{n, n + 1, 2 * n, 2 * n + 1, 2 * n + 2}), 2, 14);
  }
  m_knobShape = randomKnob(m_rng, m_kind == "hot_plate" ? m_rng.uniformf(0.9, 1.6) : 1.0f);

  // Finishes.
  std::string finish;
  if (m_look == "glass_zone") finish = "black_glass";
  else finish = m_rng.pick(std::vector<std::string>{"stainless", "stainless", "white_enamel",
                                                     "black_glass", "cast_iron", "dark_grey",
                                                     "cream", "retro_red", "matte_black"});
  m_pal.finishName = finish;
  const Finish body = finishNamed(m_rng, finish);
  m_pal.body = mat("body_" + finish, body.color);
  m_pal.top = m_rng.chance(0.6) ? m_pal.body
                                : mat("top", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                                              "black_glass", "stainless",
                                                              "cast_iron", "matte_black"}))
                                                 .color);
  m_pal.burner = mat("burner", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                                      "cast_iron", "matte_black", "dark_grey"}))
                                   .color);
  m_pal.burnerDark = mat("burner_dark", jitter(m_rng, {0.05f, 0.05f, 0.05f}, 0.03f));
  m_pal.trim = mat("trim", finishNamed(m_rng, "chrome").color);
  const std::string knobFinish = m_rng.pick(std::vector<std::string>{
      "matte_black", "chrome", "stainless", "ceramic_white", "matte_black", "red", "brass"});
  m_pal.knob = mat("knob_" + knobFinish, finishNamed(m_rng, knobFinish).color);
  m_pal.knobAccent = mat("knob_mark", m_rng.chance(0.5) ? Vec3(0.9f, 0.9f, 0.9f) : Vec3(0.7f, 0.1f, 0.1f));
  m_pal.glass = mat("oven_glass", jitter(m_rng, {0.08f, 0.09f, 0.1f}, 0.04f));
  m_pal.handle = mat("handle", finishNamed(m_rng, m_rng.pick(std::vector<std::string>{
                                                      "chrome", "stainless", "matte_black", "brass"}))
                                   .color);
  m_pal.foot = mat("foot", jitter(m_rng, {0.1f, 0.1f, 0.1f}, 0.05f));
  if (m_kind == "glass_slab") m_pal.top = m_pal.body;
}

void StoveBuilder::buildHotPlateOrCooktopBody(float height) {
  const float bevel = m_rng.chance(0.6) ? m_rng.uniformf(0.002, 0.012) : 0.0f;
  const float feet = (m_kind == "hot_plate" && m_rng.chance(0.5)) ? m_rng.uniformf(0.005, 0.015) : 0.0f;
  const int subdiv = m_rng.pick(std::vector<int>{1, 1, 2, 4, 8});
  m_b.box(translation(0, 0, feet + 0.5f * height), Vec3(m_width, m_depth, height), m_pal.body,
          std::min(bevel, 0.45f * height), 2, subdiv);
  if (feet > 0) {
    m_extras.push_back("feet");
    for (int i = 0; i < 4; ++i) {
      const float x = (i % 2 ? 1 : -1) * (0.5f * m_width - 0.03f);
      const float y = (i / 2 ? 1 : -1) * (0.5f * m_depth - 0.03f);
      m_b.cylinder(translation(x, y, 0), 0.012f, 0, feet + 0.002f, 12, m_pal.foot);
    }
  }
  m_topZ = feet + height;
  m_frontY = -0.5f * m_depth;
  m_frontZ0 = feet;
  m_frontZ1 = feet + height;
  if (m_kind == "cooktop" && m_controls == "front_panel" && height < 0.06f) {
    // Drop-in cooktops with front controls hang a fascia below the front edge.
    const float fascia = m_rng.uniformf(0.06, 0.09);
    m_b.box(translation(0, -0.5f * m_depth + 0.02f, m_topZ - 0.5f * fascia),
            Vec3(m_width - 0.01f, 0.04f, fascia), m_pal.body);
    m_frontY = -0.5f * m_depth;
    m_frontZ0 = m_topZ - fascia;
    m_frontZ1 = m_topZ;
    m_extras.push_back("front_fascia");
  }
}

void StoveBuilder::buildRangeBody() {
  const float height = m_rng.uniformf(0.86, 0.94);
  const float plinth = m_rng.uniformf(0.0, 0.08);
  const bool feet = plinth > 0.03f && m_rng.chance(0.5);
  const float topThick = m_rng.uniformf(0.02, 0.04);
  const float bodyH = height - plinth - topThick;
  // Main carcass, with a recessed kick plate or feet below.
  m_b.box(translation(0, 0, plinth + 0.5f * bodyH), Vec3(m_width, m_depth, bodyH), m_pal.body,
          m_rng.chance(0.3) ? 0.004f : 0.0f, 2, m_rng.pick(std::vector<int>{1, 1, 3}));
  if (plinth > 0) {
    if (feet) {
      m_extras.push_back("feet");
      for (int i = 0; i < 4; ++i) {
        const float x = (i % 2 ? 1 : -1) * (0.5f * m_width - 0.04f);
        const float y = (i / 2 ? 1 : -1) * (0.5f * m_depth - 0.05f);
        m_b.cylinder(translation(x, y, 0), 0.018f, 0, plinth + 0.002f, 12, m_pal.foot);
      }
    } else {
      m_b.box(translation(0, 0.02f, 0.5f * plinth + 0.001f), Vec3(m_width - 0.02f, m_depth - 0.06f, plinth + 0.002f),
              m_pal.foot);
    }
  }
  // Cooktop slab, slightly overhanging at the front for slide-ins.
  const float overhang = m_kind == "range_slide_in" ? m_rng.uniformf(0.01, 0.03) : 0.0f;
  m_b.box(translation(0, -0.5f * overhang, height - 0.5f * topThick),
          Vec3(m_width + 2 * overhang, m_depth + overhang, topThick), m_pal.top,
          m_rng.chance(0.5) ? 0.004f : 0.0f, 2, m_rng.pick(std::vector<int>{1, 2, 6}));
  m_topZ = height;
  m_top = {-0.5f * m_width, 0.5f * m_width, -0.5f * m_depth - overhang, 0.5f * m_depth};

  // Front: control fascia at the top, oven door with window and handle, drawer below.
  const float fy = -0.5f * m_depth;
  const float fasciaH = m_controls == "front_panel" ? m_rng.uniformf(0.08, 0.13) : m_rng.uniformf(0.0, 0.06);
  const float doorTop = height - topThick - fasciaH - 0.01f;
  const float drawerH = m_rng.chance(0.6) ? m_rng.uniformf(0.1, 0.17) : 0.0f;
  const float doorBottom = plinth + drawerH + 0.015f;
  const float doorT = m_rng.uniformf(0.015, 0.035);
  const bool twoOvens = m_width > 0.85f && m_rng.chance(0.5);
  auto door = [&](float x0, float x1) {
    const float w = x1 - x0, h = doorTop - doorBottom;
    m_b.box(translation(0.5f * (x0 + x1), fy - 0.5f * doorT, doorBottom + 0.5f * h),
            Vec3(w, doorT, h), m_pal.body, m_rng.chance(0.5) ? 0.004f : 0.0f, 2);
    if (m_rng.chance(0.8)) {
      const float ww = w * m_rng.uniformf(0.55, 0.8), wh = h * m_rng.uniformf(0.35, 0.55);
      m_b.box(translation(0.5f * (x0 + x1), fy - doorT - 0.001f, doorBottom + 0.45f * h),
              Vec3(ww, 0.004f, wh), m_pal.glass, 0.003f, 1);
      m_extras.push_back("oven_window");
    }
    Affine hf = translation(0.5f * (x0 + x1), fy - doorT, doorTop - 0.05f) * rotationX(kPi / 2);
    buildBarHandle(m_b, hf, w * m_rng.uniformf(0.6, 0.9), m_rng.uniformf(0.03, 0.06),
                   m_rng.uniformf(0.007, 0.013), m_pal.handle);
  };
  if (twoOvens) {
    const float split = m_rng.uniformf(-0.15, 0.15) * m_width;
    door(-0.5f * m_width + 0.01f, split - 0.005f);
    door(split + 0.005f, 0.5f * m_width - 0.01f);
    m_extras.push_back("double_oven");
  } else {
    door(-0.5f * m_width + 0.01f, 0.5f * m_width - 0.01f);
  }
  if (drawerH > 0) {
    m_b.box(translation(0, fy - 0.008f, plinth + 0.5f * drawerH + 0.005f),
            Vec3(m_width - 0.02f, 0.016f, drawerH - 0.01f), m_pal.body);
    if (m_rng.chance(0.6)) {
      buildBarHandle(m_b, translation(0, fy - 0.016f, plinth + drawerH * 0.6f) * rotationX(kPi / 2),
                     m_width * 0.4f, 0.025f, 0.007f, m_pal.handle);
    }
    m_extras.push_back("drawer");
  }
  m_frontY = fy;
  m_frontZ0 = doorTop + 0.01f;
  m_frontZ1 = height - topThick;
  if (fasciaH > 0.0f && m_controls != "front_panel" && m_rng.chance(0.5)) {
    // A display on the fascia (distractor).
    m_b.box(translation(m_rng.uniformf(-0.2, 0.2) * m_width, fy - 0.002f, 0.5f * (m_frontZ0 + m_frontZ1)),
            Vec3(0.08f, 0.004f, std::max(0.01f, 0.5f * fasciaH)), m_pal.glass);
    m_extras.push_back("display");
  }

  if (m_kind == "range_freestanding") {
    // Backguard: tall for back-panel controls, a low trim otherwise.
    const bool tall = m_controls == "back_panel" || m_rng.chance(0.4);
    const float bh = tall ? m_rng.uniformf(0.1, 0.24) : m_rng.uniformf(0.03, 0.06);
    const float bt = m_rng.uniformf(0.04, 0.09);
    m_backTilt = tall && m_rng.chance(0.4) ? m_rng.uniformf(0.1, 0.35) : 0.0f;
    const float y = 0.5f * m_depth - 0.5f * bt;
    Affine bf = translation(0, y, height) * rotationX(-m_backTilt);
    m_b.box(bf * translation(0, 0, 0.5f * bh), Vec3(m_width, bt, bh), m_pal.body,
            m_rng.chance(0.5) ? 0.005f : 0.0f, 2);
    m_hasBackPanel = tall;
    m_backY = y - 0.5f * bt;
    m_backZ0 = height;
    m_backZ1 = height + bh;
    m_top.y1 = 0.5f * m_depth - bt;
    if (tall && m_controls != "back_panel" && m_rng.chance(0.5)) {
      m_b.box(bf * translation(0, -0.5f * bt - 0.002f, 0.5f * bh), Vec3(0.1f, 0.004f, 0.3f * bh),
              m_pal.glass);
      m_extras.push_back("display");
    }
  }
}

void StoveBuilder::buildCounterBlock() {
  // A base cabinet with a worktop; the hob sits in the worktop.
  const float cabW = m_width + m_rng.uniformf(0.06, 0.4);
  const float cabD = std::max(m_depth + 0.06f, m_rng.uniformf(0.55, 0.65));
  const float height = m_rng.uniformf(0.84, 0.92);
  const float worktop = m_rng.uniformf(0.025, 0.045);
  const Finish cab = pickFinish(m_rng, {"white_enamel", "wood", "laminate", "dark_grey", "cream", "pastel_blue"});
  const Finish top = pickFinish(m_rng, {"granite", "wood", "laminate", "ceramic_white", "matte_black"});
  const int cabM = mat("cabinet_" + cab.name, cab.color);
  const int topM = mat("worktop_" + top.name, top.color);
  const float plinth = m_rng.uniformf(0.06, 0.12);
  m_b.box(translation(0, 0.03f, 0.5f * plinth), Vec3(cabW - 0.01f, cabD - 0.08f, plinth), m_pal.foot);
  m_b.box(translation(0, 0, plinth + 0.5f * (height - worktop - plinth)),
          Vec3(cabW, cabD - 0.02f, height - worktop - plinth), cabM, 0, 0, m_rng.pick(std::vector<int>{1, 2, 5}));
  const float yCab = -0.5f * (cabD - 0.02f);
  const float fasciaH = m_controls == "front_panel" ? m_rng.uniformf(0.08, 0.12) : 0.0f;
  // Doors or a built-in oven below the hob.
  const float doorTop = height - worktop - fasciaH - 0.01f;
  if (m_rng.chance(0.5)) {
    const int n = cabW > 0.7f ? 2 : 1;
    for (int i = 0; i < n; ++i) {
      const float w = cabW / n - 0.006f;
      const float x = -0.5f * cabW + (i + 0.5f) * cabW / n;
      m_b.box(translation(x, yCab - 0.01f, plinth + 0.5f * (doorTop - plinth)), Vec3(w, 0.02f, doorTop - plinth - 0.006f), cabM);
      const float hx = x + (n == 2 ? (i == 0 ? 0.35f : -0.35f) * w : 0.35f * w);
      buildBarHandle(m_b, translation(hx, yCab - 0.02f, doorTop - 0.15f) * rotationX(kPi / 2) * rotationY(kPi / 2),
                     0.12f, 0.025f, 0.006f, m_pal.handle);
    }
    m_extras.push_back("cabinet_doors");
  } else {
    const float ovenH = std::min(0.6f, doorTop - plinth - 0.05f);
    m_b.box(translation(0, yCab - 0.01f, doorTop - 0.5f * ovenH), Vec3(std::min(cabW, 0.6f), 0.02f, ovenH), m_pal.body);
    m_b.box(translation(0, yCab - 0.021f, doorTop - 0.55f * ovenH), Vec3(std::min(cabW, 0.6f) * 0.7f, 0.004f, ovenH * 0.45f),
            m_pal.glass);
    buildBarHandle(m_b, translation(0, yCab - 0.02f, doorTop - 0.06f) * rotationX(kPi / 2),
                   std::min(cabW, 0.6f) * 0.75f, 0.04f, 0.009f, m_pal.handle);
    m_extras.push_back("builtin_oven");
  }
  m_b.box(translation(0, -0.005f, height - 0.5f * worktop), Vec3(cabW + 0.02f, cabD + 0.01f, worktop), topM,
          m_rng.chance(0.5) ? 0.003f : 0.0f, 2, m_rng.pick(std::vector<int>{1, 3}));
  // The hob itself: a thin slab on the worktop.
  const float hobT = m_rng.uniformf(0.004, 0.012);
  m_b.box(translation(0, 0, height + 0.5f * hobT), Vec3(m_width, m_depth, hobT), m_pal.top,
          m_rng.chance(0.6) ? 0.002f : 0.0f, 1, m_rng.pick(std::vector<int>{1, 4}));
  m_topZ = height + hobT;
  m_frontY = yCab;
  m_frontZ0 = doorTop + 0.01f;
  m_frontZ1 = height - worktop;
  m_params["cabinet_width_m"] = cabW;
}

void StoveBuilder::buildBody() {
  if (m_kind == "hot_plate") {
    const float h = m_rng.uniformf(0.035, 0.1);
    m_top = {-0.5f * m_width, 0.5f * m_width, -0.5f * m_depth, 0.5f * m_depth};
    buildHotPlateOrCooktopBody(h);
  } else if (m_kind == "cooktop") {
    const float h = m_rng.uniformf(0.03, 0.1);
    m_top = {-0.5f * m_width, 0.5f * m_width, -0.5f * m_depth, 0.5f * m_depth};
    buildHotPlateOrCooktopBody(h);
  } else if (m_kind == "hob_in_counter") {
    m_top = {-0.5f * m_width, 0.5f * m_width, -0.5f * m_depth, 0.5f * m_depth};
    buildCounterBlock();
  } else if (m_kind == "glass_slab") {
    buildGlassSlab();
  } else {
    buildRangeBody();
  }

  // Split the top into the burner region and the control strip.
  const float margin = m_rng.uniformf(0.015, 0.04);
  m_region = {m_top.x0 + margin, m_top.x1 - margin, m_top.y0 + margin, m_top.y1 - margin};
  if (m_controls == "printed") {
    splitPrintedControlArea();
  } else if (m_controls == "top_front_strip" || (m_controls == "touch" && m_rng.chance(0.7))) {
    const float strip = std::min(0.3f * m_region.depth(), m_rng.uniformf(0.05, 0.1));
    m_strip = {m_region.x0, m_region.x1, m_region.y0, m_region.y0 + strip};
    m_region.y0 += strip;
  } else if (m_controls == "top_beside" || m_controls == "touch") {
    const float strip = std::min(0.35f * m_region.width(), m_rng.uniformf(0.06, 0.12));
    m_stripOnSide = true;
    if (m_rng.chance(0.7)) {  // right end, as most appliances; LIBERO's stove has it at one end
      m_strip = {m_region.x1 - strip, m_region.x1, m_region.y0, m_region.y1};
      m_region.x1 -= strip;
    } else {
      m_strip = {m_region.x0, m_region.x0 + strip, m_region.y0, m_region.y1};
      m_region.x0 += strip;
    }
  }
  m_burners = layoutBurners(m_rng, m_layout, m_region);
}

void StoveBuilder::buildCoil(const Burner& br) {
  const float z = m_topZ;
  // Chrome drip pan under the coil.
  m_b.lathe(translation(br.center.x(), br.center.y(), z),
            {{0, 0.001f}, {br.radius * 1.12f, 0.001f}, {br.radius * 1.18f, 0.004f}, {br.radius * 1.1f, 0.005f}, {0, 0.002f}},
            32, m_pal.trim);
  const std::size_t t0 = m_b.triangleCount();
  const float tubeR = m_rng.uniformf(0.003, 0.005);
  const float coilZ = z + m_rng.uniformf(0.008, 0.016);
  const float turns = m_rng.uniformf(2.5, 4.5);
  const float r0 = m_rng.uniformf(0.006, 0.012);
  const int perTurn = m_rng.pick(std::vector<int>{20, 28, 36});
  std::vector<Vec3> path;
  const int steps = static_cast<int>(turns * perTurn);
  const float phase = m_rng.uniformf(0, 2 * kPi);
  for (int i = 0; i <= steps; ++i) {
    const float t = float(i) / steps;
    const float a = phase + 2 * kPi * turns * t;
    const float r = r0 + (br.radius - r0) * t;
    path.push_back({br.center.x() + r * std::cos(a), br.center.y() + r * std::sin(a), coilZ});
  }
  // The terminal leg dives into the top at the rim.
  const Vec3 end = path.back();
  path.push_back(end + Vec3(0, 0, -0.6f * (coilZ - z)));
  m_b.tube(path, tubeR, m_rng.pick(std::vector<int>{6, 8, 10}), m_pal.burner);
  gt("heatsource", Vec3(br.center.x(), br.center.y(), coilZ + tubeR), Vec3::UnitZ(), t0);
}

void StoveBuilder::buildGas(const Burner& br, bool ownGrate) {
  const float z = m_topZ;
  const float rb = br.radius * m_rng.uniformf(0.45, 0.6);
  const float capH = m_rng.uniformf(0.015, 0.03);
  const int seg = m_rng.pick(std::vector<int>{16, 24, 32});
  // Burner base (spreader) and cap; the flame ring is the cooking heat source.
  m_b.lathe(translation(br.center.x(), br.center.y(), z),
            {{0, 0}, {rb * 1.25f, 0}, {rb * 1.2f, 0.004f}, {rb, 0.006f}, {rb, capH * 0.7f}, {0, capH * 0.7f}},
            seg, m_pal.trim);
  const std::size_t t0 = m_b.triangleCount();
  const float capR = rb * m_rng.uniformf(0.85, 1.05);
  m_b.lathe(translation(br.center.x(), br.center.y(), z + capH * 0.7f),
            {{0, 0}, {capR, 0}, {capR, capH * 0.2f}, {capR * 0.8f, capH * 0.3f}, {0, capH * 0.32f}}, seg,
            m_pal.burnerDark);
  gt("heatsource", Vec3(br.center.x(), br.center.y(), z + capH * 0.7f + capH * 0.32f), Vec3::UnitZ(), t0);
  if (!ownGrate) return;
  // A square grate with fingers reaching towards the burner.
  const float gz = z + capH + m_rng.uniformf(0.012, 0.025);
  const float half = br.radius * m_rng.uniformf(1.05, 1.25);
  const float bar = m_rng.uniformf(0.007, 0.012);
  const float legH = gz - z;
  for (int s = 0; s < 4; ++s) {
    const Affine rot = translation(br.center.x(), br.center.y(), 0) * rotationZ(s * kPi / 2);
    m_b.box(rot * translation(half, 0, gz), Vec3(bar, 2 * half + bar, bar), m_pal.burner);
    m_b.box(rot * translation(half * 0.55f, 0, gz), Vec3(half * 0.9f, bar, bar), m_pal.burner);
    m_b.box(rot * translation(half, half, z + 0.5f * legH), Vec3(bar, bar, legH), m_pal.burner);
  }
}

void StoveBuilder::buildRaisedPlate(const Burner& br) {
  const float z = m_topZ;
  const float h = m_rng.uniformf(0.004, 0.02);
  const int seg = m_rng.pick(std::vector<int>{24, 32, 48, 64});
  const bool trimRing = m_rng.chance(0.6);
  if (trimRing) {
    m_b.lathe(translation(br.center.x(), br.center.y(), z),
              {{br.radius * 0.98f, 0}, {br.radius * 1.1f, 0}, {br.radius * 1.08f, h * 0.8f}, {br.radius * 0.98f, h * 0.8f}},
              seg, m_pal.trim);
  }
  const std::size_t t0 = m_b.triangleCount();
  std::vector<Vec2> profile = {{0, 0}, {br.radius, 0}, {br.radius, h * 0.85f}, {br.radius * 0.96f, h}};
  if (m_rng.chance(0.4)) {
    // Concentric grooves, as on solid plates and LIBERO's burner disc.
    const int grooves = m_rng.uniformInt(3, 7);
    const float depth = std::min(0.0015f, 0.3f * h);
    for (int i = grooves; i >= 1; --i) {
      const float r = br.radius * 0.92f * i / (grooves + 1);
      profile.push_back({r + 0.002f, h});
      profile.push_back({r + 0.002f, h - depth});
      profile.push_back({r - 0.002f, h - depth});
      profile.push_back({r - 0.002f, h});
    }
    m_extras.push_back("grooved_plate");
  }
  profile.push_back({0, h});
  m_b.lathe(translation(br.center.x(), br.center.y(), z), profile, seg, m_pal.burner);
  if (m_rng.chance(0.4)) {  // centre dot / thermostat disc
    m_b.lathe(translation(br.center.x(), br.center.y(), z + h),
              {{0, 0}, {br.radius * 0.2f, 0}, {br.radius * 0.2f, 0.001f}, {0, 0.001f}}, 16, m_pal.trim);
  }
  gt("heatsource", Vec3(br.center.x(), br.center.y(), z + h), Vec3::UnitZ(), t0);
}

void StoveBuilder::buildGlassTop() {
  // The zones exist only in the texture of a flat glass sheet lying on the top.
  const Rect2& t = m_top;
  auto toUv = [&t](const Vec2& p) {
    return Vec2((p.x() - t.x0) / t.width(), (p.y() - t.y0) / t.depth());
  };
  const float lift = 0.0006f;
  const bool slab = m_kind == "glass_slab";
  const int pixels = slab ? 1024 : 512;  // printed symbols are a few millimetres wide
  TexturePainter painter(pixels, std::max(64, static_cast<int>(pixels * t.depth() / t.width())),
                         jitter(m_rng, {0.05f, 0.05f, 0.06f}, 0.03f));
  const Vec3 zoneColor = m_rng.pick(std::vector<Vec3>{{0.45f, 0.45f, 0.45f}, {0.6f, 0.2f, 0.15f},
                                                      {0.75f, 0.75f, 0.75f}, {0.5f, 0.35f, 0.2f}});
  const bool filled = m_rng.chance(0.35);
  for (const Burner& br : m_burners) {
    const Vec2 uv = toUv(br.center);
    const float ru = br.radius / t.width();
    if (filled) painter.disc(uv, ru, 0.35f * zoneColor + Vec3::Constant(0.04f));
    painter.ring(uv, ru, 0.006f / t.width(), zoneColor);
    if (m_rng.chance(0.6)) painter.ring(uv, ru * 0.62f, 0.004f / t.width(), zoneColor);
    if (m_rng.chance(0.3)) painter.disc(uv, 0.006f / t.width(), zoneColor);
  }
  const Eigen::AlignedBox2f top(Eigen::Vector2f(t.x0, t.y0), Eigen::Vector2f(t.x1, t.y1));
  std::vector<Eigen::Vector2f> printed;
  if (slab) {
    // A dotted ring inside some zones, and a maker's name at the back, as on real glass hobs.
    for (const Burner& br : m_burners) {
      if (!m_rng.chance(0.5)) continue;
      const int dots = m_rng.uniformInt(24, 48);
      for (int i = 0; i < dots; ++i) {
        const float a = 2 * kPi * i / dots;
        const Vec2 p = br.center + 0.85f * br.radius * Vec2(std::cos(a), std::sin(a));
        painter.disc(toUv(p), 0.0015f / t.width(), zoneColor);
      }
    }
    if (m_rng.chance(0.6)) {
      const float y = t.y1 - 0.5f * (t.y1 - m_region.y1) - 0.01f;
      const float x = m_rng.uniformf(-0.25, 0.25) * t.width();
      paintPrintedLettering(m_rng, painter, top,
                            Eigen::AlignedBox2f(Eigen::Vector2f(x - 0.05f, y - 0.01f),
                                                Eigen::Vector2f(x + 0.05f, y + 0.01f)),
                            zoneColor);
      m_extras.push_back("printed_lettering");
    }
  }
  if (m_controls == "printed") {
    const Eigen::AlignedBox2f area(Eigen::Vector2f(m_strip.x0, m_strip.y0),
                                   Eigen::Vector2f(m_strip.x1, m_strip.y1));
    const Vec3 symbolColor = m_rng.chance(0.6) ? zoneColor : Vec3(0.85f, 0.85f, 0.85f);
    printed = paintPrintedControls(m_rng, painter, top, area, m_knobCount, symbolColor);
  }
  painter.speckle(0.03f, static_cast<unsigned>(m_rng.next() & 0xffff));
  const int tex = m_b.addTexture(std::move(painter).take());
  const int glass = m_b.material("glass_top", Vec3::Ones(), tex);
  const std::size_t t0 = m_b.triangleCount();
  m_b.texturedQuad(translation(0.5f * (t.x0 + t.x1), 0.5f * (t.y0 + t.y1), m_topZ + lift),
                   Vec2(t.width() - 0.002f, t.depth() - 0.002f), glass, m_rng.pick(std::vector<int>{1, 2, 8}));
  for (const Burner& br : m_burners) {
    gt("heatsource", Vec3(br.center.x(), br.center.y(), m_topZ + lift), Vec3::UnitZ(), t0);
  }
  for (const Eigen::Vector2f& p : printed) {
    gt("togglebutton", Vec3(p.x(), p.y(), m_topZ + lift), Vec3::UnitZ(), t0);
  }
  m_topZ += lift;
}

void StoveBuilder::buildGlassSlab() {
  // A built-in glass hob on its own: one thin sheet, sometimes in a steel frame; no body.
  const float thickness = m_rng.uniformf(0.003, 0.01);
  m_b.box(translation(0, 0, 0.5f * thickness), Vec3(m_width, m_depth, thickness), m_pal.top,
          m_rng.chance(0.5) ? 0.4f * thickness : 0.0f, 1);
  m_topZ = thickness;
  m_top = {-0.5f * m_width, 0.5f * m_width, -0.5f * m_depth, 0.5f * m_depth};
  if (m_rng.chance(0.35)) {
    const float bar = m_rng.uniformf(0.003, 0.008);
    const float h = thickness + 0.0015f;
    m_b.box(translation(0, -0.5f * (m_depth + bar), 0.5f * h), Vec3(m_width + 2 * bar, bar, h),
            m_pal.trim);
    m_b.box(translation(0, 0.5f * (m_depth + bar), 0.5f * h), Vec3(m_width + 2 * bar, bar, h),
            m_pal.trim);
    m_b.box(translation(-0.5f * (m_width + bar), 0, 0.5f * h), Vec3(bar, m_depth, h), m_pal.trim);
    m_b.box(translation(0.5f * (m_width + bar), 0, 0.5f * h), Vec3(bar, m_depth, h), m_pal.trim);
    m_extras.push_back("steel_frame");
  }
  m_frontY = -0.5f * m_depth;
  m_frontZ0 = 0;
  m_frontZ1 = thickness;
}

void StoveBuilder::splitPrintedControlArea() {
  // Most touch panels run along the front edge; some sit at one end beside the zones.
  if (m_rng.chance(0.75)) {
    const float strip = std::min(0.3f * m_region.depth(), m_rng.uniformf(0.04, 0.08));
    m_strip = {m_region.x0, m_region.x1, m_region.y0, m_region.y0 + strip};
    m_region.y0 += strip;
  } else {
    const float strip = std::min(0.3f * m_region.width(), m_rng.uniformf(0.04, 0.08));
    m_stripOnSide = true;
    m_strip = {m_region.x1 - strip, m_region.x1, m_region.y0, m_region.y1};
    m_region.x1 -= strip;
  }
}

void StoveBuilder::buildBurners() {
  if (m_look == "glass_zone") {
    buildGlassTop();
    return;
  }
  const bool continuousGrate = m_look == "gas" && m_burners.size() > 1 && m_rng.chance(0.5);
  for (const Burner& br : m_burners) {
    if (m_look == "coil") buildCoil(br);
    else if (m_look == "gas") buildGas(br, !continuousGrate);
    else buildRaisedPlate(br);
  }
  if (continuousGrate) {
    // One grate frame over the whole region with bars between burners.
    const float gz = m_topZ + m_rng.uniformf(0.035, 0.05);
    const float bar = m_rng.uniformf(0.008, 0.013);
    const Rect2& r = m_region;
    const float cx = 0.5f * (r.x0 + r.x1), cy = 0.5f * (r.y0 + r.y1);
    m_b.box(translation(cx, r.y0, gz), Vec3(r.width(), bar, bar), m_pal.burner);
    m_b.box(translation(cx, r.y1, gz), Vec3(r.width(), bar, bar), m_pal.burner);
    m_b.box(translation(r.x0, cy, gz), Vec3(bar, r.depth(), bar), m_pal.burner);
    m_b.box(translation(r.x1, cy, gz), Vec3(bar, r.depth(), bar), m_pal.burner);
    const int bars = std::max(3, static_cast<int>(r.width() / 0.07f));
    for (int i = 1; i < bars; ++i) {
      const float x = r.x0 + r.width() * i / bars;
      m_b.box(translation(x, cy, gz), Vec3(bar, r.depth(), bar), m_pal.burner);
    }
    for (float x : {r.x0, r.x1}) {
      for (float y : {r.y0, r.y1}) {
        m_b.box(translation(x, y, 0.5f * (m_topZ + gz)), Vec3(bar, bar, gz - m_topZ), m_pal.burner);
      }
    }
    m_extras.push_back("continuous_grate");
  }
}

void StoveBuilder::addKnob(const Affine& frame, float maxRadius, float maxDepth) {
  KnobShape k = m_knobShape;
  const float scale = std::min(1.0f, maxRadius / (k.radius * (k.style == KnobStyle::Skirted ? 1.35f : 1.0f)));
  k.radius *= scale;
  k.depth = std::min(k.depth, maxDepth);
  const std::size_t t0 = m_b.triangleCount();
  const Vec3 c = buildKnob(m_b, frame, k, m_pal.knob, m_pal.knobAccent);
  gt("togglebutton", c, frame.linear() * Vec3::UnitZ(), t0);
}

void StoveBuilder::addTouchButton(const Affine& frame, float radius) {
  const float h = m_rng.uniformf(0.0008, 0.003);
  const std::size_t t0 = m_b.triangleCount();
  const int m = m_b.material("touch_button", m_rng.chance(0.5) ? Vec3(0.8f, 0.8f, 0.8f) : Vec3(0.75f, 0.2f, 0.15f));
  if (m_rng.chance(0.5)) m_b.cylinder(frame, radius, 0, h, 20, m);
  else m_b.box(frame * translation(0, 0, 0.5f * h), Vec3(2 * radius, 1.4f * radius, h), m, 0.0f, 0);
  gt("togglebutton", frame * Vec3(0, 0, h), frame.linear() * Vec3::UnitZ(), t0);
}

void StoveBuilder::buildControls() {
  if (m_controls == "printed") return;  // painted with the glass top
  const int n = m_knobCount;
  if (m_controls == "top_front_strip" || m_controls == "top_beside" ||
      (m_controls == "touch" && m_strip.width() > 0)) {
    const bool alongX = !m_stripOnSide;
    const float length = alongX ? m_strip.width() : m_strip.depth();
    const float across = alongX ? m_strip.depth() : m_strip.width();
    const float spacing = length / n;
    const float maxR = std::min(0.42f * spacing, 0.4f * across);
    for (int i = 0; i < n; ++i) {
      const float t = (i + 0.5f) / n;
      const Vec2 p = alongX ? m_strip.at(t, 0.5f) : m_strip.at(0.5f, t);
      const Affine frame = translation(p.x(), p.y(), m_topZ);
      if (m_controls == "touch") addTouchButton(frame, std::min(maxR, m_rng.uniformf(0.006, 0.012)));
      else addKnob(frame, maxR, 0.05f);
    }
    if (m_controls == "touch" && m_rng.chance(0.5)) m_extras.push_back("printed_display");
  } else if (m_controls == "touch") {
    // Touch buttons along the front edge of the top.
    const float y = m_region.y0 + 0.02f;
    for (int i = 0; i < n; ++i) {
      const float x = m_region.x0 + m_region.width() * (i + 0.5f) / n;
      addTouchButton(translation(x, y, m_topZ), 0.008f);
    }
  } else if (m_controls == "front_panel") {
    const float zc = 0.5f * (m_frontZ0 + m_frontZ1);
    const float height = m_frontZ1 - m_frontZ0;
    const float span = m_width * m_rng.uniformf(0.6, 0.92);
    const float spacing = span / n;
    const float maxR = std::min(0.42f * spacing, 0.42f * height);
    for (int i = 0; i < n; ++i) {
      const float x = -0.5f * span + (i + 0.5f) * spacing;
      // Knob axis -y: rotate local z onto -y.
      addKnob(translation(x, m_frontY, zc) * rotationX(kPi / 2), maxR, 0.045f);
    }
  } else if (m_controls == "back_panel") {
    const float height = m_backZ1 - m_backZ0;
    const float span = m_width * m_rng.uniformf(0.6, 0.9);
    const float spacing = span / n;
    const float maxR = std::min(0.42f * spacing, 0.4f * height);
    const Affine panel = translation(0, m_backY + 0.0f, m_topZ) * rotationX(-m_backTilt);
    for (int i = 0; i < n; ++i) {
      const float x = -0.5f * span + (i + 0.5f) * spacing;
      const Affine f = translation(0, 0, 0) * panel * translation(x, 0, 0.5f * height) * rotationX(kPi / 2);
      addKnob(f, maxR, 0.045f);
    }
  } else {  // side
    const float sx = m_rng.chance(0.7) ? 1.0f : -1.0f;
    const float height = m_frontZ1 - m_frontZ0;
    const float spacing = m_depth / (n + 1);
    // Small appliances often carry one big knob beside the body, taller than the slab itself.
    const float maxR = m_kind == "hot_plate" ? std::min(0.4f * spacing, 0.045f) : std::min(0.4f * spacing, 0.42f * height);
    for (int i = 0; i < n; ++i) {
      const float y = -0.5f * m_depth + (i + 1) * spacing;
      const float r = std::min(maxR, m_knobShape.radius * (m_knobShape.style == KnobStyle::Skirted ? 1.35f : 1.0f));
      const float z = std::max(0.5f * (m_frontZ0 + m_frontZ1), r);
      addKnob(translation(sx * 0.5f * m_width, y, z) * rotationY(sx * kPi / 2), maxR, 0.05f);
    }
  }
}

GeneratedObject StoveBuilder::run() {
  choose();
  buildBody();
  buildBurners();
  buildControls();
  m_params["kind"] = m_kind;
  m_params["layout"] = m_layout;
  m_params["burners"] = static_cast<int>(m_burners.size());
  m_params["burner_look"] = m_look;
  m_params["controls"] = m_controls;
  m_params["knobs"] = m_knobCount;
  m_params["knob_style"] =
      m_controls == "touch" || m_controls == "printed" ? m_controls : toString(m_knobShape.style);
  m_params["finish"] = m_pal.finishName;
  m_params["width_m"] = roundedToMillimetre(m_width);
  std::sort(m_extras.begin(), m_extras.end());
  m_extras.erase(std::unique(m_extras.begin(), m_extras.end()), m_extras.end());
  m_params["extras"] = m_extras;

  return makeGeneratedObject("stove", std::move(m_b).build(), std::move(m_points), m_params);
}

}  // namespace

const std::vector<std::string>& stoveKinds() {
  static const std::vector<std::string> v = {"hot_plate", "cooktop", "hob_in_counter",
                                             "range_freestanding", "range_slide_in"};
  return v;
}
const std::vector<std::string>& stoveLayouts() {
  static const std::vector<std::string> v = {"single", "row2", "column2", "row3", "triangle3",
                                             "grid2x2", "offgrid4", "four_plus_centre", "grid2x3"};
  return v;
}
const std::vector<std::string>& stoveBurnerLooks() {
  static const std::vector<std::string> v = {"coil", "gas", "raised_plate", "glass_zone"};
  return v;
}
const std::vector<std::string>& stoveControlPlacements() {
  static const std::vector<std::string> v = {"front_panel", "top_front_strip", "back_panel",
                                             "side", "touch", "top_beside"};
  return v;
}

GeneratedObject generateStove(Rng& rng, const StoveOptions& options) {
  return StoveBuilder(rng, options).run();
}

}  // namespace sagrid::gen
