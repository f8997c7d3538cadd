// A tiny Sweet Home 3D furniture library (.sh3f) for corpus tests, so no test needs the Debian
// package: a stove (cooker, OBJ + MTL + texture in a sub-folder), a sink (OBJ + MTL + texture, with
// a "../" mtllib and an absolute map_Ka to be refused), an oven distractor (OBJ only, with a
// modelRotation), an unrelated chair, and a second "cooker" whose id collides after normalisation.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid::test {

struct SweetHome3dFixture {
  std::filesystem::path sh3f;  // <dir>/TestLib.sh3f
  std::string cookerObj, cookerMtl, cookerTexture, sinkObj, sinkMtl, sinkTexture, ovenObj;
};

// Cooker OBJ in cm (extent 60 x 90 x 50; catalog 60 wide, 50 deep, 90 high): 0.01 m per unit.
// Sink OBJ in m (extent 0.8 x 0.2 x 0.5; catalog 80 x 50 x 20): 1 m per unit.
SweetHome3dFixture writeSweetHome3dFixture(const std::filesystem::path& dir);

// labels.json for `id` whose object.sha256 is `sha256`, like the labeller ships.
std::string fixtureLabelsJson(const std::string& id, const std::string& mesh,
                              const std::string& sha256, const std::string& category);

}  // namespace sagrid::test
