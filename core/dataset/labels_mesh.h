// Which mesh a labels.json describes, without letting the file choose where we read (issue 14).
//
// The containment rule for a labels file's object.mesh (and a manifest's mesh/labels fields,
// dataset.h): the reference is resolved with resolveContained (core/common/contained_paths.h):
// never an absolute path, a NUL byte, a name over 255 bytes or a link leading out, and
//  - by default it must stay inside the labels' own folder (what generate, the corpus, the
//    training-set export and the GUI write: a name beside labels.json);
//  - a caller may widen that to a root folder the USER named (never one named by data): then the
//    reference, taken relative to the labels' folder, may climb ("../") as long as it ends inside
//    that root. This is how `annotate --out OUT` output is read back: annotate writes object.mesh
//    relative to OUT/<id>/ (e.g. "../../data/x/mesh.glb"), and `export OUT --mesh-root data`
//    accepts it while an object.mesh of "../../../../etc/hostname" is still refused.
// Refusals are FileErrors naming the labels file, the reference and the folder it must lie in.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/labels/labels.h"

namespace sagrid {

// `reference` as written in `referencingFile`, relative to `folder` (the referencing file's
// folder), resolved inside `root` (empty: inside `folder` itself). See the rule above.
std::filesystem::path resolveReferenceWithin(const std::filesystem::path& folder,
                                             std::string_view reference,
                                             const std::filesystem::path& referencingFile,
                                             const std::filesystem::path& root = {});

// The mesh a labels file describes: object.mesh resolved by the rule above (`meshRoot` empty:
// inside the labels' folder), else the one mesh-like file beside labels.json (the first by name).
// Throws FileError naming `labelsPath` when the reference is refused or no mesh is found.
std::filesystem::path meshForLabels(const ObjectLabels& labels,
                                    const std::filesystem::path& labelsPath,
                                    const std::filesystem::path& meshRoot = {});

}  // namespace sagrid
