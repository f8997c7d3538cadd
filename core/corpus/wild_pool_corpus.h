// The wild pool (shared/data/wild-pool, issue 41): appliance meshes taken from public
// repositories exactly as committed, one folder each with the mesh, every file it references and
// provenance.json (repo, commit, path, kind, licence, sha256, bytes). Meshes never enter this
// repository: curated labels live in resources/datasets/wild/<id>/labels.json, keyed by the mesh's
// sha256, with the pool's provenance; split.json assigns whole repositories to wild-train or
// wild-val. `sagrid corpus wild` joins the two into datasets the other tools read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sagrid {

struct WildPoolObject {
  std::string id;  // the pool folder's name, e.g. "kenney_cco__kitchen_stove"
  std::filesystem::path folder;
  std::filesystem::path mesh;  // inside folder
  std::string repo;            // "owner/name": the source of leave-one-source-out evaluation
  std::string kind;            // as first judged from a picture: "stove", "fridge", ...
  std::string sha256;
  nlohmann::json provenance;   // provenance.json as the pool has it
};

// Every object folder of the pool, sorted by id. Throws FileError naming the object for a missing
// or malformed provenance.json, a mesh that is missing, or whose bytes no longer have the sha256
// the provenance records (the file changed since it was catalogued).
std::vector<WildPoolObject> readWildPool(const std::filesystem::path& pool);

// split.json: repository -> "wild-train" | "wild-val".
std::map<std::string, std::string> readWildSplit(const std::filesystem::path& splitFile);

struct WildCorpusOptions {
  std::filesystem::path pool;
  std::filesystem::path out;
  std::filesystem::path labelsDir;  // <id>/labels.json and split.json
  std::function<void(std::size_t, std::size_t, const std::string&)> progress;
};

struct WildCorpusSummary {
  std::map<std::string, int> countsByDataset;   // wild-train, wild-val, unlabelled
  std::map<std::string, int> countsByCategory;  // of labelled objects: stove, sink, none
  std::vector<std::string> warnings;
};

// Writes OUT/wild-train, OUT/wild-val (curated objects of the split's repositories) and
// OUT/unlabelled (the rest), each object a folder with the pool's files as committed,
// provenance.json and, where curated, labels.json with object.source "wild-pool" and
// object.provenance; manifest.jsonl per dataset and OUT/corpus.json. Built in a staging folder and
// swapped into place. Throws FileError naming the object when curated labels' object.sha256 does
// not match the pool's mesh.
WildCorpusSummary buildWildCorpus(const WildCorpusOptions& options);

}  // namespace sagrid
