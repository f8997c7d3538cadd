// Touch keys: the flat pads of a glass hob's touch controls. They rise a millimetre or two above
// the top, a voxel or less of the 64^3 grid, so the network does not see them (on 150 generated
// stoves no network trained on, its nearest toggle point was more than 5 cm from the pads on 20 of
// the 22 touch stoves); but each is a small part of its own, flat, with a round or squarish
// footprint, high on the object, standing on a flat top that reaches beyond it all round, and a
// hob has several. Works in the normalized frame (largest extent 1, z up).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/geometry/connected_parts.h"
#include "core/grid/normalization.h"

namespace sagrid {

class SurfaceScene;

struct TouchKey {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // the middle of its top, normalized frame
  float radius = 0;                                  // half its larger horizontal extent
};

struct TouchKeySettings {
  float maxHeightVoxels = 0.5f;  // a key rises no more than this (voxels of the grid)
  float maxFlatness = 0.4f;      // height / smaller horizontal extent
  // Its larger horizontal extent, in voxels: a fingertip's width on a hob 30-90 cm wide.
  float minWidthVoxels = 0.5f, maxWidthVoxels = 5.0f;
  float maxAspect = 2.5f;  // larger / smaller horizontal extent (a pointer line on a knob is more)
  int minTriangles = 8;    // a solid pad, not a decal quad
  // Its bottom no lower than this share of the object's height above its bottom: a cooktop's top
  // can lie under half its height, below the gas grate.
  float minHeightShare = 0.25f;
  // It stands on a top: rays cast down beside it, at 1.5 x its radius from its middle in eight
  // directions, meet an upward surface (normal z at least minTopNormal) within its height plus
  // half a voxel on at least minSupportedRays of them (a knob's grip bar, flat too, stands out
  // in the air in front of a panel).
  int minSupportedRays = 6;
  float minTopNormal = 0.9f;
  // A hob has a few keys; one flat pad alone is a badge, dozens are a pattern.
  int fewestKeys = 1, mostKeys = 24;
};

// The touch keys among `parts` (normalized frame of `normalization`; `resolution` is the grid's),
// in the parts' order; `scene` is the mesh's (z-up mesh frame). Empty unless their number is
// within [fewestKeys, mostKeys].
std::vector<TouchKey> findTouchKeys(const std::vector<ConnectedPart>& parts,
                                    const SurfaceScene& scene, const Normalization& normalization,
                                    int resolution, const TouchKeySettings& settings = {});

}  // namespace sagrid
