#include "core/corpus/wild_pool_corpus.h"

#include <algorithm>
#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/common/staged_folder.h"
#include "core/io/json_file.h"
#include "core/labels/labels.h"

namespace sagrid {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string textField(const json& object, const char* key, const fs::path& file) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_string() || it->get<std::string>().empty()) {
    throw FileError(file, std::string("has no text field '") + key + "'");
  }
  return it->get<std::string>();
}

WildPoolObject readPoolObject(const fs::path& folder) {
  WildPoolObject object;
  object.id = folder.filename().string();
  object.folder = folder;
  const fs::path provenanceFile = folder / "provenance.json";
  if (!fs::is_regular_file(provenanceFile)) {
    throw FileError(folder, "wild-pool object " + object.id + " has no provenance.json");
  }
  object.provenance = parseJsonDocument(readFileBytes(provenanceFile), provenanceFile);
  if (!object.provenance.is_object()) throw FileError(provenanceFile, "is not a JSON object");
  object.repo = textField(object.provenance, "repo", provenanceFile);
  object.kind = object.provenance.value("kind", std::string());
  object.sha256 = textField(object.provenance, "sha256", provenanceFile);
  const std::string committedPath = textField(object.provenance, "path", provenanceFile);
  object.mesh = resolveContained(folder, fs::path(committedPath).filename().string(), provenanceFile);
  if (!fs::is_regular_file(object.mesh)) {
    throw FileError(object.mesh, "wild-pool object " + object.id + ": its mesh is missing");
  }
  const std::string sha = sha256Hex(readFileBytes(object.mesh));
  if (sha != object.sha256) {
    throw FileError(object.mesh, "wild-pool object " + object.id + ": the mesh's sha256 is " + sha +
                                     " but its provenance records " + object.sha256 +
                                     " (the file changed since it was catalogued)");
  }
  return object;
}

// The object's files as the pool holds them (the mesh and what it references); the pool's
// preview render stays behind.
void copyObjectFiles(const WildPoolObject& object, const fs::path& to) {
  fs::create_directories(to);
  for (const auto& entry : fs::directory_iterator(object.folder)) {
    const std::string name = entry.path().filename().string();
    if (name == "look.png") continue;
    fs::copy(entry.path(), to / name, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  }
}

}  // namespace

std::vector<WildPoolObject> readWildPool(const fs::path& pool) {
  if (!fs::is_directory(pool)) throw FileError(pool, "wild pool folder not found");
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(pool))
    if (entry.is_directory()) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  std::vector<WildPoolObject> objects;
  for (const auto& folder : folders) objects.push_back(readPoolObject(folder));
  if (objects.empty()) throw FileError(pool, "holds no object folders");
  return objects;
}

std::map<std::string, std::string> readWildSplit(const fs::path& splitFile) {
  const json split = parseJsonDocument(readFileBytes(splitFile), splitFile);
  std::map<std::string, std::string> byRepo;
  for (const char* dataset : {"wild-train", "wild-val"}) {
    const auto it = split.find(dataset);
    if (it == split.end() || !it->is_array()) {
      throw FileError(splitFile, std::string("expected {\"wild-train\": [repositories], \"wild-val\": [...]}; '") +
                                     dataset + "' is missing or not a list");
    }
    for (const auto& repo : *it) {
      if (!repo.is_string()) throw FileError(splitFile, std::string("'") + dataset + "' lists a non-text entry");
      if (!byRepo.emplace(repo.get<std::string>(), dataset).second) {
        throw FileError(splitFile, "repository " + repo.get<std::string>() + " is in both datasets");
      }
    }
  }
  return byRepo;
}

WildCorpusSummary buildWildCorpus(const WildCorpusOptions& options) {
  const std::vector<WildPoolObject> objects = readWildPool(options.pool);
  const fs::path splitFile = options.labelsDir / "split.json";
  const std::map<std::string, std::string> split =
      fs::is_regular_file(splitFile) ? readWildSplit(splitFile) : std::map<std::string, std::string>{};
  WildCorpusSummary summary;
  requireReplaceableFolder(options.out, "corpus.json");
  StagedFolder staged(options.out);
  std::map<std::string, std::string> manifests{{"wild-train", ""}, {"wild-val", ""}, {"unlabelled", ""}};
  json listing = json::array();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const WildPoolObject& object = objects[i];
    if (options.progress) options.progress(i, objects.size(), object.id);
    const fs::path curated = options.labelsDir / object.id / "labels.json";
    std::string dataset = "unlabelled";
    std::string category;
    std::optional<ObjectLabels> labels;
    if (fs::is_regular_file(curated)) {
      labels = readLabels(curated);
      if (labels->object.sha256 != object.sha256) {
        throw FileError(curated, "wild-pool object " + object.id + ": object.sha256 " + labels->object.sha256 +
                                     " does not match the pool's mesh (" + object.sha256 +
                                     "); the mesh changed, so these labels need curating again");
      }
      category = labels->object.category;
      const auto placed = split.find(object.repo);
      if (placed != split.end()) {
        dataset = placed->second;
      } else {
        summary.warnings.push_back(object.id + ": repository " + object.repo +
                                   " is in neither wild-train nor wild-val of split.json; left unlabelled");
      }
    }
    const fs::path objectDir = staged.path() / dataset / object.id;
    copyObjectFiles(object, objectDir);
    const std::string meshName = object.mesh.filename().string();
    json line{{"id", object.id}, {"mesh", object.id + "/" + meshName}, {"source", object.repo}};
    if (labels && dataset != "unlabelled") {
      labels->object.mesh = meshName;
      labels->object.extra["source"] = "wild-pool";
      labels->object.extra["provenance"] = object.provenance;
      writeLabels(objectDir / "labels.json", *labels);
      line["category"] = category;
      line["labels"] = object.id + "/labels.json";
      ++summary.countsByCategory[category];
    }
    manifests[dataset] += line.dump() + "\n";
    ++summary.countsByDataset[dataset];
    listing.push_back({{"id", object.id}, {"repo", object.repo}, {"kind", object.kind}, {"dataset", dataset},
                       {"category", category.empty() ? json(nullptr) : json(category)}});
  }
  if (options.progress) options.progress(objects.size(), objects.size(), "");
  for (const auto& [dataset, text] : manifests) {
    fs::create_directories(staged.path() / dataset);
    writeFileAtomic(staged.path() / dataset / "manifest.jsonl", text);
  }
  json corpus{{"source", "wild pool: appliance meshes from public repositories, as committed"},
              {"pool", fs::absolute(options.pool).lexically_normal().string()},
              {"counts_by_dataset", summary.countsByDataset},
              {"counts_by_category", summary.countsByCategory},
              {"objects", listing},
              {"warnings", summary.warnings}};
  writeFileAtomic(staged.path() / "corpus.json", corpus.dump(2) + "\n");
  staged.commit();
  return summary;
}

}  // namespace sagrid
