#include "core/physics/convex_decomposition.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "core/common/error.h"
#include "core/common/parallel_for.h"
#include "core/grid/distance_transform.h"
#include "core/mesh/mesh.h"
#include "core/physics/solid_voxels.h"
#include "core/physics/surface_pieces.h"
#include "core/physics/surface_sampling.h"

namespace sagrid::physics {

namespace {

using Index = std::uint32_t;
using Points = std::vector<Eigen::Vector3f>;

// A part while cutting: a 26-connected set of solid voxels, its hull in grid units and how far
// that hull strays outside the solid.
struct VoxelPart {
  std::vector<Index> voxels;
  Eigen::Vector3i lo, hi;  // inclusive voxel bounds
  Points points;           // hull input, grid units
  std::optional<ConvexPart> hull;
  double concavity = 0;    // voxels
  double gap = 0;          // hull volume not in the solid, voxels^3
  bool settled = false;    // within tolerance, or cannot be cut further
};

// Hull surface sampling for the concavity, in voxels: coarse while choosing cuts, fine for parts.
constexpr float kCoarseSpacing = 3.0f;
constexpr float kFineSpacing = 1.5f;
// Hulls used while cutting keep at most this many vertices (Qhull's greedy farthest-point
// hull): a finely tessellated curved surface otherwise puts tens of thousands of points on
// every hull, and each cut candidate carries them on.
constexpr int kScoringHullVertices = 256;

struct Cut {
  int axis = 0;
  int position = 0;  // voxels with coordinate < position go to the first side
  double cost = std::numeric_limits<double>::infinity();
};

class Decomposer {
 public:
  Decomposer(const Mesh& mesh, const DecompositionOptions& options)
      : m_options(options),
        m_n(options.resolution),
        m_solid(solidVoxels(mesh, options.resolution, options.holeClosingVoxels, options.frame)),
        m_pieces(mesh, m_solid.normalization, options.resolution),
        m_partOf(m_solid.solid.voxelCount(), -1),
        m_mark(m_solid.solid.voxelCount(), 0) {
    report(0.05f, "voxelizing");
    m_outsideDistance = distanceToVoxels(m_solid.solid.occupancy(), m_n);
    const double extent = m_n - 2.0 * (options.holeClosingVoxels + 2);
    // Below 1.5 voxels the estimate is noise: a hull lying on the surface may sample the voxel
    // just outside it (distance 1).
    m_tolerance = std::max(1.5, static_cast<double>(options.concavityTolerance) * extent);
  }

  Decomposition run() {
    Decomposition result;
    if (m_solid.closedCount > 0)
      result.warnings.push_back("the surface has holes; " + std::to_string(m_solid.closedCount) +
                                " voxels were closed before filling");
    if (m_solid.enclosedCount == 0)
      result.warnings.push_back(
          "the mesh encloses no volume (open or flat): parts are hulls of its surface");

    std::vector<Index> all;
    for (std::size_t i = 0; i < m_solid.solid.voxelCount(); ++i)
      if (m_solid.solid.occupancy()[i]) all.push_back(static_cast<Index>(i));
    for (auto& component : components(all)) addPart(std::move(component));

    cutWhileBudgetAllows();
    if (static_cast<int>(m_parts.size()) > m_options.maxParts) {
      result.warnings.push_back("the mesh has " + std::to_string(m_parts.size()) +
                                " separate pieces; neighbours were merged to fit " +
                                std::to_string(m_options.maxParts) + " parts");
      mergeDownToBudget();
    }
    report(0.9f, "hulls");
    finish(result);
    report(1.0f, "done");
    return result;
  }

 private:
  void report(float fraction, const char* stage) const {
    if (m_options.cancel && m_options.cancel->load()) throw Cancelled();
    if (m_options.progress) m_options.progress(fraction, stage);
  }

