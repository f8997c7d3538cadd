#include "core/model/affordance_model.h"

#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "core/common/atomic_file.h"
#include "core/common/blas_kernels.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/common/thread_count.h"
#include "core/model/affordance_model_impl.h"

namespace sagrid::model {
namespace fs = std::filesystem;

void configureTorchRuntime() {
  static const bool configured = [] {
    if (const char* kernels = blasKernelsNamed())
      spdlog::debug("BLAS kernels: {} (named at start-up; OPENBLAS_CORETYPE overrides)", kernels);
    torch::set_num_threads(defaultThreadCount());
    return true;
  }();
  (void)configured;
}

bool cudaAvailable() { return torch::cuda::is_available(); }

NetworkShape networkShapeOf(const ModelCard& card) {
  NetworkShape shape;
  shape.architecture = Architecture::parse(card.architecture);
  shape.featureChannels = card.featureChannels;
  shape.descriptorSize = card.descriptorSize;
  shape.resolution = card.gridResolution;
  return shape;
}

NetworkObject networkObjectOf(const FeatureGrid& f) {
  NetworkObject o;
  o.voxels = f.voxels;
  o.features = f.values;
  o.descriptor = f.descriptor;
  return o;
}

std::string serializeWeights(SAGridNet& net) {
  torch::serialize::OutputArchive archive;
  for (const auto& p : net->named_parameters()) archive.write(p.key(), p.value().detach().cpu());
  for (const auto& b : net->named_buffers()) archive.write(b.key(), b.value().cpu(), true);
  std::ostringstream out;
  archive.save_to(out);
  return out.str();
}

void deserializeWeights(SAGridNet& net, const std::string& bytes, const std::string& name) {
  torch::serialize::InputArchive archive;
  try {
    std::istringstream in(bytes);
    archive.load_from(in);
  } catch (const c10::Error& e) {
    throw FileError(name, "weights file is truncated or not a SAGrid weights archive");
  }
  torch::NoGradGuard noGrad;
  auto restore = [&](const std::string& key, torch::Tensor& target, bool isBuffer) {
    torch::Tensor value;
    try {
      if (!archive.try_read(key, value, isBuffer))
        throw ModelError(name + ": weights lack \"" + key + "\"; they do not belong to this card");
    } catch (const c10::Error&) {
      throw FileError(name, "weights file is corrupt (cannot read \"" + key + "\")");
    }
    if (value.sizes() != target.sizes())
      throw ModelError(name + ": weights \"" + key + "\" have shape " + c10::str(value.sizes()) +
                       " but the card's architecture needs " + c10::str(target.sizes()));
    target.copy_(value);
  };
  for (auto& p : net->named_parameters()) restore(p.key(), p.value(), false);
  for (auto& b : net->named_buffers()) restore(b.key(), b.value(), true);
}

AffordanceModel::AffordanceModel(std::unique_ptr<AffordanceModelImpl> impl)
    : m_impl(std::move(impl)) {}

AffordanceModel::AffordanceModel(ModelCard card, unsigned seed)
    : m_impl(std::make_unique<AffordanceModelImpl>()) {
  configureTorchRuntime();
  m_impl->shape = networkShapeOf(card);
  m_impl->mode = parseExecutionMode(card.mode);
  card.architecture = m_impl->shape.architecture.toString();
  m_impl->card = std::move(card);
  torch::manual_seed(seed);
  m_impl->net = SAGridNet(m_impl->shape);
  if (torch::cuda::is_available()) m_impl->device = torch::Device(torch::kCUDA);
  m_impl->net->to(m_impl->device);
  m_impl->net->eval();
}

AffordanceModel::~AffordanceModel() = default;
AffordanceModel::AffordanceModel(AffordanceModel&&) noexcept = default;
AffordanceModel& AffordanceModel::operator=(AffordanceModel&&) noexcept = default;

namespace {
// One network's weights from `path` into `net` (on the CPU, then to `device`), checked against
// `sha256` when given; every problem names the card first.
void loadWeightsInto(SAGridNet& net, const fs::path& path, const std::string& sha256,
                     const fs::path& cardFile, const torch::Device& device) {
  const std::string bytes = readFileBytes(path);
  if (!sha256.empty() && sha256Hex(bytes) != sha256)
    throw FileError(path, "weights sha256 differs from the model card " +
                              cardFile.filename().string() +
                              " (truncated, corrupt or replaced file)");
  net->to(torch::kCPU);
  deserializeWeights(net, bytes, path.string());
  net->to(device);
  net->eval();
}
}  // namespace

AffordanceModel AffordanceModel::load(const fs::path& cardFile) {
  ModelCard card = readModelCard(cardFile);
  try {
    AffordanceModel model(card, 0);
    AffordanceModelImpl& impl = *model.m_impl;
    loadWeightsInto(impl.net, cardFile.parent_path() / card.weightsFile, card.weightsSha256,
                    cardFile, impl.device);
    for (const auto& member : card.ensemble) {
      impl.members.push_back(SAGridNet(impl.shape));
      loadWeightsInto(impl.members.back(), cardFile.parent_path() / member.file, member.sha256,
                      cardFile, impl.device);
    }
    return model;
  } catch (const FileError& e) {
    throw FileError(cardFile, e.what());
  } catch (const ModelError& e) {
    throw ModelError(cardFile.string() + ": " + e.what());
  }
}

void AffordanceModel::save(const fs::path& cardFile) {
  // Training writes one network; an ensemble's card lists members it did not write.
  if (!m_impl->card.ensemble.empty())
    throw ModelError(cardFile.string() +
                     ": a model card with weights.ensemble cannot be saved by training (it "
                     "writes one network); list the members in the card by hand");
  const std::string name = cardFile.stem().string();
  m_impl->card.weightsFile = name + ".pt";
  const std::string bytes = serializeWeights(m_impl->net);
  m_impl->card.weightsSha256 = sha256Hex(bytes);
  if (!cardFile.parent_path().empty()) fs::create_directories(cardFile.parent_path());
  writeFileAtomic(cardFile.parent_path() / m_impl->card.weightsFile, bytes);
  writeModelCard(cardFile, m_impl->card);
}

const ModelCard& AffordanceModel::card() const { return m_impl->card; }
ModelCard& AffordanceModel::card() { return m_impl->card; }

namespace {
// A forward pass on the CPU runs on one intra-op thread, so that its result does not depend on
// the thread count: split between threads, the BLAS (OpenBLAS) computes a GEMM with other
// blockings and kernels, and ATen's vectorised loops put each chunk's tail on a scalar path. The
// last bits then decide near-ties between minima of the field, which moved a point by a whole
// part between a one-process run and the one-core tasks of a Slurm array (issue 42). Several
// passes (symmetric copies, ensemble members) run side by side instead. ATen keeps the count per
// thread (an OpenMP setting, which an OpenMP BLAS follows); its global copy, read by threads that
// start using ATen, is set back to the configured count. Each change also rebuilds ATen's global
// thread pool (whose new workers spin a while), so a batch of passes sets the count once around
// them all: its worker threads then start at one thread and change nothing.
class OneIntraOpThread {
 public:
  OneIntraOpThread() : m_changed(at::get_num_threads() != 1) {
    if (m_changed) at::set_num_threads(1);
  }
  ~OneIntraOpThread() {
    if (m_changed) at::set_num_threads(defaultThreadCount());
  }
  OneIntraOpThread(const OneIntraOpThread&) = delete;
  OneIntraOpThread& operator=(const OneIntraOpThread&) = delete;

