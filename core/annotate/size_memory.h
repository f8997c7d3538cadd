// A memory of the real sizes of curated objects, recalled by shape (issues 41 and 40): the sizes
// in metres (core/mesh/size_measures.h: largest extent, height, work surface height) of every
// curated real object (Sweet Home 3D's catalog sizes, the wild pool's curated units, real-dev),
// with its category, source and object descriptor. An object whose file says nothing of its units
// is expected at the median size of the curated objects of its category whose descriptors are
// nearest (z-scored over the memory), in the measure of the memory's that those neighbours agree
// on most; the units guess (core/mesh/unit_guess.h) gives way to that size where its named unit is
// more than the memory's far factor from it. The measures a memory may recall, how many objects and
// the factor are chosen leaving each source out (`sagrid units memory`). resources/models/units_memory.json; a
// folder without it keeps the named-unit guess.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/mesh/size_measures.h"
#include "core/mesh/unit_guess.h"

namespace sagrid {

inline constexpr const char* kSizeMemoryFile = "units_memory.json";

struct RememberedSize {
  std::string id, source, category;  // category "stove", "sink" or "none"
  std::vector<float> descriptor;
  // The file's sizes in its own units and the curated metres per unit: the sizes it is remembered
  // by, and what evaluating the memory again with more objects needs.
  SizeMeasures units;
  double metersPerUnit = 0;
  double meters(SizeMeasure measure) const { return units[measure] * metersPerUnit; }
};

// What a memory expects of an object: a size in metres in one measure, and how far apart (the
// median absolute deviation of their logs) the recalled objects are in it.
struct ExpectedSize {
  SizeMeasure measure = SizeMeasure::LargestExtent;
  double meters = 0;
  double spread = 0;
};

class SizeMemory {
 public:
  // `measures`: those it may recall (at least one; the largest extent alone when empty).
  SizeMemory(std::vector<RememberedSize> entries, std::string featureConfigHash, double farFactor,
             int neighbours = 5, std::vector<SizeMeasure> measures = {});

  // The `neighbours` entries of `category` nearest to `descriptor` (entries of `leaveOutSource`
  // left out: leave-one-source-out evaluation); of the memory's measures that `object` has (finite,
  // positive) and at least half of them have, the one they agree on most (ties: the earlier
  // measure), and the median of their sizes in it, in log. nullopt when no entry of the category
  // is left, no measure qualifies or the descriptor's size differs.
  std::optional<ExpectedSize> expectedSize(const std::vector<float>& descriptor,
                                           const std::string& category, const SizeMeasures& object,
                                           const std::string& leaveOutSource = {}) const;

  // `guess` unless the expected size is more than `farFactor` (the memory's own when negative)
  // from what it makes of the object's size in that measure (unlessFarFromExpectedSize).
  UnitGuess refine(const UnitGuess& guess, const SizeMeasures& object,
                   const std::vector<float>& descriptor, const std::string& category,
                   const std::string& leaveOutSource = {}, double farFactor = -1) const;

  const std::vector<RememberedSize>& entries() const { return m_entries; }
  const std::string& featureConfigHash() const { return m_featureConfigHash; }
  double farFactor() const { return m_farFactor; }
  const std::vector<SizeMeasure>& measures() const { return m_measures; }
  int neighbours() const { return m_neighbours; }

  nlohmann::json toJson() const;
  // Throws FileError naming `file` for another schema, missing or non-finite values, descriptors
  // of different sizes, sizes that are not positive, unknown measures. An entry without a height or
  // work surface (a memory written before they were remembered) lacks that measure.
  static SizeMemory fromJson(const nlohmann::json& j, const std::filesystem::path& file);

 private:
  std::vector<RememberedSize> m_entries;
  std::string m_featureConfigHash;
  double m_farFactor;
  int m_neighbours;
  std::vector<SizeMeasure> m_measures;
  std::vector<float> m_mean, m_scale;  // per descriptor dimension, over the entries
};

// modelsDir/units_memory.json, nullopt when the folder has none; throws FileError as fromJson.
std::optional<SizeMemory> readSizeMemory(const std::filesystem::path& modelsDir);
void writeSizeMemory(const SizeMemory& memory, const std::filesystem::path& modelsDir);

}  // namespace sagrid
