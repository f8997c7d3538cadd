// The OmniGibson export against the rules of OmniGibson's own importer, each test naming the file
// and function of StanfordVL/BEHAVIOR-1K it comes from (read at commit 08578371b9a5 of
// OmniGibson/omnigibson/utils/asset_conversion_utils.py, and
// OmniGibson/examples/objects/import_custom_object.py). The rules are restated here in our own
// words and checked on an exported stove (burners, knobs) and sink (outlet), plus check_urdf
// (urdfdom) on both URDFs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "core/common/atomic_file.h"
#include "core/export/omnigibson_export.h"
#include "core/export/omnigibson_model_name.h"
#include "support/analytic_meshes.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Exported once for the suite: a stove with 4 burners and 4 knobs, a sink with an outlet.
class OmniGibsonConformance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    s_dir = new fs::path(test::freshTempDir("omnigibson_conformance"));
    ExportOptions options;
    options.collision = CollisionMode::Decompose;
    options.maxCollisionParts = 8;
    const auto stoveLabels = test::writeAnalyticStove(*s_dir / "in" / "stove", "kitchen_stove");
    s_stove = new SimulatorExport(exportOmniGibson(readLabels(stoveLabels),
                                                   stoveLabels.parent_path() / "mesh.obj",
                                                   *s_dir / "out", options, stoveLabels));
    const auto sinkLabels =
        test::writeLabelledObject(*s_dir / "in" / "sink", test::box({0, 0, 0}, {0.5f, 0.4f, 0.3f}),
                                  {test::affordance("fluidsource", {0.25f, 0.1f, 0.5f}),
                                   test::affordance("togglebutton", {0.3f, 0.1f, 0.4f})},
                                  "sink 7", "sink");
    s_sink = new SimulatorExport(exportOmniGibson(readLabels(sinkLabels),
                                                  sinkLabels.parent_path() / "mesh.obj",
                                                  *s_dir / "out", options, sinkLabels));
  }
  static void TearDownTestSuite() {
    delete s_stove;
    delete s_sink;
    delete s_dir;
  }
  static json metadata(const SimulatorExport& e) {
    return json::parse(readFileBytes(e.root / "misc" / "metadata.json"));
  }
  static std::string model(const SimulatorExport& e) { return e.root.filename().string(); }
  static std::string urdf(const SimulatorExport& e, const std::string& suffix = "") {
    return readFileBytes(e.root / "urdf" / (model(e) + suffix + ".urdf"));
  }
  static std::vector<SimulatorExport*> both() { return {s_stove, s_sink}; }

  static fs::path* s_dir;
  static SimulatorExport* s_stove;
  static SimulatorExport* s_sink;
};
fs::path* OmniGibsonConformance::s_dir = nullptr;
SimulatorExport* OmniGibsonConformance::s_stove = nullptr;
SimulatorExport* OmniGibsonConformance::s_sink = nullptr;

std::vector<std::string> matches(const std::string& text, const std::string& pattern) {
  std::vector<std::string> found;
  const std::regex re(pattern);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    found.push_back((*it)[1].str());
  return found;
}

// import_custom_object.py, import_custom_object(): the model name is exactly 6 characters, all
// letters. The model names the folder <category>/<model>.
TEST_F(OmniGibsonConformance, ModelNameIsSixLetters) {
  for (const auto* e : both()) {
    EXPECT_TRUE(exportdetail::isOmniGibsonModelName(model(*e))) << model(*e);
    EXPECT_EQ(e->root.parent_path().filename(), e == s_stove ? "stove" : "sink");
  }
  EXPECT_EQ(model(*s_stove), "kitche");
}

// asset_conversion_utils.py, import_obj_metadata(): misc/metadata.json must hold bbox_size ("We
// cannot work without a bbox size"); base_link_offset is read (defaulting to 0); link_tags is
// iterated with .items(), so it must be an object.
// record_obj_metadata_from_urdf(): bbox_size is the extent of the object's axis-aligned bounding
// box, base_link_offset its centre relative to the base link; the file also carries meta_links,
// link_tags, object_parts and orientations.
TEST_F(OmniGibsonConformance, MetadataHoldsTheImportersKeys) {
  const json meta = metadata(*s_stove);
  ASSERT_TRUE(meta.contains("bbox_size"));
  EXPECT_EQ(meta["bbox_size"].size(), 3u);
  EXPECT_NEAR(meta["bbox_size"][0].get<double>(), 0.6, 1e-5);
  EXPECT_NEAR(meta["bbox_size"][1].get<double>(), 0.52, 1e-5);
  EXPECT_NEAR(meta["bbox_size"][2].get<double>(), 0.1, 1e-5);
  EXPECT_NEAR(meta["base_link_offset"][1].get<double>(), -0.01, 1e-5);
  EXPECT_NEAR(meta["base_link_offset"][2].get<double>(), 0.05, 1e-5);
  EXPECT_TRUE(meta["link_tags"].is_object());
  EXPECT_TRUE(meta["meta_links"].is_object());
  EXPECT_TRUE(meta["object_parts"].is_array());
  EXPECT_TRUE(meta["orientations"].is_array());
}