  Eigen::Vector3i coordinates(Index v) const {
    const int n = m_n;
    return {static_cast<int>(v / (n * n)), static_cast<int>((v / n) % n), static_cast<int>(v % n)};
  }

  // 26-connected pieces of a voxel set.
  std::vector<std::vector<Index>> components(const std::vector<Index>& voxels) {
    ++m_stamp;  // m_mark == stamp: in the set; stamp + 1: visited
    const std::uint32_t member = m_stamp, visited = ++m_stamp;
    for (Index v : voxels) m_mark[v] = member;
    std::vector<std::vector<Index>> result;
    std::vector<Index> stack;
    for (Index seed : voxels) {
      if (m_mark[seed] != member) continue;
      result.emplace_back();
      m_mark[seed] = visited;
      stack.push_back(seed);
      while (!stack.empty()) {
        const Index v = stack.back();
        stack.pop_back();
        result.back().push_back(v);
        const Eigen::Vector3i c = coordinates(v);
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -1; dk <= 1; ++dk) {
              const Eigen::Vector3i q = c + Eigen::Vector3i(di, dj, dk);
              if ((q.array() < 0).any() || (q.array() >= m_n).any()) continue;
              const Index w = static_cast<Index>((q.x() * m_n + q.y()) * m_n + q.z());
              if (m_mark[w] != member) continue;
              m_mark[w] = visited;
              stack.push_back(w);
            }
      }
    }
    return result;
  }

  // Hull input of one voxel of part `id`: its surface pieces, or the corners of an enclosed
  // voxel on the part's boundary (where a cut went through the solid).
  void appendVoxelPoints(Index v, int id, Points& out) const {
    if (m_pieces.crossesVoxel(v)) {
      const auto& p = m_pieces.points(v);
      out.insert(out.end(), p.begin(), p.end());
      return;
    }
    // A surface voxel only touched by a face on its boundary: the neighbour has the points.
    if (m_solid.surface.occupancy()[v]) return;
    const Eigen::Vector3i c = coordinates(v);
    bool boundary = false;
    for (int axis = 0; axis < 3 && !boundary; ++axis)
      for (int step = -1; step <= 1 && !boundary; step += 2) {
        Eigen::Vector3i q = c;
        q[axis] += step;
        if (q[axis] < 0 || q[axis] >= m_n) {
          boundary = true;
          continue;
        }
        boundary = m_partOf[(q.x() * m_n + q.y()) * m_n + q.z()] != id;
      }
    if (!boundary) return;
    for (int corner = 0; corner < 8; ++corner)
      out.emplace_back(c.x() + (corner & 1), c.y() + ((corner >> 1) & 1), c.z() + ((corner >> 2) & 1));
  }

  // The largest outside distance (voxels) over the hull's surface, sampled every `spacing`
  // voxels at the nearest voxel centre (the distance is 1-Lipschitz, so the sampling misses at
  // most about a spacing).
  double concavityOf(const ConvexPart& hull, float spacing = kFineSpacing) const {
    float worst = 0;
    const int last = m_n - 1;
    sampleTriangles(hull.vertices, hull.triangles, spacing, [&](const Eigen::Vector3f& p) {
      const int i = std::clamp(static_cast<int>(p.x()), 0, last);
      const int j = std::clamp(static_cast<int>(p.y()), 0, last);
      const int k = std::clamp(static_cast<int>(p.z()), 0, last);
      worst = std::max(worst, m_outsideDistance[(static_cast<std::size_t>(i) * m_n + j) * m_n + k]);
    });
    return worst;
  }

  void evaluate(VoxelPart& part) const {
    part.hull = convexHull(part.points, kScoringHullVertices);
    part.concavity = part.hull ? concavityOf(*part.hull) : 0.0;
    part.gap = part.hull ? std::max(0.0, part.hull->volume() - static_cast<double>(part.voxels.size())) : 0.0;
    part.settled = part.concavity <= m_tolerance || (part.hi - part.lo).maxCoeff() == 0;
  }

