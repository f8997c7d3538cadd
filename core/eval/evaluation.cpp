#include "core/eval/evaluation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/annotate/annotate.h"
#include "core/annotate/point_passes.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/report_cell.h"
#include "core/dataset/dataset.h"
#include "core/dataset/object_source.h"
#include "core/eval/count_breakdown.h"
#include "core/eval/embedding_search.h"
#include "core/features/feature_grid.h"
#include "core/geometry/surface_scene.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/plot/plot.h"

namespace sagrid {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

const char* const kPaperOrder[] = {"sink.togglebutton", "sink.fluidsource", "stove.togglebutton",
                                   "stove.heatsource"};

enum Method { kArgmin, kRefined, kAuto, kKMeans, kCosine, kL2, kMethodCount };
const char* const kMethodNames[] = {"SAGrid argmin (paper)",   "SAGrid argmin refined",
                                    "SAGrid auto count",       "SAGrid k-means, true count",
                                    "Embedding search cosine", "Embedding search L2"};

}  // namespace

std::string paperColumnName(const std::string& name) {
  if (name == "sink.togglebutton") return "toggle sink";
  if (name == "sink.fluidsource") return "fluid source";
  if (name == "stove.togglebutton") return "toggle stove";
  if (name == "stove.heatsource") return "heat source";
  return name;
}

