#include "core/training/trainer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/model/affordance_model_impl.h"
#include "core/training/sample_mixing.h"

namespace sagrid::model {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kDefaultEpochs = 40;

NetworkObject toNetworkObject(const TrainingSample& s) {
  NetworkObject o;
  o.voxels = s.voxels;
  o.features = s.features;
  o.descriptor = s.descriptor;
  return o;
}

// Mean over objects of the per-object (weighted) mean |pred - target| (paper: L1 over occupied
// voxels, uniform weights when nearWeight = 0).
torch::Tensor batchLoss(const torch::Tensor& predicted, const NetworkBatch& batch,
                        const std::vector<float>& targets, float nearWeight = 0,
                        float nearRadius = 0.05f) {
  const std::int64_t n = batch.voxelCount();
  std::vector<float> weights(static_cast<std::size_t>(n));
  for (int o = 0; o < batch.batchSize(); ++o) {
    double sum = 0;
    for (auto v = batch.offsets[o]; v < batch.offsets[o + 1]; ++v) {
      // targets hold log(1 + d): recover d for the weight.
      weights[v] = 1.0f + nearWeight * std::exp(-std::expm1(targets[v]) / nearRadius);
      sum += weights[v];
    }
    for (auto v = batch.offsets[o]; v < batch.offsets[o + 1]; ++v)
      weights[v] = static_cast<float>(weights[v] / (sum * batch.batchSize()));
  }
  const auto device = predicted.device();
  const torch::Tensor target =
      torch::from_blob(const_cast<float*>(targets.data()), {n}).clone().to(device);
  const torch::Tensor w = torch::from_blob(weights.data(), {n}).clone().to(device);
  return (w * (predicted - target).abs()).sum();
}

struct Checkpoint {
  int epochsDone = 0;
  std::size_t stepsTotal = 0;  // the plan; the last epoch may be cut short by a time budget
  std::vector<EpochRecord> curve;
};

nlohmann::json curveToJson(const std::vector<EpochRecord>& curve) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& e : curve) j.push_back({e.epoch, e.loss, e.learningRate, e.seconds});
  return j;
}

void saveCheckpoint(const fs::path& file, SAGridNet& net, torch::optim::AdamW& optimizer,
                    const Checkpoint& state, const ModelCard& card) {
  torch::serialize::OutputArchive archive, netArchive, optimizerArchive;
  for (const auto& p : net->named_parameters()) netArchive.write(p.key(), p.value().detach().cpu());
  for (const auto& b : net->named_buffers()) netArchive.write(b.key(), b.value().cpu(), true);
  optimizer.save(optimizerArchive);
  archive.write("net", netArchive);
  archive.write("optimizer", optimizerArchive);
  const nlohmann::json meta = {{"epochs_done", state.epochsDone},
                               {"steps_total", state.stepsTotal},
                               {"architecture", card.architecture},
                               {"name", card.name},
                               {"curve", curveToJson(state.curve)}};
  archive.write("meta", c10::IValue(meta.dump()));
  std::ostringstream out;
  archive.save_to(out);
  writeFileAtomic(file, out.str());
}

// `stepsPerEpoch` reads the plan of checkpoints written before it was kept in steps
// ("epochs_total" full epochs).
bool loadCheckpoint(const fs::path& file, SAGridNet& net, torch::optim::AdamW& optimizer,
                    Checkpoint& state, const ModelCard& card, std::size_t stepsPerEpoch) {
  if (!fs::exists(file)) return false;
  torch::serialize::InputArchive archive, netArchive, optimizerArchive;
  nlohmann::json meta;
  try {
    std::istringstream in(readFileBytes(file));
    archive.load_from(in);
    c10::IValue metaValue;
    archive.read("meta", metaValue);
    meta = nlohmann::json::parse(metaValue.toStringRef());
    archive.read("net", netArchive);
    archive.read("optimizer", optimizerArchive);
  } catch (const c10::Error&) {
    throw FileError(file, "checkpoint is truncated or corrupt; delete it to start over");
  }
  if (meta.value("architecture", "") != card.architecture || meta.value("name", "") != card.name)
    throw ModelError(file.string() + ": checkpoint is for " + meta.value("name", "?") + " " +
                     meta.value("architecture", "?") + ", not " + card.name + " " +
                     card.architecture + "; delete it or train without --resume");
  torch::NoGradGuard noGrad;
  for (auto& p : net->named_parameters()) {
    torch::Tensor v;
    netArchive.read(p.key(), v);
    p.value().copy_(v);
  }
  for (auto& b : net->named_buffers()) {
    torch::Tensor v;
    netArchive.read(b.key(), v, true);
    b.value().copy_(v);
  }
  optimizer.load(optimizerArchive);
  state.epochsDone = meta.at("epochs_done").get<int>();
  state.stepsTotal = meta.contains("steps_total")
                         ? meta.at("steps_total").get<std::size_t>()
                         : meta.at("epochs_total").get<std::size_t>() * stepsPerEpoch;
  for (const auto& e : meta.at("curve"))
    state.curve.push_back(
        {e[0].get<int>(), e[1].get<double>(), e[2].get<double>(), e[3].get<double>()});
  return true;
}

