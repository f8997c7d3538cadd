#include "support/fbx_files.h"

namespace sagrid::test {

std::string asciiFbx(int models, const FbxLinks& links, int meshParent) {
  std::string text =
      "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n"
      "\tFBXVersion: 7400\n}\nObjects:  {\n\tGeometry: 1, \"Geometry::tri\", \"Mesh\" {\n"
      "\t\tVertices: *9 {\n\t\t\ta: 0,0,0,1,0,0,0,1,0\n\t\t}\n"
      "\t\tPolygonVertexIndex: *3 {\n\t\t\ta: 0,1,-3\n\t\t}\n\t}\n";
  for (int m = 0; m < models; ++m)
    text += "\tModel: " + std::to_string(100 + m) + ", \"Model::n" + std::to_string(m) +
            "\", \"Null\" {\n\t\tShading: T ; a comment with { and \"\n\t}\n";
  text += "}\nConnections:  {\n";
  for (const auto& [child, parent] : links)
    text += "\tC: \"OO\", " + std::to_string(child) + ", " + std::to_string(parent) + "\n";
  text += "\tC: \"OO\", 1, " + std::to_string(meshParent) + "\n}\n";
  return text;
}

FbxLinks fbxChain(int depth) {
  FbxLinks links{{100, 0}};
  for (int m = 1; m < depth; ++m) links.push_back({100 + m, 99 + m});
  return links;
}

}  // namespace sagrid::test