// asset_conversion_utils.py, _add_meta_links_to_urdf(): meta_links is {parent link: {type: {id:
// [entries]}}}; every type must be in _ALLOWED_META_TYPES (after _META_LINK_RENAME_MAPPING);
// dimensionless types other than attachment (heatsource, particlesource) take exactly one entry
// per id; each entry has a position and an orientation quaternion (x y z w, converted with
// quat2euler for the joint).
TEST_F(OmniGibsonConformance, MetaLinksShape) {
  const std::set<std::string> allowed = {"particlesource", "togglebutton",    "attachment",
                                         "heatsource",     "particleapplier", "particleremover",
                                         "particlesink",   "slicer",          "container",
                                         "collision",      "lights"};
  for (const auto* e : both()) {
    const json links = metadata(*e)["meta_links"];
    ASSERT_TRUE(links.contains("base_link"));
    for (const auto& [type, ids] : links["base_link"].items()) {
      EXPECT_TRUE(allowed.count(type)) << type;
      for (const auto& [id, entries] : ids.items()) {
        ASSERT_TRUE(entries.is_array());
        EXPECT_EQ(entries.size(), 1u) << type << " " << id;
        EXPECT_EQ(entries[0]["position"].size(), 3u);
        EXPECT_EQ(entries[0]["orientation"], json({0.0, 0.0, 0.0, 1.0}));
      }
    }
  }
  EXPECT_EQ(metadata(*s_stove)["meta_links"]["base_link"]["heatsource"].size(), 4u);
  EXPECT_EQ(metadata(*s_stove)["meta_links"]["base_link"]["togglebutton"].size(), 4u);
}

// import_obj_metadata(): a meta link prim name loses "meta__" and "_link" and is split with
// rsplit("_", 3) into parent link, type, id and sub-id (an int). So type, id and sub-id hold no
// underscore; our ids are digits. _add_meta_links_to_urdf() names the link
// meta__<parent>_<type>_<id>_<i>_link and its fixed joint <same>_joint.
TEST_F(OmniGibsonConformance, MetaLinkNamesSplitIntoFourParts) {
  const std::string withMeta = urdf(*s_stove, "_with_meta_links");
  const auto names = matches(withMeta, "<link name=\"(meta__[^\"]+)\"");
  ASSERT_EQ(names.size(), 8u);
  const std::regex shape("meta__base_link_([a-z]+)_([A-Za-z0-9]+)_([0-9]+)_link");
  for (const auto& name : names) {
    EXPECT_TRUE(std::regex_match(name, shape)) << name;
    const std::string stem = name.substr(0, name.size() - 5);
    EXPECT_NE(withMeta.find("<joint name=\"" + stem + "_joint\" type=\"fixed\">"),
              std::string::npos)
        << name;
  }
}

// _add_meta_links_to_urdf() appends a link and joint for every meta_links entry to the URDF it is
// given (<model>.urdf) and saves <model>_with_meta_links.urdf; it does not check for existing
// ones. So <model>.urdf carries none (else every meta link would be duplicated), and our
// _with_meta_links.urdf is what the importer produces, meta links with the mass 0.0001 and
// inertia 1e-5 of _create_urdf_meta_link().
TEST_F(OmniGibsonConformance, MetaLinksOnlyInTheWithMetaLinksUrdf) {
  for (const auto* e : both()) {
    EXPECT_EQ(urdf(*e).find("meta__"), std::string::npos);
    EXPECT_NE(urdf(*e, "_with_meta_links").find("<mass value=\"0.0001\"/>"), std::string::npos);
  }
}