// The parameters a fine-tune of `part` trains. The others take no gradient (backward then stops
// at the last layer) and, for the head, batch norm keeps the init model's statistics, until the
// scope ends.
class AdaptationScope {
 public:
  AdaptationScope(SAGridNet& net, AdaptedPart part) : m_net(net) {
    if (part == AdaptedPart::Everything) {
      trained = net->parameters();
      return;
    }
    trained = net->lastLayerParameters();
    for (auto& p : net->parameters()) {
      const bool isTrained = std::any_of(trained.begin(), trained.end(),
                                         [&](const torch::Tensor& t) { return t.is_same(p); });
      if (!isTrained && p.requires_grad()) {
        p.requires_grad_(false);
        m_frozen.push_back(p);
      }
    }
    net->setFrozenStatistics(true);
  }
  ~AdaptationScope() {
    for (auto& p : m_frozen) p.requires_grad_(true);
    m_net->setFrozenStatistics(false);
  }
  AdaptationScope(const AdaptationScope&) = delete;
  AdaptationScope& operator=(const AdaptationScope&) = delete;

  std::vector<torch::Tensor> trained;

 private:
  SAGridNet& m_net;
  std::vector<torch::Tensor> m_frozen;
};

}  // namespace

const char* toString(AdaptedPart part) {
  return part == AdaptedPart::Head ? "head" : "everything";
}

AdaptedPart parseAdaptedPart(const std::string& text) {
  if (text == "everything") return AdaptedPart::Everything;
  if (text == "head") return AdaptedPart::Head;
  throw InvalidArgument("adapted part \"" + text + "\": expected everything or head");
}

std::size_t plannedSteps(std::size_t stepsDone, double elapsedSeconds, double secondsPerStep,
                         double budgetSeconds) {
  const double left = budgetSeconds - elapsedSeconds;
  const std::size_t atLeast = std::max<std::size_t>(1, stepsDone);
  if (!(secondsPerStep > 0) || !(left > 0)) return atLeast;
  const double more = std::floor(std::min(left / secondsPerStep, 1e12));
  return std::max(atLeast, stepsDone + static_cast<std::size_t>(more));
}