EvaluationReport evaluateModels(const ModelSet& models, const EvaluationOptions& options) {
  EvaluationReport report;
  // Each dataset's val/ split when it has one; its objects read their features from --cache, else
  // from the dataset's own cache.
  std::vector<DatasetEntry> entries;
  std::vector<fs::path> cacheOf;
  std::vector<std::string> datasetOf;  // the folder each entry was read from: its fallback source
  std::vector<fs::path> dataDirs = {options.dataDir};
  dataDirs.insert(dataDirs.end(), options.moreData.begin(), options.moreData.end());
  for (const fs::path& dir : dataDirs) {
    const fs::path used = fs::is_directory(dir / "val") ? dir / "val" : dir;
    if (report.dataDir.empty())
      report.dataDir = used;
    else
      report.moreDataDirs.push_back(used);
    const auto read = readDataset(used, options.referenceRoot);
    if (read.empty()) throw InvalidArgument("dataset " + used.string() + " has no objects");
    entries.insert(entries.end(), read.begin(), read.end());
    cacheOf.insert(
        cacheOf.end(), read.size(),
        options.features.cacheDir.empty() ? dir / ".sagrid-cache" : options.features.cacheDir);
    datasetOf.insert(datasetOf.end(), read.size(), dir.filename().string());
  }

  for (const char* name : kPaperOrder)
    for (const auto& m : models.models())
      if (m.card().name == name) report.modelNames.push_back(name);
  for (const auto& m : models.models())
    if (std::find(report.modelNames.begin(), report.modelNames.end(), m.card().name) ==
        report.modelNames.end())
      report.modelNames.push_back(m.card().name);

  std::vector<std::map<std::string, TypeMetricsAccumulator>> acc(kMethodCount);
  CuratorEffortAccumulator effort;
  std::map<std::string, CuratorEffortAccumulator> effortByCategory, effortBySource;
  std::map<std::string, std::pair<double, std::size_t>> errorBySource;  // sum, count
  double modelSeconds = 0;
  const auto categories = models.categories();
  const PassOptions passes = withLearnedDecision(options, models);
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const DatasetEntry& entry = entries[e];
    if (options.onProgress) options.onProgress(e, entries.size(), entry.id);
    try {
      const ObjectLabels labels = readLabels(entry.labels);
      const std::string category = entry.category.empty() ? labels.object.category : entry.category;
      if (std::find(categories.begin(), categories.end(), category) == categories.end()) continue;
      FeatureOptions objectFeatures = options.features;
      objectFeatures.cacheDir = cacheOf[e];
      const UpAxis up = upAxisOrZ(labels.object.up);
      objectFeatures.up = up;
      const Mesh mesh = importMesh(entry.mesh, ImportOptions(up));
      const FeatureGrid grid = extractFeatures(entry.mesh, objectFeatures);
      const SurfaceScene scene(mesh);
      const double mpu = metersPerUnit(labels);
      report.meanOccupiedVoxels += static_cast<double>(grid.voxels.size());
      const std::string source =
          objectSource(labels, entry.mesh, datasetOf[e]);
      nlohmann::json object = {
          {"id", entry.id}, {"category", category}, {"meters_per_unit", mpu}, {"source", source}};
      if (const auto generator = labels.object.extra.find("generator");
          generator != labels.object.extra.end() && generator->is_object())
        object["generator"] = *generator;
      // One field and automatic-count prediction per model: the timed part, as annotate does it.
      // Every other extraction mode below reads the same field.
      const auto categoryModels = models.forCategory(category);
      const auto t = Clock::now();
      const CategoryPoints categoryPoints =
          predictCategoryPoints(categoryModels, {mesh, grid, scene, objectFeatures}, passes,
                                InstanceMode::Auto);
      const std::vector<ModelPrediction>& autoPredictions = categoryPoints.predictions;
      modelSeconds += secondsSince(t);
      auto surfaceOf = [](const ModelPrediction& p) {
        std::vector<Eigen::Vector3f> out;
        for (const auto& s : p.surface) out.push_back(s.position);
        return out;
      };
      PointEdits objectEdits;
      for (std::size_t m = 0; m < categoryModels.size(); ++m) {
        const auto* model = categoryModels[m];
        const auto& card = model->card();
        std::vector<Eigen::Vector3f> truth;
        for (const auto* a : labels.ofType(card.type)) truth.push_back(a->position);
        // What the GUI shows: the automatic count. Extra points on a type the object lacks are
        // edits too (deletions), so this comes before skipping types without ground truth.
        const PredictedField& field = autoPredictions[m].field;
        auto predict = [&](InstanceMode mode, int count = 1,
                           const ExtractionSettings* settings = nullptr) {
          return surfaceOf(predictionFromField(*model, field, grid, scene, mesh.fileUp, mode,
                                               count, settings));
        };
        const auto autoPoints = surfaceOf(autoPredictions[m]);
        const PointEdits edits = pointEdits(matchPoints(autoPoints, truth, mpu));
        objectEdits += edits;
        object["edits"][card.name] = {{"drags", edits.drags},
                                      {"deletions", edits.deletions},
                                      {"additions", edits.additions}};
        if (options.keepCandidates && m < categoryPoints.candidates.size()) {
          CandidateSet set{entry.id, source, card.name, object.contains("generator"), mpu,
                           categoryPoints.candidates[m], {}, autoPoints, truth, passesOff(passes),
                           card.weightsIdentity()};
          for (const auto& c : set.candidates)
            set.candidateSurface.push_back(
                projectToSurface(c.position, grid.normalization, scene, mesh.fileUp).position);
          report.candidateSets.push_back(std::move(set));
        }
        if (truth.empty()) continue;
        auto record = [&](Method method, const std::vector<Eigen::Vector3f>& predicted) {
          const double single = nearestDistance(predicted.front(), truth, mpu);
          acc[method][card.name].addSingle(single);
          if (method == kArgmin) {
            object["paper_error_m"][card.name] = single;
            errorBySource[source].first += single;
            ++errorBySource[source].second;
          }
          acc[method][card.name].addMatch(matchPoints(predicted, truth, mpu));
          nlohmann::json points = nlohmann::json::array();
          for (const auto& p : predicted) points.push_back({p.x(), p.y(), p.z()});
          object["predictions"][card.name][kMethodNames[method]] = points;
        };
        ExtractionSettings paper = card.extraction;
        paper.refineVoxels = 0;  // the paper's argmin: a voxel centre
        record(kArgmin, predict(InstanceMode::Single, 1, &paper));
        record(kRefined, predict(InstanceMode::Single));
        record(kAuto, autoPoints);
        record(kKMeans, predict(InstanceMode::Count, static_cast<int>(truth.size())));
        for (Method m : {kCosine, kL2}) {
          const std::size_t v =
              embeddingSearchVoxel(grid, card.affordanceFeatureMean,
                                   m == kCosine ? EmbeddingMetric::Cosine : EmbeddingMetric::L2);
          record(m, {projectToSurface(voxelCenter(grid.voxels[v], grid.resolution),
                                      grid.normalization, scene, mesh.fileUp)
                         .position});
        }
        nlohmann::json t = nlohmann::json::array();
        for (const auto& p : truth) t.push_back({p.x(), p.y(), p.z()});
        object["truth"][card.name] = t;
        if (options.keepFields) {
          auto& kept = report.fieldsByModel[card.name];
          kept.fields.push_back(field);
          kept.truths.emplace_back();
          kept.metresPerUnit.push_back(mpu / grid.normalization.scale);
          for (const auto& p : truth)
            kept.truths.back().push_back(grid.normalization.toNormalized(fileToZUp(p, up)));
        }
      }
      const double signal = leastSurePointDistance(autoPredictions);
      report.confidenceSignal.push_back(signal);
      report.confidence.push_back(options.confidence.probability(signal));
      report.oneKey.push_back(objectEdits.total() == 0);
      object["confidence"] = report.confidence.back();
      object["one_key"] = objectEdits.total() == 0;
      effort.addObject(objectEdits);
      effortByCategory[category].addObject(objectEdits);
      effortBySource[source].addObject(objectEdits);
      report.perObject.push_back(object);
      ++report.objects;
    } catch (const Cancelled&) {
      throw;
    } catch (const Error& error) {
      logger()->warn("eval: {} failed: {}", entry.id, error.what());
      ++report.failed;
    }
  }
  if (options.onProgress) options.onProgress(entries.size(), entries.size(), "");
  if (report.objects == 0)
    throw InvalidArgument("dataset " + evaluatedData(report) +
                          " has no object of a category the models know");
  report.modelMilliseconds = 1000.0 * modelSeconds / report.objects;
  report.meanOccupiedVoxels /= static_cast<double>(report.objects);
  for (int m = 0; m < kMethodCount; ++m) {
    MethodMetrics mm;
    mm.method = kMethodNames[m];
    for (const auto& [name, a] : acc[m]) mm.byModel[name] = a.result();
    report.methods.push_back(mm);
  }
  report.effort = effort.result();
  report.confidenceCalibrated = options.confidence.fitted;
  report.reliability = reliabilityReport(report.confidence, report.oneKey);
  for (const auto& [category, a] : effortByCategory) report.effortByCategory[category] = a.result();
  for (const auto& [source, a] : effortBySource) {
    EvaluationReport::SourceFigures& f = report.bySource[source];
    f.effort = a.result();
    const auto& [sum, count] = errorBySource[source];
    f.paperErrors = count;
    f.paperError = count ? sum / static_cast<double>(count) : NAN;
  }
  return report;
}

