// Mirror pairs: the instances an automatic count misses on objects built symmetrically. A double
// vanity has two spouts and four taps, a washbasin with separate hot and cold taps two outlets, a
// range its knobs in a symmetric row; the network's field often has one deep minimum and a
// shallow shoulder at the twin, and the count keeps only the first. When the object's voxels are
// mirror-symmetric about a vertical plane, a point off that plane whose neighbourhood has the same
// shape at its mirror image gets that image as a point too (unless a point is there already).
// Works in the normalized frame on the occupied voxels of the field.
//
// Anchored pairs: a mixer's hot and cold handles sit either side of its own spout, not of the
// whole object (two taps per basin on a double vanity, a basin off the counter's middle), so the
// same twin is also sought across the vertical plane through the nearest spout.
#pragma once

#include <optional>
#include <vector>

#include "core/points/point_extraction.h"

namespace sagrid {

struct MirrorPlane {
  int axis = 0;      // 0 = x, 1 = y: the horizontal axis the plane is normal to (z is up)
  int indexSum = 0;  // voxel index v along the axis mirrors to indexSum - v
  float score = 0;   // share of occupied voxels whose mirror image is occupied
  // The plane's coordinate along the axis in the normalized frame.
  float coordinate(int resolution) const;
  Eigen::Vector3f mirror(const Eigen::Vector3f& normalizedPoint, int resolution) const;
};

struct MirrorPairSettings {
  float minSymmetry = 0.85f;    // the object: share of voxels with an occupied mirror image
  float minLocalMatch = 0.9f;   // the point's neighbourhood: the same share there
  int neighbourhoodVoxels = 3;  // Chebyshev radius of that neighbourhood
  // A neighbourhood voxel matches when its mirror image has an occupied voxel within this
  // Chebyshev distance: voxelization puts the two sides of a symmetric part up to a voxel apart
  // (a tap handle turned a little, a surface on a voxel boundary). 0 = the image voxel itself.
  int matchToleranceVoxels = 1;
  // The field at the image: its smallest predicted distance within two voxels must not exceed
  // the point's own by more than this (normalized units); < 0 = no condition on the field.
  float maxDistanceAbovePoint = 0.05f;
  // Anchored pairs: a point pairs across the plane through the nearest anchor within this
  // horizontal distance (voxels).
  int anchorRadiusVoxels = 10;
  // An anchored twin must lie this far (voxels) from every point, or the count's suppression
  // radius when that is smaller.
  int anchoredSeparationVoxels = 3;
};

// The best vertical mirror plane of the occupied voxels (axis x or y, offset within a few voxels
// of the bounding box's middle), or none when its score is below `minSymmetry` or there are no
// voxels.
std::optional<MirrorPlane> findMirrorPlane(const std::vector<VoxelIndex>& voxels, int resolution,
                                           float minSymmetry);

// `points` plus the mirror image of each point (best first, images after their point) that lies
// beyond `nmsRadius` of the plane, of every given point and of every image so far, whose
// neighbourhood matches, and where the field is low enough (settings). An image's distance is the
// field's smallest within two voxels, its confidence exp(-distance / confidenceScale). Unchanged
// without a plane.
std::vector<ExtractedPoint> completeMirrorPairs(const PredictedField& field,
                                                const std::vector<ExtractedPoint>& points,
                                                const ExtractionSettings& extraction,
                                                const MirrorPairSettings& settings = {});

// `points` plus, for each point with an anchor (a spout, normalized frame) within
// `anchorRadiusVoxels` horizontally, its image across the vertical plane through the nearest such
// anchor, normal to the horizontal axis along which the point lies further from it; the image is
// kept under the same conditions as in completeMirrorPairs, but beyond `anchoredSeparationVoxels`
// of the other points instead of the suppression radius, and not when the straight segment from
// the point to its image runs through occupied voxels only (one lever across the spout, not two
// handles). Unchanged without anchors.
std::vector<ExtractedPoint> completeAnchoredPairs(const PredictedField& field,
                                                  const std::vector<ExtractedPoint>& points,
                                                  const std::vector<Eigen::Vector3f>& anchors,
                                                  const ExtractionSettings& extraction,
                                                  const MirrorPairSettings& settings = {});

}  // namespace sagrid
