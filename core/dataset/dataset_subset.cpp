#include "core/dataset/dataset_subset.h"

#include <nlohmann/json.hpp>
#include <string>

#include "core/common/atomic_file.h"

namespace sagrid {
namespace fs = std::filesystem;

fs::path folderHoldingFiles(const fs::path& dataDir, const std::vector<fs::path>& files) {
  fs::path root = fs::weakly_canonical(fs::absolute(dataDir));
  for (const auto& file : files) {
    const fs::path real = fs::weakly_canonical(fs::absolute(file));
    fs::path common;
    for (auto a = root.begin(), b = real.begin(); a != root.end() && b != real.end() && *a == *b;
         ++a, ++b)
      common /= *a;
    root = common;
  }
  return root;
}

void writeDatasetSubset(const fs::path& dir, const std::vector<const DatasetEntry*>& objects) {
  fs::create_directories(dir);
  const fs::path from = fs::weakly_canonical(fs::absolute(dir));
  auto relative = [&](const fs::path& file) {
    return fs::weakly_canonical(fs::absolute(file)).lexically_relative(from).generic_string();
  };
  std::string lines;
  for (const auto* o : objects)
    lines += nlohmann::json{{"id", o->id},
                            {"category", o->category},
                            {"mesh", relative(o->mesh)},
                            {"labels", relative(o->labels)}}
                 .dump() +
             "\n";
  writeFileAtomic(dir / "manifest.jsonl", lines);
}

}  // namespace sagrid
