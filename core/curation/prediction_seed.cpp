#include "core/curation/prediction_seed.h"

#include <system_error>

#include "core/common/error.h"
#include "core/dataset/labels_mesh.h"
#include "core/labels/labels.h"

namespace sagrid {
namespace fs = std::filesystem;

std::size_t seedPredictions(const fs::path& predictions, const fs::path& meshRoot,
                            const std::function<fs::path(const fs::path&)>& labelsPathFor) {
  if (!fs::is_directory(predictions)) throw FileError(predictions, "predictions folder not found");
  std::size_t written = 0;
  for (const auto& entry : fs::directory_iterator(predictions)) {
    const fs::path file = entry.path() / "labels.json";
    std::error_code ec;
    if (!entry.is_directory(ec) || !fs::is_regular_file(file, ec)) continue;
    ObjectLabels labels = readLabels(file);
    const fs::path mesh = meshForLabels(labels, file, meshRoot);
    labels.object.mesh = mesh.filename().string();
    writeLabels(labelsPathFor(mesh), labels);
    ++written;
  }
  return written;
}

}  // namespace sagrid
