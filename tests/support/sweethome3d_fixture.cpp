#include "support/sweethome3d_fixture.h"

#include <nlohmann/json.hpp>
#include <vector>

#include "core/io/zip_archive.h"

namespace sagrid::test {
namespace fs = std::filesystem;

namespace {

std::string box(double x, double y, double z, const std::string& header) {
  std::string obj = header;
  for (int i = 0; i < 8; ++i) {
    obj += "v " + std::to_string(i & 1 ? x : 0.0) + " " + std::to_string(i & 2 ? y : 0.0) + " " +
           std::to_string(i & 4 ? z : 0.0) + "\n";
  }
  obj += "f 1 2 4 3\nf 5 6 8 7\nf 1 2 6 5\nf 3 4 8 7\nf 1 3 7 5\nf 2 4 8 6\n";
  return obj;
}

}  // namespace

SweetHome3dFixture writeSweetHome3dFixture(const fs::path& dir) {
  SweetHome3dFixture f;
  f.cookerObj = box(60, 90, 50, "# cooker\nmtllib cooker.mtl\nusemtl hob\n");
  f.cookerMtl = "newmtl hob\nKd 0.2 0.2 0.2\nmap_Kd -s 1 1 1 textures/cooker.png\n";
  static const char png[] = "\x89PNG\r\n\x1a\n\0\xff\xfe cooker";
  f.cookerTexture = std::string(png, sizeof(png) - 1);
  f.sinkObj = box(0.8, 0.2, 0.5, "mtllib ../shared.mtl sink.mtl\r\n");
  f.sinkMtl = "newmtl steel\r\nmap_Kd sink.jpg\r\nmap_Ka /home/someone/steel.png\r\n";
  static const char jpg[] = "\xff\xd8\xff\xe0 sink\0jpg";
  f.sinkTexture = std::string(jpg, sizeof(jpg) - 1);
  f.ovenObj = box(2, 3, 4, "");
  // ISO-8859-1 byte \xe9 and a \u escape in the library name; comments and a continuation line.
  const std::string properties =
      "# PluginFurnitureCatalog.properties\n"
      "id=Test#Library\n"
      "name=Test biblioth\xe8que \\u00e9\n"
      "license=Public domain\n"
      "\n"
      "id#1=Test Lib#cooker\nname#1=Cooker\ncategory#1=Kitchen\ncreator#1=Alice\n"
      "model#1=/testlib/cooker/cooker.obj\nwidth#1=60\ndepth#1=50\nheight#1=90\n\n"
      "id#2=Test Lib#sink\nname#2=Kitchen \\\n    sink\ncategory#2=Kitchen\ncreator#2=Bob\n"
      "model#2=/testlib/sink/sink.obj\nwidth#2=80\ndepth#2=50\nheight#2=20\n\n"
      "id#3=Test Lib#oven\nname#3=Small oven\ncategory#3=Kitchen\ncreator#3=Carol\n"
      "model#3=/testlib/oven/oven.obj\nwidth#3=40\ndepth#3=30\nheight#3=20\n"
      "modelRotation#3=1 0 0 0 0 1 0 -1 0\n\n"
      "id#4=Test Lib#chair\nname#4=Chair\ncategory#4=Living "
      "room\nmodel#4=/testlib/chair/chair.obj\n"
      "width#4=40\ndepth#4=40\nheight#4=90\n\n"
      "id#5=Test-Lib#Cooker\nname#5=Cooker\ncategory#5=Kitchen\n"
      "model#5=/testlib/cooker/cooker.obj\nwidth#5=60\ndepth#5=50\nheight#5=90\n";
  const std::vector<std::pair<std::string, std::string>> entries = {
      {"PluginFurnitureCatalog.properties", properties},
      {"testlib/", ""},
      {"testlib/cooker/cooker.obj", f.cookerObj},
      {"testlib/cooker/cooker.mtl", f.cookerMtl},
      {"testlib/cooker/textures/cooker.png", f.cookerTexture},
      {"testlib/sink/sink.obj", f.sinkObj},
      {"testlib/sink/sink.mtl", f.sinkMtl},
      {"testlib/sink/sink.jpg", f.sinkTexture},
      {"testlib/shared.mtl", "newmtl outside\n"},
      {"testlib/oven/oven.obj", f.ovenObj},
      {"testlib/chair/chair.obj", box(1, 1, 1, "")},
  };
  fs::create_directories(dir);
  f.sh3f = dir / "TestLib.sh3f";
  writeStoredZip(f.sh3f, entries);
  return f;
}

std::string fixtureLabelsJson(const std::string& id, const std::string& mesh,
                              const std::string& sha256, const std::string& category) {
  nlohmann::json j = {{"schema", "sagrid.labels/1"},
                      {"object",
                       {{"id", id},
                        {"mesh", mesh},
                        {"sha256", sha256},
                        {"category", category},
                        {"up", "y"},
                        {"meters_per_unit", 0.01}}},
                      {"affordances", nlohmann::json::array({{{"type", "heatsource"},
                                                              {"position", {10.0, 90.0, 20.0}},
                                                              {"status", "added"},
                                                              {"source", "human"}}})},
                      {"review", {{"state", "done"}, {"updated", "2026-11-23T12:00:00Z"}}}};
  return j.dump(2) + "\n";
}

}  // namespace sagrid::test