  void fill(VoxelPart& part, int id) {
    part.lo = Eigen::Vector3i::Constant(m_n);
    part.hi = Eigen::Vector3i::Constant(-1);
    for (Index v : part.voxels) {
      m_partOf[v] = id;
      const Eigen::Vector3i c = coordinates(v);
      part.lo = part.lo.cwiseMin(c);
      part.hi = part.hi.cwiseMax(c);
    }
  }

  void gatherPoints(VoxelPart& part, int id) const {
    part.points.clear();
    for (Index v : part.voxels) appendVoxelPoints(v, id, part.points);
  }

  void addPart(std::vector<Index> voxels) {
    const int id = static_cast<int>(m_parts.size());
    m_parts.emplace_back();
    m_parts.back().voxels = std::move(voxels);
    fill(m_parts.back(), id);
    gatherPoints(m_parts.back(), id);
    evaluate(m_parts.back());
  }

  // The hull of `carried` plus `points`, with the vertices to carry on (all points when flat).
  struct Chain {
    Points carried;
    std::optional<ConvexPart> hull;
  };
  static Chain extend(const Chain& previous, const Points& points) {
    Chain next;
    next.carried = previous.hull ? previous.hull->vertices : previous.carried;
    next.carried.insert(next.carried.end(), points.begin(), points.end());
    next.hull = convexHull(next.carried, kScoringHullVertices);
    return next;
  }

  // The best cut of `part` along `axis`: sides' hulls are grown layer chunk by chunk from each
  // end, so every candidate costs two hull updates.
  Cut bestCutAlong(const VoxelPart& part, int id, int axis) const {
    Cut best;
    best.axis = axis;
    const int lo = part.lo[axis], layers = part.hi[axis] - lo + 1;
    if (layers < 2) return best;
    std::vector<Points> layerPoints(layers);
    std::vector<double> layerSolid(layers, 0.0);
    for (Index v : part.voxels) {
      const int layer = coordinates(v)[axis] - lo;
      appendVoxelPoints(v, id, layerPoints[layer]);
      layerSolid[layer] += 1;
    }
    // Candidates: evenly spaced cuts, plus the layers where the solid's cross-section changes
    // most (the floor of a basin ends, an arm of an L starts): concave edges lie there, and a
    // cavity needs cuts at its walls before any single cut lowers its hull's stray.
    std::vector<double> jump(layers + 1, 0.0);
    const double widest = *std::max_element(layerSolid.begin(), layerSolid.end());
    for (int l = 1; l < layers; ++l) jump[l] = std::abs(layerSolid[l] - layerSolid[l - 1]) / widest;
    const int evenly = std::min(layers - 1, 12);
    std::vector<int> cuts;  // layer index where the second side starts
    for (int c = 0; c < evenly; ++c)
      cuts.push_back(1 + static_cast<int>(std::lround(static_cast<double>(c) * (layers - 2) / std::max(1, evenly - 1))));
    std::vector<int> byJump;
    for (int l = 1; l < layers; ++l)
      if (jump[l] > 0.05) byJump.push_back(l);
    std::sort(byJump.begin(), byJump.end(), [&](int a, int b) { return jump[a] > jump[b]; });
    if (byJump.size() > 8) byJump.resize(8);
    cuts.insert(cuts.end(), byJump.begin(), byJump.end());
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    auto chunkPoints = [&](int from, int to) {
      Points p;
      for (int l = from; l < to; ++l) p.insert(p.end(), layerPoints[l].begin(), layerPoints[l].end());
      return p;
    };
    std::vector<Chain> below(cuts.size()), above(cuts.size());
    Chain chain;
    for (std::size_t c = 0; c < cuts.size(); ++c)
      chain = below[c] = extend(chain, chunkPoints(c == 0 ? 0 : cuts[c - 1], cuts[c]));
    chain = Chain{};
    for (std::size_t c = cuts.size(); c-- > 0;)
      chain = above[c] = extend(chain, chunkPoints(cuts[c], c + 1 < cuts.size() ? cuts[c + 1] : layers));

    std::vector<double> solidBelow(layers + 1, 0.0);
    for (int l = 0; l < layers; ++l) solidBelow[l + 1] = solidBelow[l] + layerSolid[l];
    const double middle = 0.5 * layers;
    // Hull volume left outside the solid, the worst stray of the two hulls, then where those
    // are flat a cut at a change of cross-section, then one through the middle.
    auto costOf = [&](const Chain& first, const Chain& second, int cut) {
      const auto side = [&](const Chain& h, double solid) {
        if (!h.hull) return std::pair<double, double>{0.0, 0.0};
        return std::pair<double, double>{std::max(0.0, h.hull->volume() - solid),
                                          concavityOf(*h.hull, kCoarseSpacing)};
      };
      const auto [gapBelow, concavityBelow] = side(first, solidBelow[cut]);
      const auto [gapAbove, concavityAbove] = side(second, solidBelow[layers] - solidBelow[cut]);
      return (gapBelow + gapAbove) / std::max(1.0, part.gap) +
             std::max(concavityBelow, concavityAbove) / std::max(1e-6, part.concavity) +
             0.5 * (1.0 - jump[cut]) + 0.1 * std::abs(cut - middle) / layers;
    };
    std::size_t bestIndex = 0;
    for (std::size_t c = 0; c < cuts.size(); ++c) {
      const double cost = costOf(below[c], above[c], cuts[c]);
      if (cost < best.cost) best.cost = cost, best.position = lo + cuts[c], bestIndex = c;
    }
    // Refine between the neighbouring candidates, growing their hulls layer by layer.
    const int from = bestIndex > 0 ? cuts[bestIndex - 1] : 0;
    const int to = bestIndex + 1 < cuts.size() ? cuts[bestIndex + 1] : layers;
    const Chain none;
    for (int cut = from + 1; cut < to; ++cut) {
      if (cut == cuts[bestIndex]) continue;
      const Chain first = extend(bestIndex > 0 ? below[bestIndex - 1] : none, chunkPoints(from, cut));
      const Chain second = extend(bestIndex + 1 < cuts.size() ? above[bestIndex + 1] : none, chunkPoints(cut, to));
      const double cost = costOf(first, second, cut);
      if (cost < best.cost) best.cost = cost, best.position = lo + cut;
    }
    return best;
  }

