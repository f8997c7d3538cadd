#include "core/generate/distractor_generator.h"

#include <cmath>

#include "core/generate/angles.h"
#include "core/generate/parts.h"
#include "core/generate/shape_builder.h"

namespace sagrid::gen {

namespace {

class DistractorBuilder {
 public:
  DistractorBuilder(Rng& rng, bool appliances) : m_rng(rng), m_appliances(appliances) {}

  GeneratedObject run() {
    // Without the appliances, the draw is the one the shipped category classifier's distractors
    // were generated with.
    const int kind = m_appliances ? m_rng.weighted({1.0, 1.0, 1.0, 0.8, 1.0, 1.0, 0.6, 0.8})
                                  : m_rng.weighted({1.0, 1.0, 1.0, 0.8, 1.0});
    m_kind = distractorKinds()[static_cast<std::size_t>(kind)];
    const Finish body = pickFinish(
        m_rng, {"stainless", "white_enamel", "black_glass", "dark_grey", "matte_black", "cream"});
    m_body = m_b.material("body_" + body.name, body.color);
    m_glass = m_b.material("glass", finishNamed(m_rng, "black_glass").color);
    const Finish handle = pickFinish(m_rng, {"stainless", "chrome", "matte_black", "brushed_nickel"});
    m_handle = m_b.material("handle_" + handle.name, handle.color);
    m_knob = m_b.material("knob", finishNamed(m_rng, m_rng.chance(0.5) ? "matte_black" : "chrome").color);
    m_accent = m_b.material("accent", finishNamed(m_rng, "white_enamel").color);
    m_params["finish"] = body.name;

    if (m_kind == "microwave") buildMicrowave();
    else if (m_kind == "wall_oven") buildWallOven();
    else if (m_kind == "dishwasher") buildDishwasher();
    else if (m_kind == "range_hood") buildRangeHood();
    else if (m_kind == "washing_machine")
      buildWashingMachine();
    else if (m_kind == "toaster")
      buildToaster();
    else if (m_kind == "countertop_appliance")
      buildCountertopAppliance();
    else buildCabinet();

    m_params["kind"] = m_kind;
    m_params["width_m"] = roundedToMillimetre(m_width);
    m_params["depth_m"] = roundedToMillimetre(m_depth);
    m_params["height_m"] = roundedToMillimetre(m_height);
    m_params["knobs"] = m_knobs;
    m_params["extras"] = m_extras;
    return makeGeneratedObject(kDistractorCategory, std::move(m_b).build(), {}, m_params);
  }

 private:
  float fy() const { return -0.5f * m_depth; }  // the front face plane (front looks to -y)

  // A knob on the front face at (x, z), axis towards the viewer.
  void knob(float x, float z, const KnobShape& shape) {
    buildKnob(m_b, translation(x, fy(), z) * rotationX(kPi / 2), shape, m_knob, m_accent);
    ++m_knobs;
  }

  void verticalHandle(float x, float z, float length) {
    buildBarHandle(m_b, translation(x, fy() - 0.005f, z) * rotationX(kPi / 2) * rotationY(kPi / 2),
                   length, m_rng.uniformf(0.025, 0.05), m_rng.uniformf(0.006, 0.012), m_handle);
  }
  void horizontalHandle(float z, float length) {
    buildBarHandle(m_b, translation(0, fy() - 0.005f, z) * rotationX(kPi / 2), length,
                   m_rng.uniformf(0.025, 0.05), m_rng.uniformf(0.006, 0.012), m_handle);
  }

