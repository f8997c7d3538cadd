// One trained SAGrid model (one category.type): the network plus its card. Predicts a distance
// field over the occupied voxels of a FeatureGrid. Torch stays inside the implementation (pimpl),
// so annotate, eval and the GUI include this header without paying libtorch's compile time.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/model/model_card.h"

namespace sagrid {
struct FeatureGrid;
}

namespace sagrid::model {

struct AffordanceModelImpl;  // torch side, core/model/affordance_model_impl.h

class AffordanceModel {
 public:
  // Fresh weights for `card` (architecture, mode and feature shape are read from it).
  AffordanceModel(ModelCard card, unsigned seed);
  ~AffordanceModel();
  AffordanceModel(AffordanceModel&&) noexcept;
  AffordanceModel& operator=(AffordanceModel&&) noexcept;

  // Reads the card and its weights. Throws FileError (missing, unreadable, truncated or corrupt
  // weights, sha256 differing from the card) or ModelError (weights not matching the card).
  static AffordanceModel load(const std::filesystem::path& cardFile);
  // Writes <card>.pt weights and the card (weights sha256 filled in), both atomically.
  void save(const std::filesystem::path& cardFile);

  const ModelCard& card() const;
  ModelCard& card();

  // Predicted distance to the nearest affordance (normalized frame units, >= 0) for each occupied
  // voxel of `features`, in the order of features.voxels; with an ensemble, the mean over its
  // networks. Checks the features against the card
  // first (ModelError on mismatch).
  std::vector<float> predictDistances(const FeatureGrid& features) const;
  // The same for several grids (e.g. the symmetric copies of one object), run side by side. On
  // the CPU each pass runs on one intra-op thread, so the numbers are bit for bit the same
  // whatever the thread count (SAGRID_THREADS): a one-process run and the one-core tasks of a
  // Slurm array give the same points. Parallelism comes from passes running side by side.
  std::vector<std::vector<float>> predictDistances(
      const std::vector<const FeatureGrid*>& grids) const;

  // Networks that predict: 1, or 1 + the ensemble's members (card weights.ensemble).
  std::size_t networkCount() const;
  // Total number of weights (parameters) of every network, for reports.
  std::int64_t parameterCount() const;
  // Multiply-accumulates of one prediction (a forward pass of every network) over an object with
  // this many occupied voxels, in the card's execution mode (and, for comparison, in the other).
  double forwardMacs(std::int64_t occupiedVoxels, bool dense = false) const;

  AffordanceModelImpl& impl() { return *m_impl; }

 private:
  explicit AffordanceModel(std::unique_ptr<AffordanceModelImpl> impl);
  std::unique_ptr<AffordanceModelImpl> m_impl;
};

// Threads and device for all model work: every CPU core (Debian's libtorch defaults to one),
// CUDA when available. Idempotent.
void configureTorchRuntime();
bool cudaAvailable();

}  // namespace sagrid::model
