#include "core/eval/learning_curve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/report_cell.h"
#include "core/dataset/dataset.h"
#include "core/dataset/dataset_subset.h"
#include "core/dataset/object_source.h"
#include "core/eval/evaluation.h"
#include "core/eval/sample_stats.h"
#include "core/labels/labels.h"
#include "core/model/model_card.h"
#include "core/model/model_files.h"
#include "core/plot/plot.h"
#include "core/training/dataset_training.h"
#include "core/training/guarded_update.h"

namespace sagrid {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kDefaultEpochs = 5;

struct RealObject {
  DatasetEntry entry;
  std::string category;
  std::set<std::string> types;
  std::string source;
};

std::string kLabel(int k) { return k == kAllObjects ? "all" : std::to_string(k); }

// The folder that holds every object of --data where it really is (folderHoldingFiles); the
// subsets are read with it as readDataset's referenceRoot, so they reach exactly the objects
// --data listed.
fs::path folderHoldingObjects(const fs::path& dataDir, const std::vector<RealObject>& objects) {
  std::vector<fs::path> files;
  for (const auto& o : objects) files.push_back(o.entry.mesh), files.push_back(o.entry.labels);
  return folderHoldingFiles(dataDir, files);
}

void writeSubsetDataset(const fs::path& dir, const std::vector<const RealObject*>& objects) {
  std::vector<const DatasetEntry*> entries;
  for (const auto* o : objects) entries.push_back(&o->entry);
  writeDatasetSubset(dir, entries);
}

struct Stats {
  double mean = NAN, sd = NAN, kUsed = 0;
  int folds = 0;
};

Stats statsOf(const LearningCurveReport& r, const std::string& model, int k) {
  Stats s;
  std::vector<double> values;
  double kSum = 0;
  for (const auto& p : r.points)
    if (p.model == model && p.k == k && p.testObjects > 0 && std::isfinite(p.paperError)) {
      values.push_back(p.paperError);
      kSum += p.kUsed;
    }
  s.folds = static_cast<int>(values.size());
  if (values.empty()) return s;
  s.kUsed = kSum / values.size();
  const SampleStats spread = sampleStats(values);
  s.mean = spread.mean;
  s.sd = spread.sd;
  return s;
}

// The models' mean errors at k averaged over the models measured both at k and at the first k
// asked for (k = 0, the init models, in the default --ks), and that average's ratio to the same
// models' average at the first k: "does fixing k objects pay?" in one number.
struct Overall {
  double mean = NAN, ratio = NAN;
  int models = 0;
};

Overall overallAt(const LearningCurveReport& r, int k) {
  Overall o;
  if (r.ks.empty()) return o;
  double sum = 0, baseSum = 0;
  for (const auto& model : r.modelNames) {
    const Stats s = statsOf(r, model, k), base = statsOf(r, model, r.ks.front());
    if (!std::isfinite(s.mean) || !std::isfinite(base.mean)) continue;
    sum += s.mean, baseSum += base.mean, ++o.models;
  }
  if (o.models == 0) return o;
  o.mean = sum / o.models;
  if (baseSum > 0) o.ratio = sum / baseSum;
  return o;
}

}  // namespace

std::vector<std::vector<std::size_t>> kFoldSplit(std::size_t count, int folds, unsigned seed,
                                                 const std::vector<std::string>& groups) {
  if (count < 2 || folds < 2)
    throw InvalidArgument("learning curve: k-fold needs at least 2 objects and 2 folds (got " +
                          std::to_string(count) + " objects, " + std::to_string(folds) +
                          " folds)");
  if (!groups.empty() && groups.size() != count)
    throw InvalidArgument("learning curve: " + std::to_string(groups.size()) +
                          " group labels for " + std::to_string(count) + " objects");
  const std::size_t f = std::min<std::size_t>(static_cast<std::size_t>(folds), count);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  // Stable by group: the shuffled order within each group, groups one after another; dealing
  // that sequence round-robin spreads each group evenly and keeps fold sizes within one.
  if (!groups.empty()) {
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return groups[a] < groups[b]; });
  }
  std::vector<std::vector<std::size_t>> result(f);
  for (std::size_t i = 0; i < count; ++i) result[i % f].push_back(order[i]);
  return result;
}

