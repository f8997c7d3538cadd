// Candidates for a learned point decision (issue 40): every place one model's points could be,
// described by numbers a small classifier can weigh. Candidates come from three places: the
// points the automatic count and its passes kept, the minima of the model's field (with the depth
// of their basin), and the small parts of the mesh (a knob, a burner's cap, a handle: connected
// parts, material parts and, for some models, crease patches, at their centroid). Each carries
// the field there and around it, where it stands in the object, the part it lies on (size,
// roundness, flatness, how many copies the part has), the company it keeps, what the
// category's other models' fields say there and how open the space is where it meets the surface
// (a spout's tip over its basin, a knob on a face; not a place inside a cabinet). Normalized frame
// (z up); no torch, no surface.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/points/point_extraction.h"

namespace sagrid {

struct PointCandidate {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // normalized frame
  float distance = 0;                                  // the field there (normalized units)
  bool kept = false;            // one of the points the automatic count and its passes kept
  std::vector<float> features;  // candidateFeatureNames() order
  // The candidates at this one's place on every copy of the part it lies on (a knob's row, a
  // burner's caps), indices into the same list: a choice may take them with it
  // (PointChoice::copyThreshold).
  std::vector<std::size_t> copies;
};

// The names of PointCandidate::features, in order (the scorer file records them, so a model
// trained on other features is refused).
const std::vector<std::string>& candidateFeatureNames();
// The index of a feature in candidateFeatureNames(); throws InvalidArgument for an unknown name.
std::size_t candidateFeatureIndex(const std::string& name);

// Where a candidate meets the surface: the surface normal there (z up), how far the candidate
// lies from it (normalized units; a part's centroid lies inside it) and how open the space there
// is (core/geometry/surface_openness.h): the share of directions that leave the mesh and the free
// distance straight down and up (normalized units; infinite where nothing lies that way).
struct SurfaceContact {
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  float depth = 0;
  float openness = 1;
  float below = std::numeric_limits<float>::infinity();
  float above = std::numeric_limits<float>::infinity();
};
using SurfaceContactAt = std::function<SurfaceContact(const Eigen::Vector3f&)>;

// A part with more copies than this (tiles, screws, a grate's bars) links its candidates to none.
constexpr std::size_t kMaxCandidateCopies = 15;

// Candidates of one model on one object: `kept` the points its automatic count and passes kept
// (best first), `parts` from normalizedParts (with the mesh's crease patches where the model's
// card says so, core/annotate/point_passes.h), `contact` the surface near a normalized point.
// Candidates closer than a voxel to an earlier one are one candidate (kept points first, then
// minima best first, then parts), with the sources of both. A candidate on a part with copies
// (PartCopies, at most kMaxCandidateCopies) is linked to the candidates at its place on each copy
// (its offset from the part's centroid kept; PointCandidate::copies). At most `maxMinima` field
// minima. `others`: the fields of the category's other models on the same object (a stove's
// burners beside its knobs, a tap's outlet beside its handles), read as two features:
// other_field, how far above its best the nearest other field lies at the candidate (in units of
// 0.2 normalized, capped at 1; 1 without other fields: a knob's candidate on a burner's cap is
// where the burners' field is lowest), and other_claim, other_field less the candidate's
// own distance above its field's best in the same units, in [-1, 1] (which model the place
// belongs to more). `contact` also gives openness as it is and the free distances below and above
// in units of half the object, capped at 1 (openness, clear_below, clear_above). Empty for an
// empty field.
std::vector<PointCandidate> pointCandidates(const PredictedField& field,
                                            const std::vector<ExtractedPoint>& kept,
                                            const std::vector<ConnectedPart>& parts,
                                            const SurfaceContactAt& contact,
                                            const std::vector<const PredictedField*>& others = {},
                                            std::size_t maxMinima = 24);

}  // namespace sagrid