namespace {
// "| first | <model columns> | last |" and its separator row.
void modelColumnsHeader(std::ostringstream& md, const char* first,
                        const std::vector<std::string>& modelNames, const char* last) {
  md << "| " << first << " |";
  for (const auto& n : modelNames) md << ' ' << paperColumnName(n) << " |";
  md << ' ' << last << " |\n|---|";
  for (std::size_t i = 0; i <= modelNames.size(); ++i) md << "---|";
  md << '\n';
}

// One row per object: the paper's single-point error per model (cm) and the curator's edits.
std::string perObjectMarkdown(const EvaluationReport& r) {
  std::ostringstream md;
  md << "\n## Per object (single-point error in cm, paper's metric; point edits)\n\n";
  modelColumnsHeader(md, "Object", r.modelNames, "Edits");
  for (const auto& object : r.perObject) {
    md << "| " << object.value("id", std::string()) << " |";
    for (const auto& n : r.modelNames) {
      const auto errors = object.find("paper_error_m");
      const bool has = errors != object.end() && errors->contains(n);
      md << ' ' << reportCell(has ? 100 * errors->at(n).get<double>() : NAN, "%.1f") << " |";
    }
    md << ' ' << objectEdits(object) << " |\n";
  }
  return md.str();
}
}  // namespace

int objectEdits(const nlohmann::json& object) {
  int edits = 0;
  if (const auto e = object.find("edits"); e != object.end())
    for (const auto& [model, kinds] : e->items())
      for (const auto& [kind, n] : kinds.items())
        if (n.is_number_integer()) edits += n.get<int>();
  return edits;
}

