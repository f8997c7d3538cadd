// Hand-built ASCII FBX 7.4 files for the FBX structure tests: one triangle under a hierarchy of
// Model objects linked by "OO" connections (assimp reads them).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sagrid::test {

using FbxLinks = std::vector<std::pair<int, int>>;  // child id, parent id (0 = the scene root)

// Models 100..100+models-1 linked by `links`; the triangle (object 1) hangs under `meshParent`.
std::string asciiFbx(int models, const FbxLinks& links, int meshParent);

// Models 100..100+depth-1, each the child of the one before.
FbxLinks fbxChain(int depth);

// A triangle under a chain of `depth` models.
inline std::string nestedAsciiFbx(int depth) {
  return asciiFbx(depth, fbxChain(depth), 99 + depth);
}

}  // namespace sagrid::test