std::vector<std::vector<std::size_t>> sourceFoldSplit(const std::vector<std::string>& sources,
                                                      int folds, unsigned seed) {
  std::map<std::string, std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < sources.size(); ++i) members[sources[i]].push_back(i);
  if (members.size() < 2 || folds < 2)
    throw InvalidArgument("learning curve by source: needs at least 2 sources and 2 folds (got " +
                          std::to_string(members.size()) + " sources, " + std::to_string(folds) +
                          " folds)");
  std::vector<const std::vector<std::size_t>*> order;
  for (const auto& [source, indices] : members) order.push_back(&indices);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  std::stable_sort(order.begin(), order.end(),
                   [](const auto* a, const auto* b) { return a->size() > b->size(); });
  std::vector<std::vector<std::size_t>> result(
      std::min<std::size_t>(static_cast<std::size_t>(folds), members.size()));
  for (const auto* indices : order) {
    auto smallest = std::min_element(result.begin(), result.end(),
                                     [](const auto& a, const auto& b) { return a.size() < b.size(); });
    smallest->insert(smallest->end(), indices->begin(), indices->end());
  }
  return result;
}

namespace {
// A guarded learning curve's fold: the training folds' objects split into those the fine-tunes
// draw from (in their order) and the guard set (one of four source groups of them; none when
// they come from one source).
std::pair<std::vector<const RealObject*>, std::vector<const RealObject*>> splitOffGuardSet(
    const std::vector<const RealObject*>& pool, unsigned seed) {
  std::vector<std::string> sources;
  for (const auto* o : pool) sources.push_back(o->source);
  if (std::set<std::string>(sources.begin(), sources.end()).size() < 2) return {pool, {}};
  const auto groups = sourceFoldSplit(sources, 4, seed);
  const std::set<std::size_t> guard(groups.back().begin(), groups.back().end());
  std::vector<const RealObject*> fineTune, held;
  for (std::size_t i = 0; i < pool.size(); ++i) (guard.count(i) ? held : fineTune).push_back(pool[i]);
  return {fineTune, held};
}
}  // namespace

std::vector<int> parseLearningCurveKs(const std::string& text) {
  std::vector<int> ks;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item == "all") {
      ks.push_back(kAllObjects);
      continue;
    }
    char* end = nullptr;
    const long k = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || k < 0)
      throw InvalidArgument("--ks: \"" + item +
                            "\" is not a count of objects (expected e.g. 0,2,5,10,all)");
    ks.push_back(static_cast<int>(k));
  }
  if (ks.empty()) throw InvalidArgument("--ks: no values (expected e.g. 0,2,5,10,all)");
  return ks;
}