  void split(std::size_t index, const Cut& cut) {
    std::vector<Index> first, second;
    for (Index v : m_parts[index].voxels)
      (coordinates(v)[cut.axis] < cut.position ? first : second).push_back(v);
    auto pieces = components(first);
    for (auto& piece : components(second)) pieces.push_back(std::move(piece));
    m_parts[index].voxels = std::move(pieces[0]);
    std::vector<std::size_t> touched{index};
    for (std::size_t p = 1; p < pieces.size(); ++p) {
      touched.push_back(m_parts.size());
      m_parts.emplace_back();
      m_parts.back().voxels = std::move(pieces[p]);
    }
    // Ids first, then points: a voxel is on a part's boundary when its neighbour moved away.
    for (std::size_t t : touched) fill(m_parts[t], static_cast<int>(t));
    parallelFor(touched.size(), 2, [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t) {
        gatherPoints(m_parts[touched[t]], static_cast<int>(touched[t]));
        evaluate(m_parts[touched[t]]);
      }
    });
  }

  void cutWhileBudgetAllows() {
    while (static_cast<int>(m_parts.size()) < m_options.maxParts) {
      std::size_t worst = m_parts.size();
      for (std::size_t p = 0; p < m_parts.size(); ++p)
        if (!m_parts[p].settled && (worst == m_parts.size() || m_parts[p].concavity > m_parts[worst].concavity))
          worst = p;
      if (worst == m_parts.size()) break;
      report(0.1f + 0.7f * static_cast<float>(m_parts.size()) / m_options.maxParts, "cutting");
      std::array<Cut, 3> cuts;
      const VoxelPart& part = m_parts[worst];
      parallelFor(3, 2, [&](std::size_t begin, std::size_t end) {
        for (std::size_t axis = begin; axis < end; ++axis)
          cuts[axis] = bestCutAlong(part, static_cast<int>(worst), static_cast<int>(axis));
      });
      const Cut best = *std::min_element(cuts.begin(), cuts.end(),
                                         [](const Cut& a, const Cut& b) { return a.cost < b.cost; });
      if (!std::isfinite(best.cost)) {
        m_parts[worst].settled = true;
        continue;
      }
      split(worst, best);
    }
  }

