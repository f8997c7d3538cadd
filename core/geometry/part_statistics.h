// What an object's parts say about what it is, as numbers a classifier reads beside its shape as a
// whole: how many parts it has, and its families of copies (a hob's burner caps, a row of knobs, a
// tap's two handles) with their size and height on the object. The category decision learns from
// them instead of a rule per kind of part (the burner-cap rule read one such family).
#pragma once

#include <array>
#include <vector>

#include "core/geometry/connected_parts.h"

namespace sagrid {

struct Mesh;

inline constexpr int kPartStatisticsSize = 14;

// Of a z-up mesh, in order; sizes are shares of the mesh's largest extent, heights of its vertical
// extent from its bottom (0) to its top (1). Instance parts are connected or material parts
// (connectedAndMaterialParts) of at least kMinInstanceTriangles triangles and at most
// kInstanceDiagonalShare of the largest extent across; a family is an instance part and its
// copies (kCopyTolerance). Families are ranked by members, then width.
//  0 parts: log(1 + parts of at least kMinInstanceTriangles)
//  1 instance parts: log(1 + their count)
//  2-5 largest family: log(1 + members), width share (larger horizontal extent), mean height of
//      its centroids, flatness (height / width, at most 1)
//  6-8 second family: log(1 + members), width share, mean height
//  9-11 largest family of round flat parts (isRoundFlatPart, as burner caps): log(1 + members),
//      width share, mean height
//  12 materials: log(1 + materials used by the triangles)
//  13 share of the parts that only their material separates
// All zero for an empty mesh; a family's entries zero where there is none.
std::array<float, kPartStatisticsSize> partStatistics(const Mesh& mesh);
// The same from the mesh's parts when they were found already (connectedAndMaterialParts(mesh),
// its frame).
std::array<float, kPartStatisticsSize> partStatistics(const Mesh& mesh,
                                                      const std::vector<ConnectedPart>& parts);

// A short name of each entry, in order (`sagrid info --parts`).
inline constexpr std::array<const char*, kPartStatisticsSize> kPartStatisticNames = {
    "log(1 + parts)",          "log(1 + instance parts)",    "largest family: log(1 + members)",
    "largest family: width",   "largest family: height",     "largest family: flatness",
    "second family: log(1 + members)", "second family: width", "second family: height",
    "round flat family: log(1 + members)", "round flat family: width",
    "round flat family: height", "log(1 + materials)", "share of parts by material"};

// The largest box diagonal of an instance part, as a share of the mesh's largest extent (a
// range's burner cap is up to 0.15 of it across, so somewhat above kSmallPartDiagonal).
inline constexpr float kInstanceDiagonalShare = 0.3f;

}  // namespace sagrid
