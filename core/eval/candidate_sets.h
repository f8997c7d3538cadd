// What the learned point decision learns from: per labelled object and model, the point candidates
// (core/points/point_candidates.h) as `sagrid eval` saw them, with their surface points, the
// count's points and the ground truth, so that fitting and leave-one-source-out evaluation of the
// decision (core/eval/point_scorer_training.h) run without the networks. Saved as JSON
// (`sagrid scorer candidates`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/points/point_candidates.h"

namespace sagrid {

struct CandidateSet {
  std::string object, source, model;
  bool generated = false;     // a generated object (labels from the generator)
  double metersPerUnit = 1;   // of the mesh file's units
  std::vector<PointCandidate> candidates;
  std::vector<Eigen::Vector3f> candidateSurface;  // per candidate, on the surface (file frame)
  std::vector<Eigen::Vector3f> keptSurface;       // the count's points, best first (file frame)
  std::vector<Eigen::Vector3f> truth;             // ground truth (file frame)
  std::vector<std::string> passesOff;  // the passes switched off when they were made (passesOff)
  // The weights of the network that made them (ModelCard::weightsIdentity); empty in files
  // written before it was recorded.
  std::string networkWeights;
};

// Per candidate of `set`, whether it is the nearest candidate to a ground-truth point within
// `radiusMeters` of it (the radius within which a point needs no drag, kMatchRadiusMeters).
std::vector<bool> candidateLabels(const CandidateSet& set, double radiusMeters);

// The sets with the named features set to 0 on every candidate: what the decision does without
// them (an ablation; a constant feature is never split on, so a decision fitted so never reads
// it). A name "MODEL:FEATURE" does so on that model's sets only. Throws InvalidArgument naming an
// unknown feature.
void withoutFeatures(std::vector<CandidateSet>& sets, const std::vector<std::string>& names);

nlohmann::json toJson(const std::vector<CandidateSet>& sets);
// Throws FileError naming `file` when it is not a candidate file of this build's features.
std::vector<CandidateSet> readCandidateSets(const std::filesystem::path& file);
void writeCandidateSets(const std::filesystem::path& file, const std::vector<CandidateSet>& sets);

}  // namespace sagrid
