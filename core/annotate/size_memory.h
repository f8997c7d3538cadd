// A memory of the real sizes of curated objects, recalled by shape (issues 41 and 40): the
// largest extent in metres of every curated real object (Sweet Home 3D's catalog sizes, the wild
// pool's curated units, real-dev), with its category, source and object descriptor. An object
// whose file says nothing of its units is expected at the median size of the curated objects of
// its category whose descriptors are nearest (z-scored over the memory); the units guess
// (core/mesh/unit_guess.h) gives way to that size where its named unit is more than the memory's
// far factor from it, the factor chosen leaving each source out (`sagrid units memory`).
// resources/models/units_memory.json; a folder without it keeps the named-unit guess.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/mesh/unit_guess.h"

namespace sagrid {

inline constexpr const char* kSizeMemoryFile = "units_memory.json";

struct RememberedSize {
  std::string id, source, category;  // category "stove", "sink" or "none"
  std::vector<float> descriptor;
  // The file's largest extent in its own units and the curated metres per unit: the size it is
  // remembered by, and what evaluating the memory again with more objects needs.
  double extentUnits = 0, metersPerUnit = 0;
  double largestExtentMeters() const { return extentUnits * metersPerUnit; }
};

class SizeMemory {
 public:
  SizeMemory(std::vector<RememberedSize> entries, std::string featureConfigHash, double farFactor,
             int neighbours = 5);

  // The median, in log, of the largest extents of the `neighbours` entries of `category` nearest
  // to `descriptor`, entries of `leaveOutSource` left out (leave-one-source-out evaluation);
  // nullopt when no entry of the category is left or the descriptor's size differs.
  std::optional<double> expectedMeters(const std::vector<float>& descriptor,
                                       const std::string& category,
                                       const std::string& leaveOutSource = {}) const;

  // `guess` unless the expected size is more than `farFactor` (the memory's own when negative)
  // from what it makes of `largestExtent` (unlessFarFromExpectedSize).
  UnitGuess refine(const UnitGuess& guess, double largestExtent,
                   const std::vector<float>& descriptor, const std::string& category,
                   const std::string& leaveOutSource = {}, double farFactor = -1) const;

  const std::vector<RememberedSize>& entries() const { return m_entries; }
  const std::string& featureConfigHash() const { return m_featureConfigHash; }
  double farFactor() const { return m_farFactor; }

  nlohmann::json toJson() const;
  // Throws FileError naming `file` for another schema, missing or non-finite values, descriptors
  // of different sizes, sizes that are not positive.
  static SizeMemory fromJson(const nlohmann::json& j, const std::filesystem::path& file);

 private:
  std::vector<RememberedSize> m_entries;
  std::string m_featureConfigHash;
  double m_farFactor;
  int m_neighbours;
  std::vector<float> m_mean, m_scale;  // per descriptor dimension, over the entries
};

// modelsDir/units_memory.json, nullopt when the folder has none; throws FileError as fromJson.
std::optional<SizeMemory> readSizeMemory(const std::filesystem::path& modelsDir);
void writeSizeMemory(const SizeMemory& memory, const std::filesystem::path& modelsDir);

}  // namespace sagrid