double objectPaperError(const nlohmann::json& object) {
  const auto errors = object.find("paper_error_m");
  if (errors == object.end()) return NAN;
  double sum = 0;
  int count = 0;
  for (const auto& [model, e] : errors->items())
    if (e.is_number() && std::isfinite(e.get<double>())) sum += e.get<double>(), ++count;
  return count ? sum / count : NAN;
}

std::string evaluatedData(const EvaluationReport& report) {
  std::string out = report.dataDir.string();
  for (const auto& dir : report.moreDataDirs) out += " + " + dir.string();
  return out;
}

std::string evaluationMarkdown(const EvaluationReport& r) {
  std::ostringstream md;
  md << "# SAGrid evaluation\n\nData: `" << evaluatedData(r) << "` — " << r.objects << " objects";
  if (r.failed) md << " (" << r.failed << " failed)";
  md << ". Models + point extraction: " << reportCell(r.modelMilliseconds, "%.0f")
     << " ms per object (features cached).\n\n";
  md << "## Mean localization error (m), paper's metric (Table II form)\n\n";
  modelColumnsHeader(md, "Method", r.modelNames, "Avg");
  for (const auto& m : r.methods) {
    md << "| " << m.method << " |";
    double sum = 0;
    int count = 0;
    for (const auto& n : r.modelNames) {
      const auto it = m.byModel.find(n);
      const double v = it == m.byModel.end() ? NAN : it->second.paperError;
      if (std::isfinite(v)) sum += v, ++count;
      md << ' ' << reportCell(v, "%.4f") << " |";
    }
    md << ' ' << reportCell(count ? sum / count : NAN, "%.4f") << " |\n";
  }
  md << "\n## Multiple instances (Hungarian-matched error in m; precision/recall within "
     << kMatchRadiusMeters * 100 << " cm; share of objects with the right count)\n\n"
     << "| Method | Model | Objects | Matched error | Precision | Recall | Right count |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const auto& m : r.methods)
    for (const auto& n : r.modelNames) {
      const auto it = m.byModel.find(n);
      if (it == m.byModel.end()) continue;
      const TypeMetrics& t = it->second;
      md << "| " << m.method << " | " << n << " | " << t.objects << " | "
         << reportCell(t.matchedError, "%.4f") << " | "
         << reportCell(100 * t.precision, "%.1f %%") << " | "
         << reportCell(100 * t.recall, "%.1f %%") << " | "
         << reportCell(100 * t.countRight, "%.1f %%") << " |\n";
    }
  md << "\n## Curator effort (SAGrid auto count; " << kMatchRadiusMeters * 100
     << " cm tolerance)\n\nPoint edits per object: a predicted point too far from its matched "
        "truth is dragged, an extra one deleted, a missing one added. By hand, every point is "
        "placed.\n\n"
     << "| Objects | Edits / object | Drags | Deletions | Additions | By hand (points / object) "
        "| Edits ÷ by hand | Right with one key |\n|---|---|---|---|---|---|---|---|\n";
  auto effortRow = [&](const std::string& label, const CuratorEffort& e) {
    md << "| " << label << e.objects << " | " << reportCell(e.editsPerObject, "%.2f") << " | "
       << reportCell(e.dragsPerObject, "%.2f") << " | "
       << reportCell(e.deletionsPerObject, "%.2f") << " | "
       << reportCell(e.additionsPerObject, "%.2f") << " | "
       << reportCell(e.handPointsPerObject, "%.2f") << " | "
       << reportCell(e.editsPerObject / e.handPointsPerObject, "%.2f") << " | "
       << reportCell(100 * e.oneKeyShare, "%.1f %%") << " |\n";
  };
  effortRow("all: ", r.effort);
  for (const auto& [category, e] : r.effortByCategory) effortRow(category + ": ", e);
  if (r.bySource.size() > 1) {
    md << "\n## By source\n\nEach repository, library or dataset folder the objects come from "
          "(objects of one source look alike: read a rule's worth source by source). Single-point "
          "error: the paper's metric, averaged over the source's objects and models.\n\n"
       << "| Source | Objects | Single-point error | Edits ÷ by hand | Right with one key |\n"
       << "|---|---|---|---|---|\n";
    for (const auto& [source, f] : r.bySource)
      md << "| " << source << " | " << f.effort.objects << " | "
         << reportCell(100 * f.paperError, "%.1f cm") << " | "
         << reportCell(f.effort.editsPerObject / f.effort.handPointsPerObject, "%.2f") << " | "
         << reportCell(100 * f.effort.oneKeyShare, "%.1f %%") << " |\n";
  }
  md << countBreakdownMarkdown(countBreakdown(r.perObject, kMethodNames[kAuto]));
  md << perObjectMarkdown(r);
  md << "\n## Object confidence (" << (r.confidenceCalibrated ? "calibrated" : "uncalibrated")
     << "): does it predict \"right with one key\"?\n\n"
     << reliabilityMarkdown(r.reliability);
  return md.str();
}

