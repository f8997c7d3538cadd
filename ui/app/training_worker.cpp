#include "ui/app/training_worker.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/annotate/annotate.h"
#include "core/annotate/category_update.h"
#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/dataset/labels_mesh.h"
#include "core/eval/point_model_guard_by_source.h"
#include "core/eval/point_scorer_update.h"
#include "core/eval/size_memory_update.h"
#include "core/eval/units_cases.h"
#include "core/labels/labels.h"
#include "core/training/dataset_training.h"
#include "core/training/guarded_update.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

std::vector<std::string> trainingTypes(const fs::path& dataset, const std::string& category) {
  std::set<std::string> types;
  std::istringstream manifest(readFileBytes(dataset / "manifest.jsonl"));
  std::string line;
  while (std::getline(manifest, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto entry = nlohmann::json::parse(line, nullptr, false);
    if (entry.is_discarded()) throw FileError(dataset / "manifest.jsonl", "a line is not JSON");
    if (entry.value("category", "") != category) continue;
    // Inside the dataset folder only (issue 14: a manifest names no file outside it).
    const ObjectLabels labels = readLabels(
        resolveReferenceWithin(dataset, entry.value("labels", ""), dataset / "manifest.jsonl"));
    for (const auto& p : labels.affordances) types.insert(p.type);
  }
  return {types.begin(), types.end()};
}

TrainingWorker::~TrainingWorker() {
  m_cancel = true;
  if (m_thread.joinable()) m_thread.join();
}

void TrainingWorker::start(TrainingRequest request) {
  m_cancel = true;
  if (m_thread.joinable()) m_thread.join();
  m_cancel = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_status = TrainingStatus{};
    m_status.running = true;
    m_status.phase = "starting";
  }
  m_running = true;
  m_thread =
      std::thread([this, request = std::move(request)]() mutable { run(std::move(request)); });
}

TrainingStatus TrainingWorker::status() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_status;
}

bool TrainingWorker::takeFinished() {
  std::lock_guard<std::mutex> lock(m_mutex);
  return std::exchange(m_finishedFlag, false);
}

void TrainingWorker::update(const std::function<void(TrainingStatus&)>& change) {
  std::lock_guard<std::mutex> lock(m_mutex);
  change(m_status);
}

void TrainingWorker::run(TrainingRequest request) {
  try {
    if (request.categoryClassifier) runCategoryClassifier(request);
    else if (request.pointScorer) runPointScorer(request);
    else if (request.unitsMemory) runUnitsMemory(request);
    else runPointModels(request);
    std::lock_guard<std::mutex> lock(m_mutex);
    m_finishedFlag = true;
  } catch (const Cancelled&) {
    update([](TrainingStatus& s) { s.phase = "cancelled"; });
  } catch (const std::exception& e) {
    update([&](TrainingStatus& s) {
      s.error = e.what();
      s.phase = "failed";
    });
  }
  update([](TrainingStatus& s) { s.running = false; });
  m_running = false;
}