// _generate_meshes_for_primitive_meta_links(): togglebutton is a primitive with exactly one mesh
// entry, whose "type" names the shape (sphere, box -> Cube, cylinder, cone) and "size" its size
// (a sphere's radius is size[0]).
TEST_F(OmniGibsonConformance, ToggleButtonIsAPrimitiveWithSize) {
  const json knob = metadata(*s_stove)["meta_links"]["base_link"]["togglebutton"]["0"][0];
  EXPECT_EQ(knob["type"], "sphere");
  ASSERT_EQ(knob["size"].size(), 3u);
  EXPECT_GT(knob["size"][0].get<double>(), 0.0);
}

// _generate_meshes_for_primitive_meta_links(): particlesource always becomes a cylinder of radius
// 0.0125 m and height 0.05 m offset by -height/2, hanging below the meta link's origin; particles
// leave along its -z, so the orientation is the identity for a downward stream.
// _META_LINK_RENAME_MAPPING renames the legacy "fluidsource" to "particlesource" (written with
// --legacy-fluidsource for OmniGibson from before the rename).
TEST_F(OmniGibsonConformance, FluidOutletIsTheParticleSourceCylinder) {
  const json links = metadata(*s_sink)["meta_links"]["base_link"];
  EXPECT_FALSE(links.contains("fluidsource"));
  const json source = links["particlesource"]["0"][0];
  EXPECT_EQ(source["type"], "cylinder");
  EXPECT_EQ(source["size"], json({0.0125, 0.0125, 0.05}));
  EXPECT_NEAR(source["position"][2].get<double>(), 0.5, 1e-6);  // the outlet itself
}

// generate_urdf_for_mesh(): urdf/<model>.urdf with robot name <model> and a base_link; collision
// meshes in shape/collision, each scaled to a unit bounding box with the extents as the URDF mesh
// scale (also get_collision_approximation_for_urdf(): "OmniGibson requires unit-bbox collision
// meshes", extents all > 0); the mesh file name starts with a letter ("Isaac Sim expects the
// filename to start with a letter").
TEST_F(OmniGibsonConformance, UrdfLayoutAndUnitBoxCollisionMeshes) {
  for (const auto* e : both()) {
    const std::string text = urdf(*e);
    EXPECT_NE(text.find("<robot name=\"" + model(*e) + "\">"), std::string::npos);
    EXPECT_NE(text.find("<link name=\"base_link\">"), std::string::npos);
    const auto files = matches(text, "<mesh filename=\"\\.\\./shape/collision/([^\"]+)\"");
    ASSERT_GE(files.size(), 1u);
    for (const auto& file : files) {
      EXPECT_TRUE(std::isalpha(static_cast<unsigned char>(file[0]))) << file;
      Eigen::AlignedBox3d box;
      std::istringstream obj(readFileBytes(e->root / "shape" / "collision" / file));
      std::string tag;
      double x, y, z;
      while (obj >> tag) {
        if (tag == "v" && obj >> x >> y >> z)
          box.extend(Eigen::Vector3d(x, y, z));
        else
          obj.ignore(1 << 20, '\n');
      }
      EXPECT_NEAR(box.sizes().maxCoeff(), 1.0, 1e-4) << file;
      EXPECT_NEAR(box.sizes().minCoeff(), 1.0, 1e-4) << file;
    }
    for (const auto& scale : matches(text,
                                     "<collision[^>]*>\\s*<origin[^>]*>\\s*<geometry><mesh "
                                     "filename=\"[^\"]+\" scale=\"([^\"]+)\"")) {
      std::istringstream s(scale);
      double a = 0, b = 0, c = 0;
      s >> a >> b >> c;
      EXPECT_GT(a, 0.0);
      EXPECT_GT(b, 0.0);
      EXPECT_GT(c, 0.0);
    }
  }
}

// generate_collision_meshes() -> simplify_convex_hull(): each collision hull has at most 60
// vertices, what Omniverse's GPU physics takes.
TEST_F(OmniGibsonConformance, CollisionHullsHaveAtMostSixtyVertices) {
  for (const auto& item : fs::directory_iterator(s_stove->root / "shape" / "collision")) {
    const std::string obj = readFileBytes(item.path());
    int vertices = 0;
    for (std::size_t at = obj.find("\nv "); at != std::string::npos; at = obj.find("\nv ", at + 1))
      ++vertices;
    EXPECT_LE(vertices, 60) << item.path();
    EXPECT_GE(vertices, 4) << item.path();
  }
}