  void buildMicrowave() {
    m_width = m_rng.uniformf(0.42, 0.6);
    m_depth = m_rng.uniformf(0.3, 0.45);
    m_height = m_rng.uniformf(0.24, 0.36);
    const float feet = m_rng.chance(0.6) ? m_rng.uniformf(0.005, 0.015) : 0.0f;
    m_b.box(translation(0, 0, feet + 0.5f * m_height), Vec3(m_width, m_depth, m_height), m_body,
            m_rng.uniformf(0.0, 0.02), 3);
    if (feet > 0)
      for (float sx : {-1.f, 1.f})
        for (float sy : {-1.f, 1.f})
          m_b.cylinder(translation(sx * 0.4f * m_width, sy * 0.4f * m_depth, 0), 0.015f, 0, feet + 0.002f,
                       12, m_knob);
    // Door with a window on the left, control panel on the right.
    const float panel = m_width * m_rng.uniformf(0.2, 0.3);
    const float doorW = m_width - panel - 0.02f;
    const float doorX = -0.5f * m_width + 0.01f + 0.5f * doorW;
    const float zc = feet + 0.5f * m_height;
    m_b.box(translation(doorX, fy() - 0.006f, zc), Vec3(doorW, 0.012f, m_height - 0.03f), m_body, 0.003f, 1);
    m_b.box(translation(doorX - 0.05f * doorW, fy() - 0.0125f, zc),
            Vec3(doorW * m_rng.uniformf(0.6, 0.8), 0.002f, (m_height - 0.03f) * m_rng.uniformf(0.55, 0.75)),
            m_glass);
    const float px = 0.5f * m_width - 0.5f * panel - 0.005f;
    m_b.box(translation(px, fy() - 0.003f, zc), Vec3(panel - 0.01f, 0.006f, m_height - 0.03f), m_glass);
    if (m_rng.chance(0.5)) verticalHandle(doorX + 0.45f * doorW, zc, 0.6f * m_height);
    // Dials or a keypad of buttons.
    if (m_rng.chance(0.55)) {
      KnobShape k = randomKnob(m_rng, 1.0f);
      const int n = m_rng.uniformInt(1, 2);
      for (int i = 0; i < n; ++i) knob(px, feet + m_height * (n == 1 ? 0.6f : 0.7f - 0.35f * i), k);
    } else {
      const int rows = m_rng.uniformInt(3, 5);
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < 3; ++c)
          m_b.box(translation(px + (c - 1) * panel * 0.25f, fy() - 0.008f, feet + m_height * (0.75f - 0.1f * r)),
                  Vec3(panel * 0.18f, 0.006f, m_height * 0.06f), m_accent, 0.001f, 1);
      m_extras.push_back("keypad");
    }
  }

  void buildWallOven() {
    m_width = m_rng.uniformf(0.5, 0.76);
    m_depth = m_rng.uniformf(0.5, 0.6);
    m_height = m_rng.uniformf(0.55, 0.95);
    m_b.box(translation(0, 0, 0.5f * m_height), Vec3(m_width, m_depth, m_height), m_body,
            m_rng.chance(0.4) ? 0.005f : 0.0f, 2);
    const float fascia = m_rng.uniformf(0.08, 0.14);
    const bool twoDoors = m_height > 0.8f && m_rng.chance(0.6);
    const float doorsTop = m_height - fascia;
    auto door = [&](float z0, float z1) {
      const float h = z1 - z0, w = m_width - 0.03f;
      m_b.box(translation(0, fy() - 0.012f, z0 + 0.5f * h), Vec3(w, 0.024f, h - 0.01f), m_body, 0.004f, 2);
      m_b.box(translation(0, fy() - 0.025f, z0 + 0.45f * h), Vec3(w * m_rng.uniformf(0.55, 0.8), 0.003f, h * 0.45f),
              m_glass, 0.003f, 1);
      buildBarHandle(m_b, translation(0, fy() - 0.024f, z1 - 0.05f) * rotationX(kPi / 2),
                     w * m_rng.uniformf(0.6, 0.9), m_rng.uniformf(0.03, 0.06), m_rng.uniformf(0.007, 0.013),
                     m_handle);
    };
    if (twoDoors) {
      const float split = 0.02f + doorsTop * 0.5f;
      door(0.02f, split);
      door(split, doorsTop);
      m_extras.push_back("double_oven");
    } else {
      door(0.02f, doorsTop);
    }
    // Fascia: dials and a display; no burners anywhere (the top is a plain box).
    m_b.box(translation(0, fy() - 0.003f, m_height - 0.5f * fascia), Vec3(m_width - 0.02f, 0.006f, fascia - 0.01f),
            m_rng.chance(0.5) ? m_glass : m_body);
    if (m_rng.chance(0.7)) {
      KnobShape k = randomKnob(m_rng, 1.0f);
      const int n = m_rng.uniformInt(1, 3);
      for (int i = 0; i < n; ++i) {
        const float x = (n == 1 ? 0.3f : -0.35f + 0.7f * i / (n - 1)) * m_width;
        knob(x, m_height - 0.5f * fascia, k);
      }
    }
    m_b.box(translation(0, fy() - 0.007f, m_height - 0.5f * fascia), Vec3(0.12f, 0.003f, 0.04f), m_accent);
  }