LearningCurveReport runLearningCurve(const LearningCurveOptions& options) {
  auto say = [&](const std::string& line) {
    if (options.onMessage) options.onMessage(line);
  };
  std::vector<RealObject> objects;
  for (const auto& e : readDataset(options.dataDir)) {
    const ObjectLabels labels = readLabels(e.labels);
    RealObject o{e, e.category, {}, objectSource(labels, e.mesh, options.dataDir.filename().string())};
    if (o.category.empty()) o.category = labels.object.category;
    o.entry.category = o.category;  // what a subset's manifest says
    for (const auto& a : labels.affordances) o.types.insert(a.type);
    objects.push_back(std::move(o));
  }
  const fs::path objectsRoot = folderHoldingObjects(options.dataDir, objects);
  LearningCurveReport report;
  report.dataDir = options.dataDir;
  report.initDir = options.initDir;
  report.seed = options.seed;
  report.ks = options.ks;
  report.replay = options.replay;
  report.adapted = options.adapted;
  report.keepInitNetworks = options.keepInitNetworks;
  report.guarded = options.guarded;
  report.epochs = options.epochs > 0 || options.minutes > 0 ? options.epochs : kDefaultEpochs;
  report.minutes = options.minutes;

  // The models: those asked for, else every init model with objects of its type in the data.
  std::set<std::string> available;
  for (const auto& card : model::listModelCards(options.initDir))
    available.insert(card.stem().string());
  auto hasObjects = [&](const std::string& name) {
    const auto [category, type] = model::splitModelName(name);
    for (const auto& o : objects)
      if (o.category == category && o.types.count(type)) return true;
    return false;
  };
  if (options.modelNames.empty()) {
    for (const auto& name : available)
      if (hasObjects(name)) report.modelNames.push_back(name);
    if (report.modelNames.empty())
      throw InvalidArgument("learning curve: " + options.dataDir.string() +
                            " has no object for any model in " + options.initDir.string());
  } else {
    for (const auto& name : options.modelNames) {
      if (!available.count(name))
        throw ModelError("learning curve: " + options.initDir.string() + " has no model " + name);
      if (!hasObjects(name))
        throw InvalidArgument("learning curve: " + options.dataDir.string() + " has no object for " +
                              name);
      report.modelNames.push_back(name);
    }
  }

  std::vector<std::string> categories, sources;
  for (const auto& o : objects) categories.push_back(o.category), sources.push_back(o.source);
  const auto split = options.bySource
                         ? sourceFoldSplit(sources, options.folds, options.seed)
                         : kFoldSplit(objects.size(), options.folds, options.seed, categories);
  for (const auto& fold : split) {
    report.folds.emplace_back();
    std::set<std::string> foldSources;
    for (std::size_t i : fold) {
      report.folds.back().push_back(objects[i].entry.id);
      foldSources.insert(objects[i].source);
    }
    if (options.bySource) report.foldSources.emplace_back(foldSources.begin(), foldSources.end());
  }
  FeatureOptions features = ModelSet::load(options.initDir).featureOptions();
  features.cacheDir =
      options.cacheDir.empty() ? options.dataDir / ".sagrid-cache" : options.cacheDir;
  // The replay of each model (weight 1 in all: drawn 1:1 with the k objects).
  const auto replayOf = [&](const std::string& modelName) -> std::vector<TrainingDataSource> {
    if (!options.replay) return {};
    if (!options.replayDir.empty())
      return {TrainingDataSource{options.replayDir, 1.0, "replay", {}, {}}};
    return defaultReplaySources(modelName);
  };

  const fs::path work = options.outDir / "work";
  for (std::size_t f = 0; f < split.size(); ++f) {
    const int foldNumber = static_cast<int>(f) + 1;
    const fs::path foldDir = work / ("fold" + std::to_string(foldNumber));
    std::vector<const RealObject*> test, pool;
    for (std::size_t i : split[f]) test.push_back(&objects[i]);
    // The training folds' objects in their seeded order: the k objects of a model are the first k
    // of its type, so a larger k adds objects to a smaller k's (nested subsets, less noise).
    for (std::size_t g = 0; g < split.size(); ++g)
      if (g != f)
        for (std::size_t i : split[g]) pool.push_back(&objects[i]);
    writeSubsetDataset(foldDir / "test", test);
    const fs::path guardDir = foldDir / "guard";
    if (options.guarded) {
      const auto [fineTunePool, guardSet] = splitOffGuardSet(pool, options.seed);
      if (guardSet.empty())
        throw InvalidArgument("learning curve --guard: fold " + std::to_string(foldNumber) +
                              "'s training folds hold one source only; a guard needs another");
      pool = fineTunePool;
      writeSubsetDataset(guardDir, guardSet);
      say("fold " + std::to_string(foldNumber) + ": guard set of " +
          std::to_string(guardSet.size()) + " object(s), fine-tunes drawn from " +
          std::to_string(pool.size()));
    }

    std::map<std::pair<std::string, int>, fs::path> tuned;  // (model, k used) -> its folder
    std::map<std::pair<std::string, int>, bool> adopted;    // (model, k used) -> guard's verdict
    std::map<std::string, HeldOutError> initOnGuard;       // model -> the init model's figure
    std::map<std::vector<int>, std::vector<LearningCurvePoint>> evaluated;  // by all k used
    for (const int k : options.ks) {
      const fs::path modelsDir = foldDir / ("k" + kLabel(k)) / "models";
      fs::remove_all(modelsDir);
      model::copyModelFiles(options.initDir, modelsDir);
      std::vector<int> kUsed;
      for (const auto& name : report.modelNames) {
        const auto [category, type] = model::splitModelName(name);
        std::vector<const RealObject*> ofType;
        for (const auto* o : pool)
          if (o->category == category && o->types.count(type)) ofType.push_back(o);
        const int used = k == kAllObjects ? static_cast<int>(ofType.size())
                                          : std::min(k, static_cast<int>(ofType.size()));
        kUsed.push_back(used);
        if (used == 0) continue;
        const auto key = std::make_pair(name, used);
        if (tuned.count(key)) {
          model::copyModelFiles(tuned[key], modelsDir, name);
          continue;
        }
        const fs::path dataDir = foldDir / (name + ".k" + std::to_string(used));
        writeSubsetDataset(dataDir, {ofType.begin(), ofType.begin() + used});
        DatasetTrainingOptions t;
        t.datasets.push_back({dataDir, 1.0, "data", features.cacheDir, objectsRoot});
        for (const auto& r : replayOf(name)) t.datasets.push_back(r);
        t.init = options.initDir;
        t.modelName = name;
        t.features = features;
        t.features.cacheDir.clear();  // per dataset (above)
        t.outDir = options.guarded ? modelsDir / ".candidate" : modelsDir;
        t.training.epochs = report.epochs;
        t.training.minutes = options.minutes;
        t.training.learningRate = kFineTuneLearningRate;
        t.training.adapted = options.adapted;
        t.keepInitNetworks = options.keepInitNetworks;
        t.training.seed = options.seed;
        t.command = "sagrid eval --learning-curve (fold " + std::to_string(foldNumber) + ", k " +
                    std::to_string(used) + ")";
        const auto start = std::chrono::steady_clock::now();
        const auto result = trainFromDataset(t);
        tuned[key] = modelsDir;
        adopted[key] = true;
        if (options.guarded) {
          const GuardOptions guard{options.initDir, t.outDir, name, guardDir, objectsRoot,
                                   features.cacheDir, features};
          if (!initOnGuard.count(name)) initOnGuard[name] = heldOutError(options.initDir, guard);
          const GuardVerdict verdict = judgeUpdate(guard, initOnGuard.at(name));
          applyVerdict(verdict, guard, modelsDir);
          fs::remove_all(t.outDir);
          adopted[key] = verdict.adopted;
          say("fold " + std::to_string(foldNumber) + " k=" + kLabel(k) + " " + name +
              ": guard: " + verdict.reason);
        }
        char line[256];
        std::snprintf(line, sizeof line,
                      "fold %d/%zu k=%s %s: fine-tuned on %d object(s)%s, %d epoch(s), loss "
                      "%.4f, %.0f s",
                      foldNumber, split.size(), kLabel(k).c_str(), name.c_str(), used,
                      options.replay ? " + replay" : "",
                      result.curve.empty() ? 0 : result.curve.back().epoch,
                      result.curve.empty() ? 0.0 : result.curve.back().loss, secondsSince(start));
        say(line);
      }
      // Same models as an earlier k of this fold (k beyond what the fold holds): same result.
      if (!evaluated.count(kUsed)) {
        EvaluationOptions e;
        e.dataDir = foldDir / "test";
        e.referenceRoot = objectsRoot;  // the subset lists --data's objects
        e.features = features;
        const EvaluationReport r = evaluateModels(ModelSet::load(modelsDir), e);
        std::vector<LearningCurvePoint> points;
        for (std::size_t m = 0; m < report.modelNames.size(); ++m) {
          LearningCurvePoint p;
          p.model = report.modelNames[m];
          p.fold = foldNumber;
          p.kUsed = kUsed[m];
          p.paperError = NAN;
          if (const auto a = adopted.find({p.model, kUsed[m]}); a != adopted.end())
            p.adopted = a->second;
          const auto& byModel = r.methods.front().byModel;  // "SAGrid argmin (paper)"
          if (const auto it = byModel.find(p.model); it != byModel.end()) {
            p.testObjects = it->second.objects;
            p.paperError = it->second.objects ? it->second.paperError : NAN;
          }
          points.push_back(p);
        }
        evaluated[kUsed] = points;
      }
      for (auto p : evaluated[kUsed]) {
        p.k = k;
        report.points.push_back(p);
        say("fold " + std::to_string(foldNumber) + " k=" + kLabel(k) + " " + p.model + ": " +
            reportCell(p.paperError * 100, "%.1f") + " cm on " + std::to_string(p.testObjects) +
            " held-out object(s)");
      }
    }
  }
  return report;
}

