#include "core/annotate/category_training.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/dataset/object_source.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace fs = std::filesystem;

std::vector<CategorySample> collectCategorySamples(
    const fs::path& dataDir, const FeatureOptions& features,
    const std::set<std::string>& excludeIds,
    const std::function<void(std::size_t, std::size_t, const std::string&)>& onProgress,
    std::size_t* failed, const CategoryInputSet& inputs) {
  const auto entries = readDataset(dataDir);
  if (entries.empty()) throw InvalidArgument("dataset " + dataDir.string() + " has no objects");
  FeatureOptions options = features;
  if (options.cacheDir.empty()) options.cacheDir = dataDir / ".sagrid-cache";
  // "parent/folder" (bench/train, distractors/val): split names alone repeat across datasets.
  fs::path normal = fs::absolute(dataDir).lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  const std::string folder =
      (normal.parent_path().filename() / normal.filename()).generic_string();
  std::vector<CategorySample> out;
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const DatasetEntry& entry = entries[e];
    if (onProgress) onProgress(e, entries.size(), entry.id);
    if (excludeIds.count(entry.id)) continue;
    try {
      // Unlabelled folders (a manifest with categories, no labels.json yet) still train and
      // test the category; their up axis is then the caller's features.up.
      const ObjectLabels labels =
          fs::exists(entry.labels) ? readLabels(entry.labels) : ObjectLabels{};
      CategorySample s;
      s.id = entry.id;
      s.category = entry.category.empty() ? labels.object.category : entry.category;
      s.group = folder;
      s.source = objectSource(labels, entry.mesh, folder);
      const auto generator = labels.object.extra.find("generator");
      if (categoryClass(s.category) == kRejectedCategory && generator != labels.object.extra.end() &&
          generator->is_object() && generator->contains("kind"))
        s.group += "/" + generator->at("kind").get<std::string>();
      FeatureOptions objectFeatures = options;
      // The labels say how the file was written (Sweet Home 3D OBJs are y-up); unset = the
      // importer's default for the format.
      if (!labels.object.up.empty()) objectFeatures.up = parseUpAxis(labels.object.up);
      // The parts are read from the mesh in the frame its features were computed in.
      const FeatureGrid grid = extractFeatures(entry.mesh, objectFeatures);
      const Mesh mesh = inputs.partStatistics
                            ? importMesh(entry.mesh, ImportOptions(objectFeatures.up))
                            : Mesh{};
      s.descriptor = categoryInputs(grid, mesh, inputs);
      s.mesh = entry.mesh;
      s.up = labels.object.up;
      s.featureCache = options.cacheDir;
      s.nameWords = fileNameWords(entry.mesh);
      // A curated file keeps its publisher's name; a generated one is "mesh.glb" whatever it is.
      s.publishedName = !labels.object.sha256.empty() && generator == labels.object.extra.end();
      out.push_back(std::move(s));
    } catch (const Error& err) {
      logger()->warn("category data: skipping {}: {}", entry.id, err.what());
      if (failed) ++*failed;
    }
  }
  if (onProgress) onProgress(entries.size(), entries.size(), "");
  return out;
}

std::map<std::string, int> assignFolds(const std::vector<std::string>& ids, int folds) {
  if (folds < 1) throw InvalidArgument("folds must be at least 1, got " + std::to_string(folds));
  std::vector<std::pair<std::string, std::string>> keyed;
  for (const auto& id : ids) keyed.emplace_back(sha256Hex(id), id);
  std::sort(keyed.begin(), keyed.end());
  std::map<std::string, int> fold;
  for (std::size_t i = 0; i < keyed.size(); ++i)
    fold[keyed[i].second] = static_cast<int>(i % static_cast<std::size_t>(folds));
  return fold;
}

IdSplit splitIds(const std::vector<std::string>& ids) {
  IdSplit split;
  for (const auto& [id, fold] : assignFolds(ids, 3))
    (fold == 2 ? split.val : split.train).insert(id);
  return split;
}

void writeIdSplit(const IdSplit& split, const fs::path& file, const std::string& source) {
  nlohmann::json j;
  j["source"] = source;
  j["rule"] = "ids ordered by sha256(id); every third (index % 3 == 2) is val, the rest train";
  j["train"] = std::vector<std::string>(split.train.begin(), split.train.end());
  j["val"] = std::vector<std::string>(split.val.begin(), split.val.end());
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  writeFileAtomic(file, j.dump(1) + "\n");
}