  void buildDishwasher() {
    m_width = m_rng.uniformf(0.45, 0.6);
    m_depth = m_rng.uniformf(0.55, 0.62);
    m_height = m_rng.uniformf(0.8, 0.88);
    const float plinth = m_rng.uniformf(0.06, 0.12);
    m_b.box(translation(0, 0.02f, 0.5f * plinth), Vec3(m_width - 0.02f, m_depth - 0.04f, plinth),
            m_b.material("plinth", finishNamed(m_rng, "matte_black").color));
    m_b.box(translation(0, 0, plinth + 0.5f * (m_height - plinth)), Vec3(m_width, m_depth, m_height - plinth), m_body);
    // One full-height door; a control strip on top of the door, sometimes with buttons.
    const float doorH = m_height - plinth - 0.01f;
    m_b.box(translation(0, fy() - 0.012f, plinth + 0.5f * doorH), Vec3(m_width - 0.01f, 0.024f, doorH), m_body,
            0.003f, 1);
    const float strip = m_rng.uniformf(0.06, 0.11);
    m_b.box(translation(0, fy() - 0.026f, m_height - 0.5f * strip - 0.01f), Vec3(m_width - 0.02f, 0.004f, strip),
            m_rng.chance(0.5) ? m_glass : m_body);
    if (m_rng.chance(0.6)) {
      const int n = m_rng.uniformInt(3, 6);
      for (int i = 0; i < n; ++i)
        m_b.box(translation(-0.3f * m_width + 0.6f * m_width * i / (n - 1), fy() - 0.03f, m_height - 0.5f * strip - 0.01f),
                Vec3(0.02f, 0.005f, 0.012f), m_accent, 0.001f, 1);
      m_extras.push_back("buttons");
    }
    if (m_rng.chance(0.7)) {
      buildBarHandle(m_b, translation(0, fy() - 0.028f, m_height - strip - 0.04f) * rotationX(kPi / 2),
                     m_width * m_rng.uniformf(0.4, 0.8), m_rng.uniformf(0.025, 0.045), m_rng.uniformf(0.006, 0.011),
                     m_handle);
      m_extras.push_back("handle");
    }
  }

  void buildRangeHood() {
    m_width = m_rng.uniformf(0.6, 0.9);
    m_depth = m_rng.uniformf(0.45, 0.55);
    const float canopyH = m_rng.uniformf(0.06, 0.2);
    const float chimneyH = m_rng.chance(0.7) ? m_rng.uniformf(0.4, 0.8) : 0.0f;
    m_height = canopyH + chimneyH;
    if (m_rng.chance(0.5)) {
      // Pyramid canopy: a loft from the wide bottom to the chimney section.
      const float cw = m_rng.uniformf(0.22, 0.32), cd = m_rng.uniformf(0.2, 0.28);
      m_b.loft(Affine::Identity(),
               {{{0, 0}, {0.5f * m_width, 0.5f * m_depth}, 0.005f, 0},
                {{0, 0}, {0.5f * m_width, 0.5f * m_depth}, 0.005f, 0.03f},
                {{0, 0.5f * m_depth - 0.5f * cd}, {0.5f * cw, 0.5f * cd}, 0.003f, canopyH}},
               2, m_body, true, true);
      m_extras.push_back("pyramid");
    } else {
      m_b.box(translation(0, 0, 0.5f * canopyH), Vec3(m_width, m_depth, canopyH), m_body, 0.004f, 2);
    }
    if (chimneyH > 0) {
      const float cw = m_rng.uniformf(0.2, 0.3), cd = m_rng.uniformf(0.18, 0.26);
      m_b.box(translation(0, 0.5f * m_depth - 0.5f * cd, canopyH + 0.5f * chimneyH), Vec3(cw, cd, chimneyH), m_body);
      m_extras.push_back("chimney");
    }
    // Grease filters under the canopy, and a row of buttons on the front lip.
    m_b.box(translation(0, 0, -0.002f), Vec3(m_width * 0.85f, m_depth * 0.8f, 0.004f),
            m_b.material("filter", finishNamed(m_rng, "dark_grey").color));
    if (m_rng.chance(0.7)) {
      const int n = m_rng.uniformInt(3, 5);
      for (int i = 0; i < n; ++i)
        m_b.box(translation(-0.15f * m_width + 0.3f * m_width * i / (n - 1), fy() - 0.003f, 0.02f),
                Vec3(0.018f, 0.006f, 0.012f), m_accent, 0.001f, 1);
      m_extras.push_back("buttons");
    }
  }