void TrainingWorker::runCategoryClassifier(const TrainingRequest& request) {
  const fs::path from = request.initDir.empty() ? request.outDir : request.initDir;
  const fs::path currentFile = from / kCategoryClassifierFile;
  std::error_code ec;
  if (!fs::is_regular_file(currentFile, ec))
    throw InvalidArgument("no category classifier in " + from.string() +
                          " to retrain (train one with `sagrid category train`)");
  if (!request.heldOut.empty()) {
    // The same refusals as a guarded point-model update: a held-out object that is also training
    // data, one mesh labelled with two categories, a models folder that is not one set.
    update([&](TrainingStatus& s) { s.phase = "checking the curated data and " + from.string(); });
    checkGuardedUpdate({from, {}, {}, request.heldOut, {}, {}, {}}, {request.dataset});
  }
  const CategoryClassifier current = CategoryClassifier::load(currentFile);
  const FeatureOptions features = ModelSet::load(from).featureOptions();
  std::vector<std::string> missing;
  const CategoryClassifier candidate = retrainCategoryClassifier(
      current, request.dataset, kCuratedCategoryWeight, features, missing,
      [&](const fs::path& dir, std::size_t done, std::size_t total) {
        if (m_cancel) throw Cancelled();
        update([&](TrainingStatus& s) {
          s.phase = "category features " + std::to_string(done) + "/" + std::to_string(total) +
                    " " + dir.filename().string();
          s.fraction = total ? 0.8f * float(done) / float(total) : 0.0f;
        });
      });
  for (const auto& dir : missing) logger()->warn("category classifier: {} is not here; retrained without it", dir);
  bool adopted = true;
  std::string verdictLine;
  if (!request.heldOut.empty()) {
    update([&](TrainingStatus& s) { s.phase = "guard: the category classifier on held-out objects"; s.fraction = 0.9f; });
    const CategoryVerdict verdict =
        judgeCategoryUpdate(candidate, currentFile, {{request.heldOut, 1.0}}, features);
    recordCategoryVerdict(verdict, request.outDir, {request.heldOut.string()});
    adopted = verdict.adopted;
    verdictLine = verdict.reason;
  } else {
    // No held-out folder: the training set's objects judge both recipes, each source left out
    // in turn (its features are cached by the retraining above).
    std::vector<std::string> gone;
    try {
      const CategoryVerdict verdict = judgeCategoryUpdateBySource(
          withCuratedFolder(recipeOf(current, gone), {request.dataset, kCuratedCategoryWeight}),
          current, {request.dataset}, features,
          [&](const fs::path&, std::size_t, std::size_t) {
            if (m_cancel) throw Cancelled();
          },
          [&](const std::string& recipe, int k, int folds) {
            if (m_cancel) throw Cancelled();
            update([&](TrainingStatus& s) {
              s.phase = "guard: the " + recipe + " classifier without source " +
                        std::to_string(k + 1) + "/" + std::to_string(folds);
              s.fraction = 0.8f + 0.1f * (recipe == "current") + 0.1f * float(k) / float(folds);
            });
          });
      recordCategoryVerdict(verdict, request.outDir, {request.dataset.string()});
      adopted = verdict.adopted;
      verdictLine = verdict.reason;
    } catch (const TooFewSources&) {
      verdictLine =
          "unguarded: the training set's objects come from one source, so none can be "
          "left out to judge the retrained classifier; it is kept, better or not (a "
          "held-out folder of other sources guards it)";
    }
  }
  const fs::path file =
      adopted ? request.outDir / kCategoryClassifierFile : request.outDir / "refused" / kCategoryClassifierFile;
  fs::create_directories(file.parent_path());
  candidate.save(file);
  logger()->info("{}; wrote {}", verdictLine, file.string());
  // An adopted classifier decides the unreviewed objects' categories again (their points with
  // them); a refused one changes nothing.
  // The GUI predicts from the folder out after any run: made whole, whatever the verdict.
  completeModelsFolder(from, request.outDir);
  const std::string requeued = adopted ? predictQueueAgainClause(request) : std::string();
  update([&](TrainingStatus& s) {
    s.fraction = 1.0f;
    s.phase = "done";
    s.verdicts.push_back(verdictLine);
    s.finished = "category classifier retrained with " + request.dataset.string() +
                 (missing.empty() ? std::string()
                                  : " (" + std::to_string(missing.size()) +
                                        " of its training folders are not on this machine)") +
                 (adopted ? "; adopted" : "; refused: " + file.string()) + requeued;
  });
}