std::string learningCurveMarkdown(const LearningCurveReport& r) {
  std::ostringstream md;
  md << "# Learning curve\n\n"
     << "Fine-tuning " << r.initDir.string() << " on k objects of " << r.dataDir.string() << " ("
     << r.folds.size() << "-fold" << (r.foldSources.empty() ? "" : " by source") << ", seed "
     << r.seed << ", "
     << (r.minutes > 0 && r.epochs == 0 ? reportCell(r.minutes, "%g min")
                                        : std::to_string(r.epochs) + " epoch(s)")
     << " per fine-tune, " << (r.replay ? "with" : "without")
     << " bench replay, adapting " << (r.adapted == model::AdaptedPart::Head ? "the last layer and head only, batch-norm statistics kept" : "every weight")
     << (r.keepInitNetworks ? ", the init model's networks kept beside the fine-tuned one" : "")
     << "). Error: the paper's metric (distance from the single predicted point to "
        "the nearest ground truth) on the held-out fold, mean ± sd across folds, in cm. k = 0 "
        "is the init model.\n";
  if (r.guarded) {
    std::size_t tunes = 0, kept = 0;
    for (const auto& p : r.points)
      if (p.kUsed > 0) ++tunes, kept += p.adopted ? 1 : 0;
    md << "\nGuarded: each fine-tune was kept only where its error on a guard set (a quarter of "
          "the training folds' sources, none of them fine-tuned on) was lower than the init "
          "model's by more than the standard error of the per-object differences; "
       << kept << " of " << tunes << " (model, fold, k) results come from a kept fine-tune, the "
       << "others are the init model's.\n";
  }
  for (std::size_t f = 0; f < r.foldSources.size(); ++f) {
    md << (f == 0 ? "\nFolds (sources held out together):\n" : "") << "- fold " << f + 1 << " ("
       << r.folds[f].size() << " objects):";
    for (const auto& source : r.foldSources[f]) md << " " << source;
    md << "\n";
  }
  if (!r.ks.empty())
    md << "\n## Average of the models\n\n| k | models | error (cm) | ÷ error at k = "
       << kLabel(r.ks.front()) << " |\n|---|---|---|---|\n";
  for (int k : r.ks) {
    const Overall o = overallAt(r, k);
    char ratio[32] = "–";
    if (std::isfinite(o.ratio)) std::snprintf(ratio, sizeof ratio, "%.2f", o.ratio);
    md << "| " << kLabel(k) << " | " << o.models << " | " << reportCell(o.mean * 100, "%.1f")
       << " | " << ratio << " |\n";
  }
  for (const auto& model : r.modelNames) {
    md << "\n## " << model << "\n\n| k | k used (mean) | folds | error (cm) | sd (cm) |\n"
       << "|---|---|---|---|---|\n";
    for (int k : r.ks) {
      const Stats s = statsOf(r, model, k);
      char used[32];
      std::snprintf(used, sizeof used, "%.1f", s.kUsed);
      md << "| " << kLabel(k) << " | " << used << " | " << s.folds << " | "
         << reportCell(s.mean * 100, "%.1f") << " | " << reportCell(s.sd * 100, "%.1f") << " |\n";
    }
  }
  return md.str();
}