  // A front-loading washer or dryer (a round porthole door, a control strip with a programme dial
  // and buttons), or a top loader (a lid on top, the controls on a console at its back edge, like
  // a range's back panel).
  void buildWashingMachine() {
    m_width = m_rng.uniformf(0.55, 0.62);
    m_depth = m_rng.uniformf(0.5, 0.65);
    m_height = m_rng.uniformf(0.82, 0.9);
    m_b.box(translation(0, 0, 0.5f * m_height), Vec3(m_width, m_depth, m_height), m_body,
            m_rng.uniformf(0.0, 0.015), 2);
    const KnobShape dial = randomKnob(m_rng, m_rng.uniformf(1.2f, 1.8f));
    const int buttons = m_rng.uniformInt(0, 5);
    if (m_rng.chance(0.3)) {
      // Top loader: lid inset in the top, console along the back edge.
      const float console = m_rng.uniformf(0.08, 0.14);
      m_b.box(translation(0, -0.5f * console, m_height + 0.006f),
              Vec3(m_width - 0.06f, m_depth - console - 0.06f, 0.012f), m_body, 0.004f, 1);
      const float cz = m_height + 0.5f * console;
      const float cy = 0.5f * m_depth - 0.5f * console;
      m_b.box(translation(0, cy, cz), Vec3(m_width, console, console), m_body, 0.01f, 2);
      buildKnob(m_b, translation(0.3f * m_width, cy - 0.5f * console, cz) * rotationX(kPi / 2),
                dial, m_knob, m_accent);
      ++m_knobs;
      for (int i = 0; i < buttons; ++i)
        m_b.box(translation(-0.35f * m_width + 0.07f * i, cy - 0.5f * console - 0.003f, cz),
                Vec3(0.02f, 0.006f, 0.012f), m_accent, 0.001f, 1);
      m_height += console;
      m_extras.push_back("top_loader");
    } else {
      const float strip = m_rng.uniformf(0.1, 0.16);
      const float sz = m_height - 0.5f * strip;
      m_b.box(translation(0, fy() - 0.003f, sz), Vec3(m_width - 0.02f, 0.006f, strip - 0.02f),
              m_rng.chance(0.5) ? m_glass : m_body);
      if (m_rng.chance(0.6)) {  // the detergent drawer on the left
        m_b.box(translation(-0.3f * m_width, fy() - 0.008f, sz),
                Vec3(0.3f * m_width, 0.01f, strip - 0.04f), m_body, 0.003f, 1);
        m_extras.push_back("drawer");
      }
      knob(0.2f * m_width, sz, dial);
      for (int i = 0; i < buttons; ++i)
        m_b.box(translation(0.32f * m_width + 0.035f * (i % 2), fy() - 0.008f,
                            sz + 0.03f * (i / 2 - 1)),
                Vec3(0.018f, 0.006f, 0.012f), m_accent, 0.001f, 1);
      // The porthole: a ring round a bulging glass.
      const float r = std::min(0.42f * m_width, 0.35f * (m_height - strip));
      const float dz = 0.45f * (m_height - strip);
      const Affine door = translation(0, fy(), dz) * rotationX(kPi / 2);
      m_b.lathe(door, {{r, 0.0f}, {r, 0.03f}, {0.85f * r, 0.045f}, {0.72f * r, 0.04f}}, 40,
                m_rng.chance(0.5) ? m_handle : m_body);
      m_b.lathe(door, {{0.72f * r, 0.035f}, {0.5f * r, 0.05f}, {0.0f, 0.055f}}, 40, m_glass);
      m_extras.push_back(m_rng.chance(0.5) ? "washer" : "dryer");
    }
  }