void TrainingWorker::runUnitsMemory(const TrainingRequest& request) {
  const fs::path from = request.initDir.empty() ? request.outDir : request.initDir;
  const ModelSet models = ModelSet::load(from);  // with its units memory, checked against the cards
  std::size_t unconfirmed = 0;
  const std::vector<UnitsCase> curated = readUnitsCases(
      {request.dataset}, models.featureOptions(),
      [&](std::size_t done, std::size_t total, const std::string& id) {
        if (m_cancel) throw Cancelled();
        update([&](TrainingStatus& s) {
          s.phase = "units: " + std::to_string(done) + "/" + std::to_string(total) + " " + id;
          s.fraction = total ? 0.8f * float(done) / float(total) : 0.0f;
        });
      },
      &unconfirmed);
  update([&](TrainingStatus& s) {
    s.phase = "guard: the units guess left out by source";
    s.fraction = 0.9f;
  });
  const SizeMemoryUpdate grown = updateSizeMemory(
      models.sizeMemory(), curated,
      recallCandidates(defaultMeasureSets(), defaultNeighbourCounts(), defaultFarFactors()),
      models.featureConfigHash());
  const fs::path dir = grown.memory ? request.outDir : request.outDir / "refused";
  fs::create_directories(dir);
  if (grown.memory) writeSizeMemory(*grown.memory, dir);
  writeFileAtomic(dir / "units_memory.md", unitsLosoMarkdown(grown.report));
  logger()->info("{}; report {}", grown.verdict, (dir / "units_memory.md").string());
  completeModelsFolder(from, request.outDir);
  update([&](TrainingStatus& s) {
    s.fraction = 1.0f;
    s.phase = "done";
    s.verdicts.push_back(grown.verdict);
    s.finished = "units memory grown with " + std::to_string(curated.size()) + " object(s) of " +
                 request.dataset.string() +
                 (unconfirmed ? " (" + std::to_string(unconfirmed) +
                                    " left out: their units are a guess nobody confirmed)"
                              : std::string()) +
                 (grown.memory ? "; adopted" : "; refused: " + (dir / "units_memory.md").string());
  });
}

void completeModelsFolder(const fs::path& from, const fs::path& out) {
  std::error_code same;
  if (fs::equivalent(from, out, same)) return;
  fs::create_directories(out);
  for (const auto& entry : fs::directory_iterator(from))
    if (entry.is_regular_file())
      fs::copy_file(entry.path(), out / entry.path().filename(), fs::copy_options::skip_existing);
}

std::string TrainingWorker::predictQueueAgainClause(const TrainingRequest& request) {
  if (request.requeue.empty()) return {};
  const RequeueCounts counts = predictQueueAgain(request, "", 0.95, 0.05);
  return "; " + std::to_string(counts.objects) + " unreviewed object(s) predicted again, " +
         std::to_string(counts.recategorized) + " changed category";
}

void TrainingWorker::runPointScorer(const TrainingRequest& request) {
  const fs::path from = request.initDir.empty() ? request.outDir : request.initDir;
  if (!request.heldOut.empty()) {
    // The same refusals as a guarded point-model update.
    update([&](TrainingStatus& s) { s.phase = "checking the curated data and " + from.string(); });
    checkGuardedUpdate({from, {}, {}, request.heldOut, {}, {}, {}}, {request.dataset});
  }
  // Beside the curated objects, generated ones the networks were not trained on (request.generated;
  // empty: the bench's val and decision splits, generated once when missing), as the shipped
  // decision was trained.
  ScorerUpdateRequest scorerRequest{from,  request.dataset, request.generated, request.heldOut,
                                    {},    {},              &m_cancel};
  const std::map<std::string, std::pair<float, float>> span = {{"bench", {0.0f, 0.0f}},
                                                               {"curated", {0.0f, 0.3f}},
                                                               {"generated", {0.3f, 0.5f}},
                                                               {"held out", {0.8f, 0.15f}}};
  scorerRequest.onProgress = [&](const std::string& phase, std::size_t done, std::size_t total,
                                 const std::string& id) {
    update([&](TrainingStatus& s) {
      s.phase = (phase == "bench" ? "generating the bench (once) " : "point candidates, " + phase + " ") +
                std::to_string(done) + "/" + std::to_string(total) + " " + id;
      const auto& [at, width] = span.at(phase);
      s.fraction = at + width * (total ? float(done) / float(total) : 0.0f);
    });
  };
  const ScorerUpdate result = updatePointScorer(scorerRequest);
  const fs::path file = writeScorerUpdate(result, request.outDir);
  if (result.guard) {
    for (const auto& v : result.guard->byModel)
      update([&](TrainingStatus& s) { s.verdicts.push_back(toString(v)); });
  }
  update([&](TrainingStatus& s) { s.verdicts.push_back(result.verdict); });
  logger()->info("point decision: {}; wrote {}", result.verdict, file.string());
  completeModelsFolder(from, request.outDir);
  const std::string requeued = result.adopted() ? predictQueueAgainClause(request) : std::string();
  update([&](TrainingStatus& s) {
    s.fraction = 1.0f;
    s.phase = "done";
    s.finished = "point decision retrained on " + std::to_string(result.curatedSets) +
                 " curated and " + std::to_string(result.generatedSets) +
                 " generated model sets" +
                 (result.adopted() ? "; adopted" : "; refused: " + file.string()) +
                 requeued;
  });
}

