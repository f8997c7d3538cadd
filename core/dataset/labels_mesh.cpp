#include "core/dataset/labels_mesh.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>
#include <vector>

#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

bool isAbsoluteReference(const std::string& text) {
  return !text.empty() && (text.front() == '/' || text.front() == '\\' ||
                           (text.size() >= 2 && std::isalpha(static_cast<unsigned char>(text[0])) &&
                            text[1] == ':'));
}

}  // namespace

fs::path resolveReferenceWithin(const fs::path& folder, std::string_view reference,
                                const fs::path& referencingFile, const fs::path& root) {
  const fs::path base = folder.empty() ? fs::path(".") : folder;
  std::string text(reference);
  try {
    return resolveContained(base, text, referencingFile);  // inside the folder: always fine
  } catch (const FileError&) {
    // Absolute paths, NUL bytes and empty names are refused whatever the root.
    if (root.empty() || text.empty() || isAbsoluteReference(text) ||
        text.find('\0') != std::string::npos)
      throw;
  }
  std::replace(text.begin(), text.end(), '\\', '/');
  const fs::path target = (fs::absolute(base) / fs::path(text)).lexically_normal();
  const fs::path inRoot = target.lexically_relative(fs::absolute(root).lexically_normal());
  // A target outside the root comes out as "../...": resolveContained refuses it.
  try {
    return resolveContained(root, inRoot.empty() ? ".." : inRoot.generic_string(),
                            referencingFile);
  } catch (const FileError&) {  // the same refusal, showing the reference as the file wrote it
    throw FileError(referencingFile,
                    "refusing the referenced file '" + std::string(reference.substr(0, 120)) +
                        "': it leads outside " + root.string() +
                        " (a name over 255 bytes or a link leading out counts too)");
  }
}

fs::path meshForLabels(const ObjectLabels& labels, const fs::path& labelsPath,
                       const fs::path& meshRoot) {
  const fs::path dir = labelsPath.parent_path().empty() ? fs::path(".") : labelsPath.parent_path();
  if (!labels.object.mesh.empty())
    return resolveReferenceWithin(dir, labels.object.mesh, labelsPath, meshRoot);
  std::error_code ec;
  std::vector<fs::path> items;
  for (const auto& item : fs::directory_iterator(dir, ec)) items.push_back(item.path());
  std::sort(items.begin(), items.end());  // the same mesh every run
  for (const auto& path : items)
    if (isMeshFile(path)) return path;
  throw FileError(labelsPath, "no mesh named in object.mesh and none found beside it");
}

}  // namespace sagrid
