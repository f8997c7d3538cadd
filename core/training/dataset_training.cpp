#include "core/training/dataset_training.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/features/vector_channels.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/model/affordance_model.h"
#include "core/model/architecture.h"
#include "core/model/model_ensemble.h"
#include "core/plot/plot.h"
#include "core/training/sample_mixing.h"

namespace sagrid {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

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

namespace {

// One dataset's usable samples (objects of the category with the type, features computed).
struct LoadedDataset {
  TrainingDataSource source;
  std::vector<TrainingSample> samples;
  std::size_t objects = 0, ofCategory = 0, skipped = 0, failed = 0, used = 0;
  std::string configHash;
};

// Throws ModelError naming both values when the init model and the requested one differ.
void checkInitMatches(const model::ModelCard& init, const model::ModelCard& requested,
                      const fs::path& initCard) {
  if (const auto d = model::networkDifference(init, requested))
    throw ModelError("--init " + initCard.string() + ": " + d->what + " differs: the init model " +
                     init.name + " has " + d->a + ", the requested " + requested.name + " has " +
                     d->b + "; fine-tuning keeps the network and its input, so they must match");
}

// A training sample's features as the grid a prediction reads.
FeatureGrid sampleFeatureGrid(const TrainingSample& s, const model::ModelCard& card) {
  FeatureGrid g;
  g.backend = card.featureBackend;
  g.configHash = card.featureConfigHash;
  g.resolution = s.resolution;
  g.channels = s.channels;
  g.voxels = s.voxels;
  g.values = s.features;
  g.descriptor = s.descriptor;
  return g;
}

}  // namespace

DatasetTrainingResult trainFromDataset(const DatasetTrainingOptions& options) {
  const auto callStart = Clock::now();
  const auto [category, type] = model::splitModelName(options.modelName);
  std::vector<TrainingDataSource> sources = options.datasets;
  if (sources.empty()) {
    if (options.dataDir.empty()) throw InvalidArgument("training: no dataset given");
    sources.push_back({options.dataDir, 1.0, "data", {}});
  }
  const std::vector<std::array<int, 3>> vectorChannels =
      vectorChannelTriples(featureChannelNames(options.features));
  // Resolved before the (slow) feature extraction, so a wrong --init fails at once.
  fs::path initCard;
  std::optional<model::ModelCard> init;
  if (!options.init.empty()) {
    initCard = resolveInitCard(options.init, options.modelName);
    init = model::readModelCard(initCard);
  }
  if (options.keepInitNetworks && !init)
    throw InvalidArgument("keeping the init model's networks needs an init model (--init)");

  // Read every manifest first, so feature progress counts over all datasets.
  std::vector<std::vector<DatasetEntry>> entries;
  std::size_t totalEntries = 0;
  for (const auto& source : sources) {
    entries.push_back(readDataset(source.dir, source.referenceRoot));
    if (entries.back().empty())
      throw InvalidArgument("dataset " + source.dir.string() +
                            " has no objects (expected manifest.jsonl or object folders with "
                            "labels.json and a mesh)");
    totalEntries += entries.back().size();
  }

  DatasetTrainingResult result;
  std::vector<LoadedDataset> loaded;
  std::size_t done = 0;
  const auto featureStart = Clock::now();
  for (std::size_t d = 0; d < sources.size(); ++d) {
    LoadedDataset data;
    data.source = sources[d];
    FeatureOptions features = options.features;
    if (!data.source.cacheDir.empty())
      features.cacheDir = data.source.cacheDir;
    else if (features.cacheDir.empty())
      features.cacheDir = data.source.dir / ".sagrid-cache";
    data.objects = entries[d].size();
    for (const DatasetEntry& entry : entries[d]) {
      if (options.onFeatureProgress) options.onFeatureProgress(done, totalEntries, entry.id);
      ++done;
      ObjectLabels labels = readLabels(entry.labels);
      const std::string objectCategory =
          entry.category.empty() ? labels.object.category : entry.category;
      if (objectCategory != category) continue;
      ++data.ofCategory;
      if (labels.ofType(type).empty()) {
        ++data.skipped;
        continue;
      }
      FeatureGrid grid;
      try {
        // Features in the frame the labels were written in (a y-up OBJ, as Sweet Home 3D writes
        // them, would otherwise be read z-up while its targets are mapped from y-up).
        FeatureOptions objectFeatures = features;
        objectFeatures.up = upAxisOrZ(labels.object.up);
        grid = extractFeatures(entry.mesh, objectFeatures);
      } catch (const Error& error) {
        logger()->warn("skipping {}: {}", entry.id, error.what());
        ++data.failed;
        continue;
      }
      data.configHash = grid.configHash;
      data.samples.push_back(
          makeTrainingSample(entry.id, grid, normalizedTargets(labels, type, grid)));
    }
    if (data.ofCategory == 0)
      throw InvalidArgument("dataset " + data.source.dir.string() + " has no " + category +
                            " objects for model " + options.modelName + " (" +
                            std::to_string(data.objects) + " objects in total)");
    if (data.samples.empty())
      throw InvalidArgument("dataset " + data.source.dir.string() + ": none of its " +
                            std::to_string(data.ofCategory) + " " + category + " objects has a " +
                            type + " affordance for model " + options.modelName +
                            (data.failed ? " with usable features" : std::string()));
    if (data.skipped)
      logger()->warn("{}: skipped {} {} objects without a {} affordance in {}", options.modelName,
                     data.skipped, category, type, data.source.dir.string());
    result.objectsSkipped += data.skipped;
    result.objectsFailed += data.failed;
    loaded.push_back(std::move(data));
  }
  if (options.onFeatureProgress) options.onFeatureProgress(totalEntries, totalEntries, "");
  result.featureSeconds = secondsSince(featureStart);

  std::vector<TrainingSample> samples;
  std::vector<std::size_t> sizes;
  std::vector<double> weights;
  std::string configHash;
  for (auto& data : loaded) {
    data.used = data.samples.size();
    sizes.push_back(data.used);
    weights.push_back(data.source.weight);
    configHash = data.configHash;
    for (auto& s : data.samples) samples.push_back(std::move(s));
    data.samples.clear();
  }

  model::ModelCard card;
  card.name = options.modelName;
  card.category = category;
  card.type = type;
  std::string architecture = options.architecture;
  if (architecture.empty())
    architecture = init ? init->architecture : std::string(model::kDefaultArchitecture);
  card.architecture = model::Architecture::parse(architecture).toString();
  card.mode = model::toString(model::parseExecutionMode(options.mode));
  card.featureBackend = options.features.backend;
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

  // Kept beside the init's networks, the fine-tuned network is saved apart first.
  const fs::path saveDir = options.keepInitNetworks
                               ? options.outDir / ("." + options.modelName + ".fine-tune")
                               : options.outDir;
  fs::create_directories(saveDir);
  result.cardFile = saveDir / (options.modelName + ".json");
  model::TrainingOptions training = options.training;
  training.vectorChannels = vectorChannels;
  if (sources.size() > 1) training.sampleWeights = mixedSampleWeights(sizes, weights);
  if (training.checkpointFile.empty())
    training.checkpointFile = options.outDir / (options.modelName + ".checkpoint");
  if (init) {
    checkInitMatches(*init, card, initCard);
    if (options.lossFromInit) {
      training.targetCap = init->training.value("target_cap", training.targetCap);
      training.nearWeight = init->training.value("near_weight", training.nearWeight);
      training.nearRadius = init->training.value("near_radius", training.nearRadius);
    }
  }
  // With --resume, a checkpoint (written by an interrupted run of this same fine-tune) replaces
  // these weights inside trainModel: resume wins over init.
  model::AffordanceModel net =
      init ? model::AffordanceModel::load(initCard) : model::AffordanceModel(card, training.seed);
  if (init) net.card() = card;
  if (training.epochs <= 0 && training.minutes > 0) {
    // A time budget is the whole call's: what the features took, and what the count calibration
    // after the loop will take (a prediction timed now, times the objects; the faster of two, as
    // the first one warms up), come off the loop's share; at least one step runs whatever is left.
    double predictionSeconds = 0;
    for (int attempt = 0; attempt < 2; ++attempt) {
      const auto predictionStart = Clock::now();
      net.predictDistances(sampleFeatureGrid(samples[attempt % samples.size()], card));
      const double seconds = secondsSince(predictionStart);
      predictionSeconds = attempt == 0 ? seconds : std::min(predictionSeconds, seconds);
    }
    const double calibrationSeconds = predictionSeconds * static_cast<double>(samples.size());
    const double loopSeconds =
        training.minutes * 60.0 - secondsSince(callStart) - calibrationSeconds;
    logger()->info(
        "{}: {:.1f} of {:.1f} s for the training loop ({:.1f} s features so far, "
        "{:.1f} s kept for the count calibration)",
        options.modelName, std::max(loopSeconds, 0.0), training.minutes * 60.0,
        secondsSince(callStart), calibrationSeconds);
    training.minutes = std::max(loopSeconds, 1.0) / 60.0;
  }
  const auto trainStart = Clock::now();
  result.curve = model::trainModel(net, samples, training);
  result.trainingSeconds = secondsSince(trainStart);

  // Calibrate the automatic instance count on the training objects (no augmentation).
  std::vector<PredictedField> fields;
  std::vector<std::vector<Eigen::Vector3f>> truths;
  double argminError = 0;
  for (const auto& s : samples) {
    PredictedField f{s.resolution, s.voxels, net.predictDistances(sampleFeatureGrid(s, card))};
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
  // A fine-tune changes the field, so by default it recalibrates on its training objects (new
  // data and replay together, as training from scratch calibrates on its training set); with too
  // few of them it keeps the init model's calibration.
  result.recalibrated = !init || samples.size() >= kMinCalibrationObjects;
  if (result.recalibrated) {
    ExtractionSettings extraction = calibrateExtraction(fields, truths, refined);
    extraction.confidenceScale = extraction.maxDistance;
    net.card().extraction = extraction;
  } else {
    net.card().extraction = init->extraction;
  }
  // Whether annotate runs the second pass for this model, and whether its candidates include
  // crease patches, are choices about the model, not calibrations: kept from the init card unless
  // the caller says.
  net.card().extraction.coarseToFine =
      options.coarseToFine.value_or(init && init->extraction.coarseToFine);
  net.card().extraction.creasePatches =
      options.creasePatches.value_or(init && init->extraction.creasePatches);

  auto& c = net.card();
  nlohmann::json datasets = nlohmann::json::array();
  for (const auto& data : loaded) {
    const DatasetFingerprint fingerprint = datasetFingerprint(data.source.dir);
    datasets.push_back({{"path", fs::absolute(data.source.dir).lexically_normal().string()},
                        {"sha256", fingerprint.sha256},
                        {"sha256_of", fingerprint.of},
                        {"weight", data.source.weight},
                        {"objects", data.used},
                        {"role", data.source.role}});
  }
  c.training = {{"data", fs::absolute(loaded.front().source.dir).lexically_normal().string()},
                {"datasets", datasets},
                {"command", options.command},
                {"mode", c.mode},  // the mode these weights were trained in (card validation)
                {"objects", samples.size()},
                {"skipped_without_type", result.objectsSkipped},
                {"failed_features", result.objectsFailed},
                {"epochs", result.curve.empty() ? 0 : result.curve.back().epoch},
                {"batch_size", training.batchSize},
                {"learning_rate", training.learningRate},
                {"adapted", model::toString(training.adapted)},
                {"weight_decay", training.weightDecay},
                {"seed", training.seed},
                {"target_cap", training.targetCap},
                {"near_weight", training.nearWeight},
                {"near_radius", training.nearRadius},
                {"seconds", result.curve.empty() ? 0.0 : result.curve.back().seconds},
                {"feature_seconds", result.featureSeconds},
                {"cuda", model::cudaAvailable()},
                {"point_extraction", result.recalibrated ? "calibrated on the training objects"
                                                         : "kept from the init model"}};
  if (init)
    c.training["init"] = {{"path", fs::absolute(initCard).lexically_normal().string()},
                          {"name", init->name},
                          {"card_sha256", sha256Hex(readFileBytes(initCard))},
                          {"weights_sha256", init->weightsSha256}};
  c.metrics["final_train_loss"] = result.curve.empty() ? 0.0 : result.curve.back().loss;
  c.metrics["train_argmin_error_normalized"] = argminError / samples.size();
  net.save(result.cardFile);
  writeLossCurve(options.outDir / (options.modelName + ".loss.csv"),
                 options.outDir / (options.modelName + ".loss.png"), options.modelName,
                 result.curve);
  result.card = net.card();
  if (options.keepInitNetworks) {
    result.cardFile = model::keepInitNetworks(initCard, result.cardFile, options.outDir);
    result.card = model::readModelCard(result.cardFile);
    result.recalibrated = false;  // the init's point extraction
    fs::remove_all(saveDir);
  }
  std::error_code ignored;
  fs::remove(training.checkpointFile, ignored);  // finished: the weights are saved
  result.objectsUsed = samples.size();
  return result;
}

}  // namespace sagrid
