// Up-axis detection: which of the six file axes (+-x, +-y, +-z) points up, chosen from the
// geometry itself, for formats that do not fix it (OBJ, PLY, STL; FBX/DAE whose declared axis the
// geometry contradicts). Each candidate axis gets an orientation-sensitive descriptor of the
// object seen with that axis up: stable-pose evidence (support polygon under it, how far it must
// tip to fall, a flat bottom face), which file axis it is (real files are nearly always +y or +z
// up: a learned convention prior), where the surface sits in height and which way it faces, and
// how rough the object looks from above and from below (burners, faucets and basins sit high; the
// bottom is a plain footprint). A linear score of the descriptor, fitted on generated stoves and
// sinks turned to all six directions (`sagrid up-axis --fit`), ranks the candidates; a softmax
// over the six gives the confidence. Objects without a clear up (spheres, cubes, flat plates, a
// single triangle) get a reasoned default with a low confidence.
#pragma once

#include <array>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

constexpr int kUpAxisDescriptorSize = 28;
using UpAxisDescriptor = std::array<float, kUpAxisDescriptorSize>;

// The interpretable part of a candidate's descriptor, for reports.
struct UpAxisEvidence {
  float supportArea = 0;   // convex hull of the lowest vertices / the box's cross-section
  float flatBottom = 0;    // area of near-horizontal faces at the lowest level / cross-section
  float tipping = 0;       // tipping angle / 90 degrees; negative: the centre of mass overhangs
  float massHeight = 0;    // area-weighted mean height of the surface, 0 = bottom, 1 = top
  float topSupport = 0;    // supportArea of the opposite side (the top)
};

struct UpAxisDetection {
  UpAxis axis = UpAxis::Z;
  float confidence = 0;             // [0,1]: softmax probability of the best minus the runner-up
  bool degenerate = false;          // no usable geometry: `axis` is the fallback
  bool flat = false;                // a plate: the axis is its normal, which side is up is a guess
  std::array<float, 6> scores{};    // per kAllUpAxes, higher = more likely up
  std::array<float, 6> probabilities{};  // softmax of the scores
  std::array<UpAxisEvidence, 6> evidence{};
};

// Descriptors of the six candidates (kAllUpAxes order) of the mesh's positions as they are.
// Empty when the mesh has no surface.
std::vector<UpAxisDescriptor> upAxisDescriptors(const Mesh& mesh);

// The scorer of one candidate's descriptor d: a linear term plus a small hidden layer,
//   score(d) = linear . d + sum_h out[h] tanh(hidden[h] . d + bias[h]),
// so that evidence can combine (a flat bottom means up only when the top is rough, ...); a purely
// linear fit stays at about 3/4 right on generated objects turned six ways. The parameters are
// one flat array in the order linear, hidden (row by row), bias, out; the default is the fitted
// one built into SAGrid.
constexpr int kUpAxisHidden = 12;
constexpr int kUpAxisParameterCount =
    kUpAxisDescriptorSize + kUpAxisHidden * kUpAxisDescriptorSize + 2 * kUpAxisHidden;
using UpAxisWeights = std::array<float, kUpAxisParameterCount>;
const UpAxisWeights& defaultUpAxisWeights();
float upAxisScore(const UpAxisWeights& weights, const UpAxisDescriptor& descriptor);

// Scores the six axes of the mesh's positions as they are (call it on the file frame, i.e.
// before any up-axis turn). Never throws: empty or degenerate meshes give `fallback` with
// confidence 0; near-ties resolve to `fallback` when it is among them.
UpAxisDetection detectUpAxis(const Mesh& mesh, UpAxis fallback = UpAxis::Z,
                             const UpAxisWeights& weights = defaultUpAxisWeights());

// One object for fitting: its six candidate descriptors and which one is up.
struct UpAxisExample {
  std::vector<UpAxisDescriptor> candidates;  // kAllUpAxes order
  int up = 0;
  float weight = 1;  // share in the loss (e.g. to balance few real objects against many generated)
};
// Softmax over the six candidates' scores (conditional logit), fitted by full-batch Adam with an
// L2 penalty from a fixed starting point; deterministic. Returns the weights and, through
// `accuracy`, the training accuracy.
UpAxisWeights fitUpAxisWeights(const std::vector<UpAxisExample>& examples, int iterations = 4000,
                               float l2 = 1e-3f, float* accuracy = nullptr);

}  // namespace sagrid