  static double boxGap(const VoxelPart& a, const VoxelPart& b) {
    const Eigen::Vector3i gap = (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0);
    return gap.cast<double>().norm();
  }

  Points hullPoints(const VoxelPart& part) const { return part.hull ? part.hull->vertices : part.points; }

  // Merges the pair whose joint hull strays least until the budget holds. Pairs are limited to
  // each part's nearest neighbours by box distance.
  void mergeDownToBudget() {
    while (static_cast<int>(m_parts.size()) > m_options.maxParts) {
      report(0.85f, "merging");
      std::vector<std::pair<std::size_t, std::size_t>> pairs;
      for (std::size_t a = 0; a < m_parts.size(); ++a) {
        std::vector<std::pair<double, std::size_t>> near;
        for (std::size_t b = 0; b < m_parts.size(); ++b)
          if (b != a) near.emplace_back(boxGap(m_parts[a], m_parts[b]), b);
        const std::size_t keep = std::min<std::size_t>(near.size(), 4);
        std::partial_sort(near.begin(), near.begin() + keep, near.end());
        for (std::size_t k = 0; k < keep; ++k) pairs.emplace_back(std::min(a, near[k].second), std::max(a, near[k].second));
      }
      std::sort(pairs.begin(), pairs.end());
      pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
      std::vector<double> cost(pairs.size());
      parallelFor(pairs.size(), 8, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          Points joint = hullPoints(m_parts[pairs[p].first]);
          const Points other = hullPoints(m_parts[pairs[p].second]);
          joint.insert(joint.end(), other.begin(), other.end());
          const auto hull = convexHull(joint, kScoringHullVertices);
          cost[p] = hull ? concavityOf(*hull) : 0.0;
        }
      });
      // Merge greedily every disjoint cheap pair in this round, up to the excess.
      std::vector<std::size_t> order(pairs.size());
      for (std::size_t p = 0; p < order.size(); ++p) order[p] = p;
      std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return cost[x] < cost[y]; });
      std::vector<char> used(m_parts.size(), 0), removed(m_parts.size(), 0);
      int excess = static_cast<int>(m_parts.size()) - m_options.maxParts;
      const double cheapest = order.empty() ? 0 : cost[order.front()];
      for (std::size_t p : order) {
        if (excess == 0 || cost[p] > std::max(cheapest * 1.25, cheapest + 1.0)) break;
        const auto [a, b] = pairs[p];
        if (used[a] || used[b]) continue;
        used[a] = used[b] = 1;
        removed[b] = 1;
        auto& target = m_parts[a].voxels;
        target.insert(target.end(), m_parts[b].voxels.begin(), m_parts[b].voxels.end());
        --excess;
      }
      std::vector<VoxelPart> kept;
      for (std::size_t p = 0; p < m_parts.size(); ++p)
        if (!removed[p]) kept.push_back(std::move(m_parts[p]));
      m_parts.swap(kept);
      for (std::size_t p = 0; p < m_parts.size(); ++p) fill(m_parts[p], static_cast<int>(p));
      parallelFor(m_parts.size(), 2, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          gatherPoints(m_parts[p], static_cast<int>(p));
          evaluate(m_parts[p]);
        }
      });
    }
  }

  void finish(Decomposition& result) const {
    const double voxel = m_solid.voxelSize();
    const Normalization& normalization = m_solid.normalization;
    auto toMeshFrame = [&](const Eigen::Vector3f& g) {
      return normalization.toMesh(g / static_cast<float>(m_n) - Eigen::Vector3f::Constant(0.5f));
    };
    std::vector<std::optional<ConvexPart>> hulls(m_parts.size());
    parallelFor(m_parts.size(), 2, [&](std::size_t begin, std::size_t end) {
      for (std::size_t p = begin; p < end; ++p) {
        Points points = m_parts[p].points;  // all of them: the cutting hulls are capped
        for (auto& q : points) q = toMeshFrame(q);
        hulls[p] = convexHull(points, m_options.maxVerticesPerPart, static_cast<float>(voxel));
      }
    });
    int dropped = 0, thin = 0;
    for (std::size_t p = 0; p < m_parts.size(); ++p) {
      if (!hulls[p]) {
        ++dropped;
        continue;
      }
      if (!m_parts[p].hull) ++thin;
      result.concavity = std::max(result.concavity, static_cast<float>(m_parts[p].concavity * voxel));
      result.parts.push_back(std::move(*hulls[p]));
    }
    if (thin > 0)
      result.warnings.push_back(std::to_string(thin) + " flat part(s) thickened to one voxel (" +
                                std::to_string(voxel) + " mesh units)");
    if (dropped > 0)
      result.warnings.push_back(std::to_string(dropped) + " degenerate part(s) dropped");
    if (result.parts.empty()) throw Error("the mesh gives no convex part with volume (it has no extent)");
  }

  const DecompositionOptions& m_options;
  int m_n;
  SolidVoxels m_solid;
  SurfacePieces m_pieces;
  std::vector<float> m_outsideDistance;
  std::vector<int> m_partOf;
  std::vector<std::uint32_t> m_mark;
  std::uint32_t m_stamp = 0;
  double m_tolerance = 1.0;
  std::vector<VoxelPart> m_parts;
};