json learningCurveJson(const LearningCurveReport& r) {
  auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json j;
  j["data"] = fs::absolute(r.dataDir).lexically_normal().string();
  j["init"] = fs::absolute(r.initDir).lexically_normal().string();
  j["seed"] = r.seed;
  j["folds"] = r.folds;
  if (!r.foldSources.empty()) j["fold_sources"] = r.foldSources;
  j["epochs"] = r.epochs;
  j["minutes"] = r.minutes;
  j["replay"] = r.replay;
  j["adapted"] = model::toString(r.adapted);
  j["keep_init"] = r.keepInitNetworks;
  j["guarded"] = r.guarded;
  j["ks"] = json::array();
  for (int k : r.ks) j["ks"].push_back(kLabel(k));
  j["points"] = json::array();
  for (const auto& p : r.points)
    j["points"].push_back({{"model", p.model},
                           {"fold", p.fold},
                           {"k", kLabel(p.k)},
                           {"k_used", p.kUsed},
                           {"test_objects", p.testObjects},
                           {"paper_error_m", number(p.paperError)},
                           {"adopted", p.adopted}});
  j["summary"] = json::object();
  for (const auto& model : r.modelNames)
    for (int k : r.ks) {
      const Stats s = statsOf(r, model, k);
      j["summary"][model].push_back({{"k", kLabel(k)},
                                     {"k_used_mean", s.kUsed},
                                     {"folds", s.folds},
                                     {"paper_error_m_mean", number(s.mean)},
                                     {"paper_error_m_sd", number(s.sd)}});
    }
  j["average"] = json::array();
  for (int k : r.ks) {
    const Overall o = overallAt(r, k);
    j["average"].push_back({{"k", kLabel(k)},
                            {"models", o.models},
                            {"paper_error_m_mean", number(o.mean)},
                            {"ratio_to_first_k", number(o.ratio)}});
  }
  return j;
}