std::vector<EpochRecord> trainModel(AffordanceModel& model,
                                    const std::vector<TrainingSample>& samples,
                                    const TrainingOptions& options) {
  if (samples.empty()) throw InvalidArgument("training: no training objects");
  if (!options.sampleWeights.empty() && options.sampleWeights.size() != samples.size())
    throw InvalidArgument("training: " + std::to_string(options.sampleWeights.size()) +
                          " sampling weights for " + std::to_string(samples.size()) + " samples");
  for (const auto& s : samples)
    if (s.targets.empty()) throw InvalidArgument("training: object " + s.id + " has no targets");
  configureTorchRuntime();
  AffordanceModelImpl& impl = model.impl();
  SAGridNet& net = impl.net;
  const AdaptationScope adaptation(net, options.adapted);
  torch::optim::AdamW optimizer(
      adaptation.trained,
      torch::optim::AdamWOptions(options.learningRate).weight_decay(options.weightDecay));

  const int batchSize = std::max(1, options.batchSize);
  const std::size_t stepsPerEpoch = (samples.size() + batchSize - 1) / batchSize;
  Checkpoint state;
  if (options.resume && !options.checkpointFile.empty() &&
      loadCheckpoint(options.checkpointFile, net, optimizer, state, impl.card, stepsPerEpoch))
    logger()->info("resuming {} after epoch {}", impl.card.name, state.epochsDone);
  if (state.stepsTotal == 0)
    state.stepsTotal =
        static_cast<std::size_t>(options.epochs > 0 ? options.epochs : kDefaultEpochs) *
        stepsPerEpoch;
  // A time budget plans in steps, anew before every step from the pace of the current epoch so
  // far (the last epoch's at an epoch's first step): a machine that gets busy shortens the run,
  // and the last epoch may stop part way. A resumed run keeps its plan.
  const bool timed = options.epochs <= 0 && options.minutes > 0 && state.epochsDone == 0;
  const double budgetSeconds = options.minutes * 60.0;
  const double secondsBefore = state.curve.empty() ? 0.0 : state.curve.back().seconds;
  const auto start = Clock::now();
  auto elapsed = [&] { return secondsSince(start); };
  double lastStepSeconds = 0;  // the pace of the last epoch

  net->train();
  std::size_t stepsDone = static_cast<std::size_t>(state.epochsDone) * stepsPerEpoch;
  for (int epoch = state.epochsDone + 1; stepsDone < state.stepsTotal; ++epoch) {
    // Seeded per epoch, so a resumed run continues with the same draws as an uninterrupted one.
    std::mt19937 rng(options.seed * 7919u + static_cast<unsigned>(epoch));
    torch::manual_seed(options.seed * 7919u + static_cast<unsigned>(epoch));
    const std::vector<std::size_t> order = drawEpochOrder(samples.size(), options.sampleWeights, rng);
    const double epochStart = elapsed();
    double lossSum = 0;
    double lr = options.learningRate;
    std::size_t step = 0;
    for (; step < stepsPerEpoch; ++step, ++stepsDone) {
      if (options.cancel && options.cancel->load()) throw Cancelled();
      if (timed) {
        const double pace =
            step > 0 ? (elapsed() - epochStart) / static_cast<double>(step) : lastStepSeconds;
        if (pace > 0) state.stepsTotal = plannedSteps(stepsDone, elapsed(), pace, budgetSeconds);
      }
      if (stepsDone >= state.stepsTotal) break;
      // Cosine schedule over all steps of the run, from learningRate down to 1% of it.
      const double progress =
          static_cast<double>(stepsDone) / static_cast<double>(state.stepsTotal);
      lr = options.learningRate * (0.01 + 0.99 * 0.5 * (1.0 + std::cos(M_PI * progress)));
      for (auto& group : optimizer.param_groups())
        static_cast<torch::optim::AdamWOptions&>(group.options()).lr(lr);

      std::vector<NetworkObject> objects;
      std::vector<float> targets;
      for (std::size_t b = step * batchSize; b < std::min(samples.size(), (step + 1) * batchSize);
           ++b) {
        const TrainingSample& s = samples[order[b]];
        TrainingSample a =
            augment(s, randomAugmentation(s, options.augmentation, rng), options.vectorChannels);
        if (a.voxels.empty() || a.targets.empty()) a = s;
        const auto d = distanceTargets(a, options.targetCap);
        targets.insert(targets.end(), d.begin(), d.end());
        objects.push_back(toNetworkObject(a));
      }
      std::vector<const NetworkObject*> pointers;
      for (const auto& o : objects) pointers.push_back(&o);
      const NetworkBatch batch = makeNetworkBatch(pointers, impl.shape, impl.mode, impl.device);
      optimizer.zero_grad();
      torch::Tensor loss = batchLoss(net->forward(batch, impl.mode), batch, targets,
                                     options.nearWeight, options.nearRadius);
      loss.backward();
      optimizer.step();
      lossSum += loss.item<double>();
      if (options.onProgress) {
        TrainingProgress p;
        p.epoch = epoch;
        p.epochs = static_cast<int>((state.stepsTotal + stepsPerEpoch - 1) / stepsPerEpoch);
        p.step = stepsDone + 1;
        p.steps = state.stepsTotal;
        p.loss = lossSum / static_cast<double>(step + 1);
        p.seconds = secondsBefore + elapsed();
        options.onProgress(p);
      }
    }
    if (step == 0) break;  // the budget ran out at the epoch's start
    lastStepSeconds = (elapsed() - epochStart) / static_cast<double>(step);
    if (timed)
      logger()->info(
          "{}: epoch {} ({} steps) took {:.1f} s, {:.1f} of {:.1f} s left: {} steps "
          "in all",
          impl.card.name, epoch, step, elapsed() - epochStart, budgetSeconds - elapsed(),
          budgetSeconds, state.stepsTotal);
    state.epochsDone = epoch;
    state.curve.push_back(
        {epoch, lossSum / static_cast<double>(step), lr, secondsBefore + elapsed()});
    if (!options.checkpointFile.empty()) {
      const auto saveStart = Clock::now();
      saveCheckpoint(options.checkpointFile, net, optimizer, state, impl.card);
      logger()->info("{}: epoch {} loss {:.5f}, checkpoint written in {:.2f} s", impl.card.name,
                     epoch, state.curve.back().loss, secondsSince(saveStart));
    }
  }
  net->eval();
  return state.curve;
}

double evaluateLoss(AffordanceModel& model, const std::vector<TrainingSample>& samples,
                    float targetCap, bool batchStatistics) {
  AffordanceModelImpl& impl = model.impl();
  torch::NoGradGuard noGrad;
  // Training-mode batch norm updates the running statistics: keep a copy and put it back.
  std::vector<torch::Tensor> buffers;
  if (batchStatistics)
    for (const auto& b : impl.net->buffers()) buffers.push_back(b.clone());
  impl.net->train(batchStatistics);
  double sum = 0;
  for (const auto& s : samples) {
    const NetworkObject o = toNetworkObject(s);
    const NetworkBatch batch = makeNetworkBatch({&o}, impl.shape, impl.mode, impl.device);
    sum += batchLoss(impl.net->forward(batch, impl.mode), batch, distanceTargets(s, targetCap))
               .item<double>();
  }
  if (batchStatistics) {
    auto current = impl.net->buffers();
    for (std::size_t b = 0; b < current.size(); ++b) current[b].copy_(buffers[b]);
    impl.net->eval();
  }
  return samples.empty() ? 0.0 : sum / static_cast<double>(samples.size());
}

}  // namespace sagrid::model