void checkOptions(const DecompositionOptions& options) {
  if (options.maxParts < 1 || options.maxParts > 4096)
    throw InvalidArgument("maximum part count " + std::to_string(options.maxParts) + " is out of range (1 to 4096)");
  if (options.resolution < 16 || options.resolution > 512)
    throw InvalidArgument("decomposition resolution " + std::to_string(options.resolution) +
                          " is out of range (16 to 512)");
  if (options.maxVerticesPerPart != 0 && options.maxVerticesPerPart < 4)
    throw InvalidArgument("a convex part needs at least 4 vertices");
  if (!(options.concavityTolerance >= 0))
    throw InvalidArgument("the concavity tolerance must be >= 0");
}

}  // namespace

Decomposition decomposeConvex(const Mesh& mesh, const DecompositionOptions& options) {
  checkOptions(options);
  Decomposer decomposer(mesh, options);
  return decomposer.run();
}

ConvexPart convexHullPart(const Mesh& mesh, int maxVertices) {
  if (mesh.triangles.empty()) throw Error("the mesh has no triangles");
  const Eigen::AlignedBox3f box = mesh.bounds();
  if (const auto problem = normalizationProblem(box)) throw Error("the mesh " + *problem);
  Points used;
  used.reserve(mesh.triangles.size());
  std::vector<char> seen(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      if (!seen[t[c]]) seen[t[c]] = 1, used.push_back(mesh.positions[t[c]]);
  // Flat meshes get the thickness of a 1/100 of their size (a plane becomes a thin box).
  const float thickness = 0.01f * box.sizes().maxCoeff();
  auto hull = convexHull(used, maxVertices, thickness);
  if (!hull) throw Error("the mesh has no extent for a convex hull");
  return *hull;
}

}  // namespace sagrid::physics
