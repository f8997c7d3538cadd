#include "core/training/dataset_training.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/dataset/dataset.h"
#include "core/features/vector_channels.h"
#include "core/labels/labels.h"
#include "core/model/affordance_model.h"
#include "core/model/architecture.h"
#include "core/plot/plot.h"

namespace sagrid {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Per-dimension mean and standard deviation of the training objects' descriptors, for category
// retrieval.
void setDescriptorStatistics(const std::vector<TrainingSample>& samples, model::ModelCard& card) {
  const std::size_t size = samples.front().descriptor.size();
  std::vector<double> sum(size, 0.0), squares(size, 0.0);
  for (const auto& s : samples)
    for (std::size_t d = 0; d < size && d < s.descriptor.size(); ++d) {
      sum[d] += s.descriptor[d];
      squares[d] += static_cast<double>(s.descriptor[d]) * s.descriptor[d];
    }
  const double n = static_cast<double>(samples.size());
  card.descriptorMean.clear();
  card.descriptorStd.clear();
  for (std::size_t d = 0; d < size; ++d) {
    const double mean = sum[d] / n;
    card.descriptorMean.push_back(static_cast<float>(mean));
    card.descriptorStd.push_back(
        static_cast<float>(std::sqrt(std::max(0.0, squares[d] / n - mean * mean))));
  }
}

// Mean feature vector at the ground-truth points: the occupied voxel nearest to each point
// (the Embedding Search baseline of the paper's Table II).
void addAffordanceFeatures(const TrainingSample& s, std::vector<double>& sum, std::size_t& count) {
  for (const auto& t : s.targets) {
    std::size_t best = 0;
    float bestDistance = 1e9f;
    for (std::size_t v = 0; v < s.voxels.size(); ++v) {
      const float d = (voxelCenter(s.voxels[v], s.resolution) - t).squaredNorm();
      if (d < bestDistance) bestDistance = d, best = v;
    }
    for (int c = 0; c < s.channels; ++c) sum[c] += s.features[best * s.channels + c];
    ++count;
  }
}

void writeLossCurve(const fs::path& csv, const fs::path& png, const std::string& name,
                    const std::vector<model::EpochRecord>& curve) {
  std::ostringstream out;
  out << "epoch,loss,learning_rate,seconds\n";
  for (const auto& e : curve)
    out << e.epoch << ',' << e.loss << ',' << e.learningRate << ',' << e.seconds << '\n';
  writeFileAtomic(csv, out.str());
  plot::LinePlot p;
  p.title = name + " training loss";
  p.xLabel = "epoch";
  p.yLabel = "L1 loss on log(1 + distance)";
  plot::Series s;
  s.name = "train";
  for (const auto& e : curve) s.x.push_back(e.epoch), s.y.push_back(e.loss);
  p.series.push_back(s);
  writeLinePlotPng(png, p);
}

}  // namespace

const std::vector<std::string>& defaultModelNames() {
  static const std::vector<std::string> names = {"stove.heatsource", "stove.togglebutton",
                                                 "sink.fluidsource", "sink.togglebutton"};
  return names;
}

