// Checks of an FBX file's structure before assimp parses it. Assimp's FBX converter walks the
// model hierarchy (Model objects linked by "OO" connections) recursively, once per path from a
// root: 20,000 nested models overflow the stack, and models with several parents are converted
// once per path. The binary reader also recurses into nested records. So the record nesting, the
// model hierarchy's depth and its number of root-to-model paths are bounded here, without
// recursion, and binary record offsets must stay inside the file and their parent record.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace sagrid {

// Most model instances (root-to-model paths) an FBX file may expand to.
inline constexpr std::size_t kMaxFbxModelPaths = 1000000;

// `bytes` hold a binary FBX ("Kaydara FBX Binary" header) or ASCII FBX. Throws FileError naming
// `path` when records or the model hierarchy nest deeper than kMaxSceneDepth, the models form a
// cycle or expand to more than kMaxFbxModelPaths instances, or a binary record lies outside the
// file or its parent.
void checkFbxStructure(std::string_view bytes, bool binary, const std::filesystem::path& path);

}  // namespace sagrid
