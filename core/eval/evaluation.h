// `sagrid eval`: runs the models of each object's category over a labelled dataset and measures
// the predictions against the ground truth — the paper's metric and the multi-instance metrics of
// core/eval/metrics.h — for SAGrid (paper argmin, automatic count, k-means with the true count)
// and the Embedding Search baselines (cosine, L2). Reports in the paper's Table II form as
// Markdown, JSON and a PNG bar chart.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/annotate/model_set.h"
#include "core/annotate/object_confidence.h"
#include "core/annotate/pass_options.h"
#include "core/eval/candidate_sets.h"
#include "core/eval/curator_effort.h"
#include "core/eval/metrics.h"
#include "core/eval/reliability.h"

namespace sagrid {

// The passes after each model are annotate's (PassOptions), so the report measures what annotate
// writes.
struct EvaluationOptions : PassOptions {
  std::filesystem::path dataDir;  // a dataset; when it has a val/ split, that is used
  // Further datasets (each its val/ split when it has one): the report covers the union, e.g. to
  // fit the object confidence or the counts on generated and real objects together.
  std::vector<std::filesystem::path> moreData;
  // Where dataDir's manifest may point (readDataset); empty: inside dataDir only.
  std::filesystem::path referenceRoot;
  FeatureOptions features;           // from the models; cacheDir empty = DATA/.sagrid-cache
  ConfidenceCalibration confidence;  // object confidence map (the models folder's, or unfitted)
  std::function<void(std::size_t, std::size_t, const std::string&)> onProgress;
  // Keep every model's field and ground truth (normalized frame) in the report, for refitting the
  // automatic count (core/eval/count_fitting.h). Off by default: it holds every field in memory.
  bool keepFields = false;
};

// The fields a model predicted on the evaluated objects that have its type, with their ground
// truth in the normalized frame (what calibrateExtraction takes).
struct FieldsWithTruth {
  std::vector<PredictedField> fields;
  std::vector<std::vector<Eigen::Vector3f>> truths;
  std::vector<double> metresPerUnit;  // metres per normalized unit, per object
};

struct MethodMetrics {
  std::string method;
  std::map<std::string, TypeMetrics> byModel;  // model name -> metrics
};

struct EvaluationReport {
  std::filesystem::path dataDir;                    // the data evaluated (a val/ split when used)
  std::vector<std::filesystem::path> moreDataDirs;  // with EvaluationOptions::moreData
  std::size_t objects = 0;              // evaluated (of a category with models)
  std::size_t failed = 0;               // could not be evaluated (import/features), logged
  std::vector<std::string> modelNames;  // columns, in the paper's order where known
  std::vector<MethodMetrics> methods;
  double meanOccupiedVoxels = 0;
  double modelMilliseconds = 0;  // mean per object: all models of the category + auto extraction
                                 // + projection, features cached
  CuratorEffort effort;  // SAGrid auto count, all objects
  std::map<std::string, CuratorEffort> effortByCategory;
  // By source (core/dataset/object_source.h: repository, library, dataset folder), for
  // leave-one-source-out reading: the curator effort and the single-point error (paper metric,
  // argmin) averaged over the source's objects and models.
  struct SourceFigures {
    CuratorEffort effort;
    double paperError = 0;  // metres; NaN without ground truth of any model's type
    std::size_t paperErrors = 0;
  };
  std::map<std::string, SourceFigures> bySource;
  // Per evaluated object: the confidence signal (least-sure point), its calibrated confidence and
  // whether the automatic prediction was right with one key; and their reliability.
  std::vector<double> confidenceSignal, confidence;
  std::vector<bool> oneKey;
  bool confidenceCalibrated = false;
  ReliabilityReport reliability;
  nlohmann::json perObject = nlohmann::json::array();
  std::map<std::string, FieldsWithTruth> fieldsByModel;  // with EvaluationOptions::keepFields
  // Every model's point candidates on every object (PassOptions::keepCandidates).
  std::vector<CandidateSet> candidateSets;
};

EvaluationReport evaluateModels(const ModelSet& models, const EvaluationOptions& options);

// The data a report covers: its dataset, " + " each further one.
std::string evaluatedData(const EvaluationReport& report);

// Markdown tables (Table II form, multi-instance table), JSON, PNG bar chart of the paper metric.
std::string evaluationMarkdown(const EvaluationReport& report);
nlohmann::json evaluationJson(const EvaluationReport& report);
// Writes eval.md, eval.json and eval.png into `outDir` (atomically).
void writeEvaluationReport(const EvaluationReport& report, const std::filesystem::path& outDir);

// One record of `EvaluationReport::perObject`: its curator point edits summed over its models, and
// its paper single-point error averaged over the models that have one (NaN: none).
int objectEdits(const nlohmann::json& object);
double objectPaperError(const nlohmann::json& object);

// The paper's column names ("toggle sink", ...) for the four shipped models, else the model name.
std::string paperColumnName(const std::string& modelName);

}  // namespace sagrid
