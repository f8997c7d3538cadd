// Sizes of an object in its file's units, for a memory of curated objects to recall (issue 41;
// core/annotate/size_memory.h). The largest extent is what a size range judges, but objects of one
// kind vary in it (a range with or without a backguard, a hob of two or five zones); their height,
// or the height of their main horizontal surface (the cooktop of a range, the counter of a vanity,
// the top of a fridge), may vary less. Which one a memory recalls is chosen from the curated
// objects (`sagrid units memory`), not here.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace sagrid {

struct Mesh;

enum class SizeMeasure { LargestExtent, Height, WorkSurface };
inline constexpr SizeMeasure kSizeMeasures[] = {SizeMeasure::LargestExtent, SizeMeasure::Height,
                                                SizeMeasure::WorkSurface};

// "largest_extent", "height", "work_surface" (the memory file's names).
const char* sizeMeasureName(SizeMeasure measure);
// Throws InvalidArgument naming `name` when it is none of them.
SizeMeasure sizeMeasureNamed(const std::string& name);
// "largest extent", "height", "work surface height" (for reasons and reports).
const char* sizeMeasureWords(SizeMeasure measure);

// In the file's units; NaN where a measure does not exist (no horizontal surface above the base).
struct SizeMeasures {
  double largestExtent = std::numeric_limits<double>::quiet_NaN();
  double height = std::numeric_limits<double>::quiet_NaN();
  double workSurface = std::numeric_limits<double>::quiet_NaN();
  double operator[](SizeMeasure measure) const;
  double& operator[](SizeMeasure measure);
};

// Of a mesh in SAGrid's z-up frame: the largest side of its box, its height along z, and the height
// above its lowest point of the horizontal faces (normals within about 25 degrees of vertical,
// either side) holding the most area, in bins of 2 % of the height, faces in the lowest 10 % (a
// base or plinth) left out. An empty mesh gives NaN for all three.
SizeMeasures measureSizes(const Mesh& mesh);

}  // namespace sagrid