  // A two- or four-slot toaster: slots sunk into its top, a lever on the front, a browning dial.
  void buildToaster() {
    const int slots = m_rng.chance(0.7) ? 2 : 4;
    m_width = slots == 2 ? m_rng.uniformf(0.25, 0.32) : m_rng.uniformf(0.3, 0.4);
    m_depth = slots == 2 ? m_rng.uniformf(0.15, 0.2) : m_rng.uniformf(0.25, 0.3);
    m_height = m_rng.uniformf(0.18, 0.22);
    const float top = 0.015f;
    m_b.box(translation(0, 0, 0.5f * (m_height - top)), Vec3(m_width, m_depth, m_height - top),
            m_body, m_rng.uniformf(0.005, 0.02), 3);
    // Each slot its own strip of the top, with a hole over a dark well.
    const int rows = slots == 2 ? 1 : 2;
    const int perRow = 2;
    const float cellW = m_width / rows, cellD = m_depth / perRow;
    const int dark = m_b.material("slot", finishNamed(m_rng, "matte_black").color);
    for (int a = 0; a < rows; ++a)
      for (int b = 0; b < perRow; ++b) {
        const float x = -0.5f * m_width + cellW * (a + 0.5f),
                    y = -0.5f * m_depth + cellD * (b + 0.5f);
        const RoundedRect hole{{0, 0}, {0.4f * cellW, 0.15f * cellD}, 0.004f, 0};
        m_b.plateWithHole(translation(x, y, m_height - top), Vec2(0.5f * cellW, 0.5f * cellD), hole,
                          0, top, 2, m_body);
        m_b.box(translation(x, y, m_height - top - 0.002f),
                Vec3(0.8f * cellW, 0.3f * cellD, 0.004f), dark);
      }
    m_b.box(translation(0.3f * m_width, fy() - 0.015f, 0.6f * m_height),
            Vec3(0.035f, 0.03f, 0.015f), m_handle, 0.003f, 1);
    knob(-0.3f * m_width, 0.35f * m_height, randomKnob(m_rng, 0.8f));
    m_extras.push_back(slots == 2 ? "two_slots" : "four_slots");
  }

  // Small appliances that stand on a worktop: a kettle on its base, a blender (a jug on a motor
  // block with a dial), or a drip coffee maker (a tower over a carafe on a warming plate).
  void buildCountertopAppliance() {
    const int style = m_rng.uniformInt(0, 2);
    const float r = m_rng.uniformf(0.07, 0.1);
    auto jug = [&](float z0, float height, int material) {
      m_b.lathe(translation(0, 0, z0),
                {{0.0f, 0.0f},
                 {r, 0.0f},
                 {r * m_rng.uniformf(0.9f, 1.15f), 0.6f * height},
                 {r * m_rng.uniformf(0.7f, 1.0f), height},
                 {0.0f, height + 0.005f}},
                32, material);
      m_b.tube({{r, 0, z0 + 0.2f * height},
                {r + 0.05f, 0, z0 + 0.3f * height},
                {r + 0.05f, 0, z0 + 0.75f * height},
                {0.9f * r, 0, z0 + 0.85f * height}},
               0.01f, 8, m_handle);
    };
    if (style == 0) {
      m_b.cylinder(Affine::Identity(), r + 0.01f, 0.0f, 0.02f, 32, m_knob);
      const float h = m_rng.uniformf(0.18, 0.26);
      jug(0.02f, h, m_body);
      m_width = m_depth = 2 * r + 0.12f;
      m_height = h + 0.03f;
      m_extras.push_back("kettle");
    } else if (style == 1) {
      const float block = m_rng.uniformf(0.08, 0.13);
      m_b.box(translation(0, 0, 0.5f * block), Vec3(2.2f * r, 2.2f * r, block), m_body, 0.01f, 2);
      m_depth = 2.2f * r;
      knob(0, 0.5f * block, randomKnob(m_rng, 1.0f));
      const float h = m_rng.uniformf(0.2, 0.3);
      jug(block, h, m_glass);
      m_width = 2.2f * r + 0.12f;
      m_height = block + h;
      m_extras.push_back("blender");
    } else {
      m_width = m_rng.uniformf(0.2, 0.28);
      m_depth = m_rng.uniformf(0.22, 0.3);
      m_height = m_rng.uniformf(0.3, 0.4);
      const float baseH = 0.04f, towerD = 0.4f * m_depth, headH = 0.08f;
      m_b.box(translation(0, 0, 0.5f * baseH), Vec3(m_width, m_depth, baseH), m_body, 0.006f, 2);
      m_b.box(translation(0, 0.5f * m_depth - 0.5f * towerD, 0.5f * m_height),
              Vec3(m_width, towerD, m_height), m_body, 0.008f, 2);
      m_b.box(translation(0, 0, m_height - 0.5f * headH), Vec3(m_width, m_depth, headH), m_body,
              0.008f, 2);
      m_b.cylinder(translation(0, -0.15f * m_depth, 0), 0.8f * r, baseH, baseH + 0.005f, 32,
                   m_knob);
      m_b.lathe(
          translation(0, -0.15f * m_depth, baseH + 0.005f),
          {{0.0f, 0.0f}, {0.8f * r, 0.0f}, {0.9f * r, 0.08f}, {0.6f * r, 0.14f}, {0.0f, 0.145f}},
          32, m_glass);
      m_b.box(translation(0.3f * m_width, fy() - 0.004f, 0.5f * baseH), Vec3(0.03f, 0.008f, 0.015f),
              m_accent, 0.001f, 1);
      m_extras.push_back("coffee_maker");
    }
  }