// _force_asset_pipeline_materials(): a visual OBJ names at most one mtllib ("Only one mtl is
// supported per obj file in omniverse"), and each map_ line of the MTL splits on " " into exactly
// the map type and a path relative to the MTL's folder.
TEST_F(OmniGibsonConformance, VisualObjHasOneMtlWithPlainMapLines) {
  const fs::path visual = s_stove->root / "shape" / "visual";
  const std::string obj = readFileBytes(visual / (model(*s_stove) + "_base_link_visual.obj"));
  EXPECT_EQ(matches(obj, "(mtllib )").size(), 1u);
  const std::string mtl = readFileBytes(visual / (model(*s_stove) + "_base_link_visual.mtl"));
  for (const auto& line : matches(mtl, "\n(map_[^\n]*)")) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ' '), 1) << line;
    EXPECT_TRUE(fs::exists(visual / line.substr(line.find(' ') + 1))) << line;
  }
}

// URDF mass and inertia (import_og_asset_from_urdf(import_inertia_tensor=True) imports the URDF's
// own inertia): base_link carries an <inertial> with a positive mass.
TEST_F(OmniGibsonConformance, BaseLinkHasMassAndInertia) {
  for (const auto* e : both()) {
    const auto masses =
        matches(urdf(*e), "<link name=\"base_link\">[\\s\\S]*?<mass value=\"([^\"]+)\"");
    ASSERT_EQ(masses.size(), 1u);
    EXPECT_GT(std::stod(masses[0]), 0.0);
    EXPECT_NE(urdf(*e).find("<inertia ixx="), std::string::npos);
  }
}

// Controls that turn (DESIGN.md: revolute/prismatic links for OmniGibson): each of the stove's
// knobs is a child link of base_link on a revolute joint with limits and damping, its visual and
// collision meshes written; the meta links stay on base_link.
TEST_F(OmniGibsonConformance, KnobsAreRevoluteChildLinks) {
  const std::string text = urdf(*s_stove, "_with_meta_links");
  for (const char* loc : {"rear_left", "rear_right", "front_left", "front_right"}) {
    SCOPED_TRACE(loc);
    const std::string knob = std::string("knob_") + loc;
    const auto joint = matches(text, "<joint name=\"" + knob +
                                         "_joint\" type=\"revolute\">[\\s\\S]*?</joint>");
    ASSERT_EQ(joint.size(), 1u);
    EXPECT_NE(text.find("<child link=\"" + knob + "_link\"/>"), std::string::npos);
    EXPECT_NE(text.find("<link name=\"" + knob + "_link\">"), std::string::npos);
    EXPECT_TRUE(fs::exists(s_stove->root / "shape" / "visual" /
                           (model(*s_stove) + "_" + knob + "_link_visual.obj")));
    EXPECT_TRUE(fs::exists(s_stove->root / "shape" / "collision" /
                           (model(*s_stove) + "_" + knob + "_link_collision_0.obj")));
  }
  EXPECT_EQ(matches(text, "<limit lower=\"0\" upper=\"([^\"]+)\"").size(), 4u);
  EXPECT_EQ(matches(text, "<dynamics damping=\"([^\"]+)\"").size(), 4u);
  for (const auto& parent : matches(text, "meta__base_link_[a-z]+_\\d+_0_joint\"[^>]*>\\s*<origin[^>]*>\\s*<parent link=\"([^\"]+)\""))
    EXPECT_EQ(parent, "base_link");
}

// urdfdom's check_urdf (Debian liburdfdom-tools) parses both URDFs: one root link, every joint's
// links present.
TEST_F(OmniGibsonConformance, CheckUrdfAcceptsBothUrdfs) {
  if (test::runCommand("command -v check_urdf").exitCode != 0)
    GTEST_SKIP() << "check_urdf not installed (liburdfdom-tools; packaging/install_deps.sh)";
  for (const auto* e : both()) {
    for (const char* suffix : {"", "_with_meta_links"}) {
      const fs::path file = e->root / "urdf" / (model(*e) + suffix + ".urdf");
      const auto r = test::runCommand("check_urdf " + test::shellQuote(file.string()));
      EXPECT_EQ(r.exitCode, 0) << file << "\n" << r.output;
      EXPECT_NE(r.output.find("root Link: base_link"), std::string::npos) << r.output;
    }
  }
}

}  // namespace
}  // namespace sagrid