 private:
  bool m_changed;
};
}  // namespace

std::vector<float> AffordanceModel::predictDistances(const FeatureGrid& features) const {
  return predictDistances(std::vector<const FeatureGrid*>{&features}).front();
}

std::vector<std::vector<float>> AffordanceModel::predictDistances(
    const std::vector<const FeatureGrid*>& grids) const {
  for (const FeatureGrid* features : grids) m_impl->card.checkFeatures(*features);
  const std::size_t networks = networkCount();
  // Before any pass: eval() writes the modules' flags, which concurrent passes only read.
  m_impl->net->eval();
  for (std::size_t m = 0; m + 1 < networks; ++m) m_impl->members[m]->eval();
  const bool cpu = m_impl->device.is_cpu();
  std::optional<OneIntraOpThread> passesOnOneThread;
  if (cpu) passesOnOneThread.emplace();
  std::vector<std::vector<float>> out(grids.size());
  auto predictOne = [&](std::size_t g) {
    const FeatureGrid& features = *grids[g];
    if (features.voxels.empty()) return;
    std::optional<OneIntraOpThread> oneThread;
    if (cpu) oneThread.emplace();
    torch::NoGradGuard noGrad;
    const NetworkObject object = networkObjectOf(features);
    const NetworkBatch batch =
        makeNetworkBatch({&object}, m_impl->shape, m_impl->mode, m_impl->device);
    // The network regresses D = log(1 + distance); report distances (an ensemble's mean, its
    // networks added in their order).
    auto distances = [&](SAGridNet& net) {
      return torch::expm1(net->forward(batch, m_impl->mode));
    };
    torch::Tensor d = distances(m_impl->net);
    for (std::size_t m = 0; m + 1 < networks; ++m) d = d + distances(m_impl->members[m]);
    d = (d / static_cast<double>(networks)).cpu().contiguous();
    out[g].assign(d.data_ptr<float>(), d.data_ptr<float>() + d.numel());
  };
  const std::size_t workers =
      cpu ? std::min(grids.size(), static_cast<std::size_t>(defaultThreadCount())) : 1;
  if (workers <= 1) {
    for (std::size_t g = 0; g < grids.size(); ++g) predictOne(g);
    return out;
  }
  // Passes are independent: which worker runs one cannot change its numbers.
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto work = [&] {
    try {
      for (std::size_t g = next++; g < grids.size(); g = next++) predictOne(g);
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      next = grids.size();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return out;
}

double AffordanceModel::forwardMacs(std::int64_t occupiedVoxels, bool dense) const {
  return static_cast<double>(networkCount()) *
         model::forwardMacs(m_impl->shape, dense ? ExecutionMode::Dense : m_impl->mode,
                            occupiedVoxels);
}

std::size_t AffordanceModel::networkCount() const {
  return m_impl->card.ensemble.empty() ? 1 : 1 + m_impl->members.size();
}

std::int64_t AffordanceModel::parameterCount() const {
  std::int64_t n = 0;
  for (const auto& p : m_impl->net->parameters()) n += p.numel();
  return n * static_cast<std::int64_t>(networkCount());
}

}  // namespace sagrid::model
