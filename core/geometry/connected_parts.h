// The connected parts of a triangle mesh: triangles joined through shared vertices, where
// vertices at the same position count as one (importers split them at seams of normals and UVs).
// A stove's knobs, a burner's caps, a tap's two handles are usually parts of their own, and
// copies of one another; a part's shape summary tells such copies from other parts.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

namespace sagrid {

struct Mesh;

struct ConnectedPart {
  int triangles = 0;
  float area = 0;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();  // mean of its distinct vertex positions
  Eigen::AlignedBox3f box;
  // Standard deviations of its distinct vertex positions along their principal axes, largest
  // first: unchanged when the part is moved, turned or mirrored.
  Eigen::Vector3f spread = Eigen::Vector3f::Zero();
  // Set for a part that only its material separates from the rest of its connected part
  // (connectedAndMaterialParts, core/geometry/material_parts.h).
  bool byMaterial = false;
  // Set for a patch of the surface that only creases bound (core/geometry/crease_patches.h).
  bool byCrease = false;
};

// Every connected part of `mesh`, in its frame, largest triangle count first (ties: the order of
// their first triangle). Triangles with an out-of-range index are left out.
std::vector<ConnectedPart> connectedParts(const Mesh& mesh);

// Whether `b` is a copy of `a` up to a rigid motion or a mirror: the same triangle count, and
// area and spread equal within `tolerance` (relative; the spread against a's largest).
bool congruentParts(const ConnectedPart& a, const ConnectedPart& b, float tolerance);

// A knob, a handle or a cap has a few faces at least: single triangles and quads (decals, the
// pieces of a triangle soup) are never one instance, and a soup of them would make every copy
// search quadratic.
constexpr int kMinInstanceTriangles = 8;

// The tolerance copies are found with (congruentParts): a knob turned to another setting
// voxelizes and rounds a little differently.
constexpr float kCopyTolerance = 0.05f;

// The factor `b` is `a` scaled by up to a rigid motion or a mirror, when it is one within
// [1 / maxScale, maxScale]: the same triangle count, the spread scaled by it and the area by its
// square within `tolerance` (relative, as congruentParts). A range's wok burner is its other
// burners' cap made larger.
std::optional<float> similarityScale(const ConnectedPart& a, const ConnectedPart& b,
                                     float tolerance, float maxScale);

// The parts of an object grouped by triangle count (copies have the same), so that finding a
// part's copies (congruentParts within `tolerance`; with `maxScale` above 1 also the parts it is
// scaled to within it, similarityScale) reads only its group. Parts of fewer than
// kMinInstanceTriangles have none. `parts` must outlive it.
class PartCopies {
 public:
  PartCopies(const std::vector<ConnectedPart>& parts, float tolerance, float maxScale = 1.0f);
  // The other parts that are copies of part p.
  std::vector<std::size_t> of(std::size_t p) const;
  // Part p's family: its copies, then p.
  std::vector<std::size_t> familyOf(std::size_t p) const;

 private:
  const std::vector<ConnectedPart>& m_parts;
  float m_tolerance, m_maxScale;
  std::unordered_map<int, std::vector<std::size_t>> m_groups;
};

// How far part p's centroid lies from the nearest centroid of the other parts of `family` (a row
// of copies: its spacing at p); p itself is skipped where it is listed. Infinity when there is no
// other.
float nearestCentroidDistance(std::size_t p, const std::vector<std::size_t>& family,
                              const std::vector<ConnectedPart>& parts);

// The largest box diagonal of a part that can be one instance (a knob, a handle, a burner cap, not
// a panel, the grate or the cabinet), in the normalized frame (largest extent 1).
constexpr float kSmallPartDiagonal = 0.2f;

// Which part a point lies on (a point candidate's part, core/points/point_candidates.h): the small
// part whose box, grown by `touchVoxels` voxels, holds it.
struct PartContact {
  float touchVoxels = 1.5f;
  // Only parts up to this box diagonal (normalized units) can be one instance.
  float maxPartDiagonal = kSmallPartDiagonal;
};

// A part small enough to be one instance: box diagonal at most `maxDiagonal` (in the parts'
// frame).
bool isSmallPart(const ConnectedPart& part, float maxDiagonal);

// A round flat part, as a burner's cap (z up): its horizontal extents within kRoundShare of the
// larger, its height at most kFlatShare of the smaller.
constexpr float kRoundShare = 0.15f, kFlatShare = 0.5f;
bool isRoundFlatPart(const ConnectedPart& part);

// The part a point lies on: of the parts up to `maxDiagonal` whose box grown by `touch` holds it,
// the one whose box is nearest (of boxes that hold it, as a knob's box and the cabinet's behind
// it do, the one with the smallest diagonal); nullopt when none does.
std::optional<std::size_t> partAt(const Eigen::Vector3f& point,
                                  const std::vector<ConnectedPart>& parts, float touch,
                                  float maxDiagonal = std::numeric_limits<float>::infinity());

}  // namespace sagrid