IdSplit readIdSplit(const fs::path& file) {
  const std::string text = readFileBytes(file);
  try {
    const auto j = nlohmann::json::parse(text);
    IdSplit split;
    for (const auto& id : j.at("train")) split.train.insert(id.get<std::string>());
    for (const auto& id : j.at("val")) split.val.insert(id.get<std::string>());
    return split;
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, std::string("malformed id split (expected {\"train\": [...], \"val\": "
                                      "[...]}): ") + e.what());
  }
}

CategoryEvaluation evaluateCategories(
    const std::function<CategoryDecision(const CategorySample&)>& decide,
    const std::vector<CategorySample>& samples) {
  CategoryEvaluation ev;
  for (const auto& s : samples) {
    const std::string truth = categoryClass(s.category);
    const CategoryDecision d = decide(s);
    const bool right = d.category == truth;
    auto& c = ev.byClass[truth];
    ++c.total, c.right += right;
    auto& g = ev.byGroup[s.group + " (" + truth + ")"];
    ++g.total, g.right += right;
    ++ev.confusion[truth][d.category];
    if (!right) ev.misses.push_back({s.id, s.group, truth, d.category, d.score, d.best});
  }
  return ev;
}

std::string categoryEvaluationTable(const CategoryEvaluation& ev) {
  std::ostringstream out;
  char line[256];
  auto row = [&](const std::string& name, const CategoryEvaluation::Count& c) {
    std::snprintf(line, sizeof(line), "| %s | %d | %d | %.1f %% |\n", name.c_str(), c.total, c.right,
                  c.total ? 100.0 * c.right / c.total : 0.0);
    out << line;
  };
  out << "| class | objects | right | share |\n|---|---:|---:|---:|\n";
  for (const char* cls : {"stove", "sink", "none"}) {
    const auto it = ev.byClass.find(cls);
    if (it == ev.byClass.end()) continue;
    row(std::string(cls) == "none" ? "distractors rejected" : std::string(cls) + "s right", it->second);
  }
  out << "\n| group | objects | right | share |\n|---|---:|---:|---:|\n";
  for (const auto& [name, c] : ev.byGroup) row(name, c);
  out << "\n| true \\ predicted | stove | sink | none |\n|---|---:|---:|---:|\n";
  for (const auto& [truth, predictions] : ev.confusion) {
    const auto& predicted = predictions;  // C++17 lambdas cannot capture bindings (clang)
    auto get = [&](const char* p) {
      const auto it = predicted.find(p);
      return it == predicted.end() ? 0 : it->second;
    };
    std::snprintf(line, sizeof(line), "| %s | %d | %d | %d |\n", truth.c_str(), get("stove"),
                  get("sink"), get("none"));
    out << line;
  }
  if (!ev.misses.empty()) {
    out << "\n| wrong: object | group | true | predicted | best known category (probability) |\n"
           "|---|---|---|---|---|\n";
    for (const auto& m : ev.misses) {
      std::snprintf(line, sizeof(line), "| %s | %s | %s | %s | %s (%.2f) |\n", m.id.c_str(),
                    m.group.c_str(), m.truth.c_str(), m.predicted.c_str(), m.best.c_str(), m.score);
      out << line;
    }
  }
  return out.str();
}

double balancedShareRight(const CategoryEvaluation& evaluation) {
  double sum = 0;
  int classes = 0;
  for (const auto& [cls, count] : evaluation.byClass) {
    if (count.total == 0) continue;
    sum += static_cast<double>(count.right) / count.total;
    ++classes;
  }
  return classes ? sum / classes : 0.0;
}

PairedChange pairedCategoryChange(const CategoryEvaluation& current,
                                  const CategoryEvaluation& candidate) {
  // Objects both decided rightly are not listed anywhere: the class totals count them.
  std::map<std::string, std::map<std::string, ObjectFigures>> wrong;  // class -> object -> figures
  const auto key = [](const CategoryEvaluation::Miss& m) { return m.group + "\n" + m.id; };
  for (const auto& m : current.misses) wrong[m.truth][key(m)].current = 1;
  for (const auto& m : candidate.misses) wrong[m.truth][key(m)].candidate = 1;
  std::vector<std::vector<ObjectFigures>> classes;
  for (const auto& [cls, count] : candidate.byClass) {
    std::vector<ObjectFigures> objects;
    if (const auto it = wrong.find(cls); it != wrong.end())
      for (const auto& [object, figures] : it->second) objects.push_back(figures);
    objects.resize(std::max<std::size_t>(objects.size(), count.total), ObjectFigures{0, 0});
    classes.push_back(std::move(objects));
  }
  return pairedChange(classes);
}

}  // namespace sagrid