nlohmann::json evaluationJson(const EvaluationReport& r) {
  nlohmann::json j;
  j["data"] = r.dataDir.string();
  if (!r.moreDataDirs.empty()) {
    j["more_data"] = nlohmann::json::array();
    for (const auto& dir : r.moreDataDirs) j["more_data"].push_back(dir.string());
  }
  j["objects"] = r.objects;
  j["failed"] = r.failed;
  j["model_ms_per_object"] = r.modelMilliseconds;
  j["models"] = r.modelNames;
  auto number = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  for (const auto& m : r.methods)
    for (const auto& [name, t] : m.byModel)
      j["methods"][m.method][name] = {{"objects", t.objects},
                                      {"paper_error_m", number(t.paperError)},
                                      {"matched_error_m", number(t.matchedError)},
                                      {"precision", number(t.precision)},
                                      {"recall", number(t.recall)},
                                      {"count_right", number(t.countRight)}};
  auto effortJson = [&](const CuratorEffort& e) {
    return nlohmann::json{{"objects", e.objects},
                          {"edits_per_object", number(e.editsPerObject)},
                          {"drags_per_object", number(e.dragsPerObject)},
                          {"deletions_per_object", number(e.deletionsPerObject)},
                          {"additions_per_object", number(e.additionsPerObject)},
                          {"hand_points_per_object", number(e.handPointsPerObject)},
                          {"one_key_share", number(e.oneKeyShare)}};
  };
  j["curator_effort"] = effortJson(r.effort);
  for (const auto& [category, e] : r.effortByCategory)
    j["curator_effort_by_category"][category] = effortJson(e);
  for (const auto& [source, f] : r.bySource) {
    j["by_source"][source] = effortJson(f.effort);
    j["by_source"][source]["paper_error_m"] = number(f.paperError);
    j["by_source"][source]["paper_errors"] = f.paperErrors;
  }
  j["confidence_calibrated"] = r.confidenceCalibrated;
  j["reliability"] = toJson(r.reliability);
  if (const auto breakdown = countBreakdown(r.perObject, kMethodNames[kAuto]); !breakdown.empty())
    j["count_by_generator"] = countBreakdownJson(breakdown);
  j["per_object"] = r.perObject;
  return j;
}

void writeEvaluationReport(const EvaluationReport& r, const fs::path& outDir) {
  fs::create_directories(outDir);
  writeFileAtomic(outDir / "eval.md", evaluationMarkdown(r));
  writeFileAtomic(outDir / "eval.json", evaluationJson(r).dump(2) + "\n");
  plot::BarChart chart;
  chart.title = "Mean localization error (m)";
  chart.yLabel = "m (lower is better)";
  for (const auto& m : r.methods) chart.methods.push_back(m.method);
  for (const auto& n : r.modelNames) {
    plot::BarGroup g;
    g.label = paperColumnName(n);
    for (const auto& m : r.methods) {
      const auto it = m.byModel.find(n);
      g.values.push_back(it == m.byModel.end() ? NAN : it->second.paperError);
    }
    chart.groups.push_back(g);
  }
  plot::writeBarChartPng(outDir / "eval.png", chart, 1000, 500);
  writeReliabilityPng(outDir / "reliability.png", r.reliability);
}

}  // namespace sagrid