  void buildCabinet() {
    const bool wall = m_rng.chance(0.35);
    m_width = m_rng.uniformf(0.3, 1.2);
    m_depth = wall ? m_rng.uniformf(0.3, 0.38) : m_rng.uniformf(0.55, 0.62);
    m_height = wall ? m_rng.uniformf(0.5, 0.9) : m_rng.uniformf(0.82, 0.92);
    const Finish front = pickFinish(m_rng, {"wood", "laminate", "white_enamel", "cream", "pastel_blue", "dark_grey"});
    const int frontM = m_b.material("front_" + front.name, front.color);
    const float plinth = wall ? 0.0f : m_rng.uniformf(0.08, 0.14);
    if (plinth > 0)
      m_b.box(translation(0, 0.03f, 0.5f * plinth), Vec3(m_width - 0.01f, m_depth - 0.08f, plinth), m_knob);
    m_b.box(translation(0, 0, plinth + 0.5f * (m_height - plinth)), Vec3(m_width, m_depth, m_height - plinth), frontM);
    // A worktop on base cabinets (a plain one: no basin, no hob).
    float top = m_height;
    if (!wall && m_rng.chance(0.7)) {
      const Finish wt = pickFinish(m_rng, {"granite", "wood", "laminate", "ceramic_white", "matte_black"});
      const float t = m_rng.uniformf(0.02, 0.04);
      m_b.box(translation(0, -0.01f, m_height + 0.5f * t), Vec3(m_width + 0.02f, m_depth + 0.02f, t),
              m_b.material("worktop_" + wt.name, wt.color));
      top += t;
      m_extras.push_back("worktop");
    }
    // Doors (one or two side by side) and drawers above them.
    const int doors = m_width > 0.65f ? 2 : 1;
    const int drawers = wall ? 0 : m_rng.uniformInt(0, 3);
    const float front0 = plinth + 0.005f, front1 = m_height - 0.005f;
    const float drawerH = drawers > 0 ? std::min(0.18f, (front1 - front0) / (drawers + 1.5f)) : 0.0f;
    const float doorTop = front1 - drawers * drawerH;
    const float doorW = (m_width - 0.01f) / doors;
    for (int d = 0; d < doors; ++d) {
      const float x = -0.5f * m_width + 0.005f + doorW * (d + 0.5f);
      m_b.box(translation(x, fy() - 0.01f, 0.5f * (front0 + doorTop)), Vec3(doorW - 0.006f, 0.02f, doorTop - front0 - 0.004f),
              frontM, 0.002f, 1);
      const float hx = x + (doors == 1 ? 0.38f : (d == 0 ? 0.38f : -0.38f)) * doorW;
      verticalHandle(hx, wall ? front0 + 0.15f : doorTop - 0.12f, m_rng.uniformf(0.1, 0.2));
    }
    for (int i = 0; i < drawers; ++i) {
      const float z = doorTop + drawerH * (i + 0.5f);
      m_b.box(translation(0, fy() - 0.01f, z), Vec3(m_width - 0.016f, 0.02f, drawerH - 0.006f), frontM, 0.002f, 1);
      horizontalHandle(z, std::min(0.3f, 0.5f * m_width));
    }
    m_height = top;
    m_extras.push_back(wall ? "wall" : "base");
  }

  Rng& m_rng;
  bool m_appliances = false;
  ShapeBuilder m_b;
  nlohmann::json m_params = nlohmann::json::object();
  std::vector<std::string> m_extras;
  std::string m_kind;
  float m_width = 0.5f, m_depth = 0.5f, m_height = 0.5f;
  int m_knobs = 0;
  int m_body = 0, m_glass = 0, m_handle = 0, m_knob = 0, m_accent = 0;
};

}  // namespace

const std::vector<std::string>& distractorKinds() {
  static const std::vector<std::string> kinds = {
      "microwave", "wall_oven",       "dishwasher", "range_hood",
      "cabinet",   "washing_machine", "toaster",    "countertop_appliance"};
  return kinds;
}

GeneratedObject generateDistractor(Rng& rng, bool appliances) {
  return DistractorBuilder(rng, appliances).run();
}

}  // namespace sagrid::gen