DatasetTrainingResult trainFromDataset(const DatasetTrainingOptions& options) {
  const auto [category, type] = model::splitModelName(options.modelName);
  const std::vector<DatasetEntry> entries = readDataset(options.dataDir);
  if (entries.empty())
    throw InvalidArgument("dataset " + options.dataDir.string() +
                          " has no objects (expected manifest.jsonl or object folders with "
                          "labels.json and a mesh)");
  FeatureOptions features = options.features;
  if (features.cacheDir.empty()) features.cacheDir = options.dataDir / ".sagrid-cache";
  const std::vector<std::array<int, 3>> vectorChannels =
      vectorChannelTriples(featureChannelNames(features));

  DatasetTrainingResult result;
  std::vector<TrainingSample> samples;
  std::string configHash;
  std::size_t ofCategory = 0;
  const auto featureStart = Clock::now();
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const DatasetEntry& entry = entries[e];
    if (options.onFeatureProgress) options.onFeatureProgress(e, entries.size(), entry.id);
    ObjectLabels labels = readLabels(entry.labels);
    const std::string objectCategory =
        entry.category.empty() ? labels.object.category : entry.category;
    if (objectCategory != category) continue;
    ++ofCategory;
    if (labels.ofType(type).empty()) {
      ++result.objectsSkipped;
      continue;
    }
    FeatureGrid grid;
    try {
      grid = extractFeatures(entry.mesh, features);
    } catch (const Error& error) {
      logger()->warn("skipping {}: {}", entry.id, error.what());
      ++result.objectsFailed;
      continue;
    }
    configHash = grid.configHash;
    samples.push_back(makeTrainingSample(entry.id, grid, normalizedTargets(labels, type, grid)));
  }
  if (options.onFeatureProgress) options.onFeatureProgress(entries.size(), entries.size(), "");
  result.featureSeconds = secondsSince(featureStart);
  if (ofCategory == 0)
    throw InvalidArgument("dataset " + options.dataDir.string() + " has no " + category +
                          " objects (" + std::to_string(entries.size()) + " objects in total)");
  if (samples.empty())
    throw InvalidArgument("dataset " + options.dataDir.string() + ": none of its " +
                          std::to_string(ofCategory) + " " + category + " objects has a " + type +
                          " affordance" +
                          (result.objectsFailed ? " with usable features" : std::string()));
  if (result.objectsSkipped)
    logger()->warn("{}: skipped {} {} objects without a {} affordance", options.modelName,
                   result.objectsSkipped, category, type);

  model::ModelCard card;
  card.name = options.modelName;
  card.category = category;
  card.type = type;
  card.architecture =
      model::Architecture::parse(options.architecture.empty() ? model::kDefaultArchitecture
                                                              : options.architecture)
          .toString();
  card.mode = model::toString(model::parseExecutionMode(options.mode));
  card.featureBackend = features.backend;
  card.featureConfigHash = configHash;
  card.featureChannels = samples.front().channels;
  card.descriptorSize = static_cast<int>(samples.front().descriptor.size());
  card.gridResolution = samples.front().resolution;
  setDescriptorStatistics(samples, card);
  std::vector<double> featureSum(card.featureChannels, 0.0);
  std::size_t featureCount = 0;
  for (const auto& s : samples) addAffordanceFeatures(s, featureSum, featureCount);
  for (double v : featureSum)
    card.affordanceFeatureMean.push_back(static_cast<float>(v / featureCount));

  fs::create_directories(options.outDir);
  result.cardFile = options.outDir / (options.modelName + ".json");
  model::TrainingOptions training = options.training;
  training.vectorChannels = vectorChannels;
  if (training.checkpointFile.empty())
    training.checkpointFile = options.outDir / (options.modelName + ".checkpoint");
  model::AffordanceModel net(card, training.seed);
  const auto trainStart = Clock::now();
  result.curve = model::trainModel(net, samples, training);
  result.trainingSeconds = secondsSince(trainStart);

  // Calibrate the automatic instance count on the training objects (no augmentation).
  std::vector<PredictedField> fields;
  std::vector<std::vector<Eigen::Vector3f>> truths;
  double argminError = 0;
  for (const auto& s : samples) {
    FeatureGrid g;
    g.backend = card.featureBackend;
    g.configHash = card.featureConfigHash;
    g.resolution = s.resolution;
    g.channels = s.channels;
    g.voxels = s.voxels;
    g.values = s.features;
    g.descriptor = s.descriptor;
    PredictedField f{s.resolution, s.voxels, net.predictDistances(g)};
    float nearest = 1e9f;
    const Eigen::Vector3f p = argminPoint(f, {}).position;
    for (const auto& t : s.targets) nearest = std::min(nearest, (p - t).norm());
    argminError += nearest;
    fields.push_back(std::move(f));
    truths.push_back(s.targets);
  }
  // Sub-voxel refinement: 4.22 -> 4.00 cm on bench val stove.heatsource (1-epoch model).
  ExtractionSettings refined;
  refined.refineVoxels = 2.0f;
  ExtractionSettings extraction = calibrateExtraction(fields, truths, refined);
  extraction.confidenceScale = extraction.maxDistance;
  net.card().extraction = extraction;

  auto& c = net.card();
  c.training = {{"data", fs::absolute(options.dataDir).lexically_normal().string()},
                {"command", options.command},
                {"objects", samples.size()},
                {"skipped_without_type", result.objectsSkipped},
                {"failed_features", result.objectsFailed},
                {"epochs", result.curve.empty() ? 0 : result.curve.back().epoch},
                {"batch_size", training.batchSize},
                {"learning_rate", training.learningRate},
                {"weight_decay", training.weightDecay},
                {"seed", training.seed},
                {"target_cap", training.targetCap},
                {"near_weight", training.nearWeight},
                {"near_radius", training.nearRadius},
                {"seconds", result.curve.empty() ? 0.0 : result.curve.back().seconds},
                {"feature_seconds", result.featureSeconds},
                {"cuda", model::cudaAvailable()}};
  c.metrics["final_train_loss"] = result.curve.empty() ? 0.0 : result.curve.back().loss;
  c.metrics["train_argmin_error_normalized"] = argminError / samples.size();
  net.save(result.cardFile);
  writeLossCurve(options.outDir / (options.modelName + ".loss.csv"),
                 options.outDir / (options.modelName + ".loss.png"), options.modelName,
                 result.curve);
  std::error_code ignored;
  fs::remove(training.checkpointFile, ignored);  // finished: the weights are saved
  result.card = net.card();
  result.objectsUsed = samples.size();
  return result;
}

}  // namespace sagrid