void writeLearningCurveReport(const LearningCurveReport& r, const fs::path& outDir) {
  fs::create_directories(outDir);
  writeFileAtomic(outDir / "learning_curve.md", learningCurveMarkdown(r));
  writeFileAtomic(outDir / "learning_curve.json", learningCurveJson(r).dump(2) + "\n");
  const plot::Color palette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                 {148, 103, 189}, {140, 86, 75}};
  plot::LinePlot p;
  p.title = "Fine-tuning learning curve (" + std::to_string(r.folds.size()) + " folds)";
  p.xLabel = "k (real objects fine-tuned on)";
  p.yLabel = "paper error (cm), mean and +-1 sd";
  for (std::size_t m = 0; m < r.modelNames.size(); ++m) {
    plot::Series mean, low, high;
    mean.name = r.modelNames[m];
    low.name = r.modelNames[m] + " -1 sd";
    high.name = r.modelNames[m] + " +1 sd";
    mean.color = low.color = high.color = palette[m % std::size(palette)];
    for (int k : r.ks) {
      const Stats s = statsOf(r, r.modelNames[m], k);
      if (!std::isfinite(s.mean)) continue;
      mean.x.push_back(s.kUsed), mean.y.push_back(100 * s.mean);
      low.x.push_back(s.kUsed);
      low.y.push_back(100 * std::max(0.0, s.mean - s.sd));  // an error is never below 0
      high.x.push_back(s.kUsed), high.y.push_back(100 * (s.mean + s.sd));
    }
    if (mean.x.empty()) continue;
    for (auto* c : {&low.color, &high.color})
      for (auto& channel : *c) channel = static_cast<unsigned char>((channel + 255) / 2);
    p.series.push_back(mean);
    p.series.push_back(low);
    p.series.push_back(high);
  }
  if (!p.series.empty()) writeLinePlotPng(outDir / "learning_curve.png", p);
}

}  // namespace sagrid