void TrainingWorker::runPointModels(const TrainingRequest& request) {
  const auto types = trainingTypes(request.dataset, request.category);
  if (types.empty()) {
    throw InvalidArgument("the training set " + request.dataset.string() + " has no " +
                          request.category + " object with points; add some first");
  }
  const double steps = double(types.size()) + 1.0;  // models, then the queue
  if (!request.initDir.empty()) {
    update([&](TrainingStatus& s) { s.phase = "checking the curated data and " + request.initDir.string(); });
    checkGuardedUpdate({request.initDir, {}, {}, request.heldOut, {}, {}, {}}, {request.dataset});
  }
  for (std::size_t t = 0; t < types.size(); ++t) {
    DatasetTrainingOptions options;
    options.modelName = request.category + "." + types[t];
    options.datasets.push_back({request.dataset, 1.0, "data", {}, {}});
    // The same fine-tune as `sagrid train --init DIR` (replay weighted 1:1, fine-tune rate).
    if (!request.initDir.empty() &&
        fs::is_regular_file(request.initDir / (options.modelName + ".json"))) {
      options.init = request.initDir;
      options.keepInitNetworks = request.keepInitNetworks;
      options.training.learningRate = kFineTuneLearningRate;
      if (request.replay) {
        update([&](TrainingStatus& s) {
          s.phase = "replay: the generated training data (generated if missing)";
        });
        for (const auto& r : defaultReplaySources(options.modelName))
          options.datasets.push_back(r);
      }
    }
    // A fine-tune is guarded: by the held-out folder when given, else leaving each fold of the
    // training set's sources out (a fine-tune per fold; unguarded with one source).
    const bool fineTune = !options.init.empty();
    const bool heldOutGuard = fineTune && !request.heldOut.empty();
    const fs::path candidateDir = request.outDir / (".candidate." + options.modelName);
    options.outDir = fineTune ? candidateDir : request.outDir;
    const GuardOptions guard{
        request.initDir, candidateDir, options.modelName, request.heldOut, {}, {}, {}};
    options.command = options.init.empty() ? "sagrid gui (Train panel)"
                                           : "sagrid gui (Train panel, fine-tune of " +
                                                 request.initDir.string() + ")";
    options.training.minutes = request.minutesPerModel;
    options.training.epochs = request.epochs;
    options.training.cancel = &m_cancel;
    // This model's share of the bar is split into the guard's folds and the final training.
    double part = 0, parts = 1;
    options.training.onProgress = [&](const model::TrainingProgress& p) {
      update([&](TrainingStatus& s) {
        const std::string fold =
            part < parts - 1
                ? " without fold " + std::to_string(int(part) + 1) + " of the sources (guard)"
                : "";
        s.phase = "training " + options.modelName + fold + ", epoch " + std::to_string(p.epoch) +
                  "/" + std::to_string(p.epochs);
        s.losses.push_back(float(p.loss));
        const double within = p.epochs > 0 ? double(p.epoch) / p.epochs : 0.0;
        s.fraction = float((double(t) + (part + within) / parts) / steps);
      });
    };
    options.onFeatureProgress = [&](std::size_t done, std::size_t total, const std::string& id) {
      update([&](TrainingStatus& s) {
        s.phase = "features " + std::to_string(done) + "/" + std::to_string(total) + " " + id;
      });
    };
    update([&](TrainingStatus& s) { s.losses.clear(); });
    std::optional<GuardVerdict> verdict;
    if (fineTune && !heldOutGuard) {
      PointModelGuardBySource bySource;
      bySource.currentDir = request.initDir;
      bySource.fineTune = options;
      bySource.workDir = request.outDir / (".guard-by-source." + options.modelName);
      bySource.seed = options.training.seed;
      bySource.onFold = [&](int fold, int folds) {
        part = fold - 1, parts = folds + 1;
        update([&](TrainingStatus& s) { s.losses.clear(); });
      };
      verdict = judgeUpdateBySource(bySource);
      part = parts - 1;
      if (!verdict) {
        // One source: nothing can judge; trained and kept as before guards existed.
        options.outDir = request.outDir;
        update([&](TrainingStatus& s) {
          s.verdicts.push_back(options.modelName +
                               ": unguarded: the training set's objects of its type come from one "
                               "source, so none can be left out while another teaches (a "
                               "held-out folder of other sources guards it)");
        });
      }
    }
    if (!verdict || verdict->adopted) {
      const auto result = trainFromDataset(options);
      logger()->info("trained {} on {} objects ({:.0f} s)", result.card.name, result.objectsUsed,
                     result.trainingSeconds);
    }
    if (heldOutGuard) {
      update([&](TrainingStatus& s) { s.phase = "guard: " + options.modelName + " on held-out objects"; });
      verdict = judgeUpdate(guard);
    }
    if (verdict) {
      applyVerdict(*verdict, guard, request.outDir);
      fs::remove_all(candidateDir);
      logger()->info("guard: {}: {}", options.modelName, verdict->reason);
      update([&](TrainingStatus& s) {
        s.verdicts.push_back(options.modelName + ": " + verdict->reason);
      });
    }
  }

  const RequeueCounts counts = predictQueueAgain(request, request.category,
                                                 double(types.size()) / steps, 1.0 / steps);
  update([&](TrainingStatus& s) {
    s.fraction = 1.0f;
    s.phase = "done";
    s.finished = std::to_string(types.size()) + " model(s) trained; " +
                 std::to_string(counts.objects) + " unreviewed object(s) predicted again: " +
                 std::to_string(counts.moved) + " of " + std::to_string(counts.compared) +
                 " predicted points moved";
  });
  logger()->info("training loop: {} of {} predicted points moved", counts.moved, counts.compared);
}

TrainingWorker::RequeueCounts TrainingWorker::predictQueueAgain(const TrainingRequest& request,
                                                                const std::string& category,
                                                                double fractionFrom,
                                                                double fractionSpan) {
  // Predict the queue again with the new models; reviewed objects keep what the curator decided.
  const ModelSet models = ModelSet::load(request.outDir);
  RequeueCounts counts;
  for (std::size_t i = 0; i < request.requeue.size(); ++i) {
    if (m_cancel) throw Cancelled();
    const QueueEntry& entry = request.requeue[i];
    update([&](TrainingStatus& s) {
      s.phase = "predicting " + entry.mesh.parent_path().filename().string();
      s.fraction = float(fractionFrom + fractionSpan * double(i) / double(request.requeue.size()));
    });
    if (entry.state != QueueState::Unreviewed) continue;
    ObjectLabels before;
    std::error_code ec;
    if (fs::exists(entry.labels, ec)) before = readLabels(entry.labels);
    if (!category.empty() && !before.object.category.empty() && before.object.category != category)
      continue;
    AnnotateOptions options;
    options.category = category;  // empty: the classifier decides again
    options.features = models.featureOptions();
    AnnotationResult r = annotateMeshFile(
        entry.mesh, before.object.id.empty() ? entry.mesh.stem().string() : before.object.id,
        models, options, entry.labels.parent_path());
    // A point "moved" when no new prediction of its type lies within 2% of the object's size.
    const float tolerance = 0.02f * [&] {
      Eigen::AlignedBox3f box;
      for (const auto& p : r.labels.affordances) box.extend(p.position);
      for (const auto& p : before.affordances) box.extend(p.position);
      return box.isEmpty() ? 1.0f : std::max(box.diagonal().norm(), 1e-6f);
    }();
    for (const auto& old : before.affordances) {
      if (old.status != AffordanceStatus::Predicted) continue;
      ++counts.compared;
      bool stayed = false;
      for (const auto& now : r.labels.affordances)
        stayed |= now.type == old.type && (now.position - old.position).norm() <= tolerance;
      if (!stayed) ++counts.moved;
    }
    ObjectLabels updated = before.object.id.empty() ? r.labels : before;
    updated.affordances = r.labels.affordances;
    if (category.empty()) {
      counts.recategorized += !before.object.category.empty() &&
                              before.object.category != r.labels.object.category;
      updated.object.category = r.labels.object.category;
      updated.object.extra = r.labels.object.extra;  // the rejection and suggestion flags
    } else if (updated.object.category.empty()) {
      updated.object.category = category;
    }
    writeLabels(entry.labels, updated);
    ++counts.objects;
  }
  return counts;
}

}  // namespace sagrid::ui
