#include "core/annotate/size_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/json_file.h"

namespace sagrid {

namespace {
constexpr const char* kSchema = "sagrid.units_memory/1";

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

bool usable(double size) { return size > 0 && std::isfinite(size); }

// The optional sizes of an entry: absent or null is a measure the entry lacks.
double optionalSize(const nlohmann::json& entry, const char* key) {
  const auto it = entry.find(key);
  return it == entry.end() || it->is_null() ? std::numeric_limits<double>::quiet_NaN() : it->get<double>();
}

nlohmann::json sizeOrNull(double size) { return usable(size) ? nlohmann::json(size) : nlohmann::json(); }

constexpr const char* kHeightKey = "height_units";
constexpr const char* kWorkSurfaceKey = "work_surface_units";
}  // namespace

SizeMemory::SizeMemory(std::vector<RememberedSize> entries, std::string featureConfigHash,
                       double farFactor, int neighbours, std::vector<SizeMeasure> measures)
    : m_entries(std::move(entries)),
      m_featureConfigHash(std::move(featureConfigHash)),
      m_farFactor(farFactor),
      m_neighbours(std::max(1, neighbours)),
      m_measures(measures.empty() ? std::vector<SizeMeasure>{SizeMeasure::LargestExtent}
                                  : std::move(measures)) {
  if (m_entries.empty()) return;
  const std::size_t d = m_entries.front().descriptor.size();
  m_mean.assign(d, 0.0f);
  m_scale.assign(d, 0.0f);
  for (const auto& e : m_entries)
    for (std::size_t i = 0; i < d; ++i) m_mean[i] += e.descriptor[i] / float(m_entries.size());
  for (const auto& e : m_entries)
    for (std::size_t i = 0; i < d; ++i)
      m_scale[i] += (e.descriptor[i] - m_mean[i]) * (e.descriptor[i] - m_mean[i]) / float(m_entries.size());
  // A dimension every entry shares weighs nothing rather than dividing by zero.
  for (float& s : m_scale) s = std::sqrt(s) + 1e-6f;
}

std::optional<ExpectedSize> SizeMemory::expectedSize(const std::vector<float>& descriptor,
                                                     const std::string& category,
                                                     const SizeMeasures& object,
                                                     const std::string& leaveOutSource) const {
  if (descriptor.size() != m_mean.size()) return std::nullopt;
  std::vector<std::pair<double, const RememberedSize*>> byDistance;
  for (const auto& e : m_entries) {
    if (e.category != category || (!leaveOutSource.empty() && e.source == leaveOutSource)) continue;
    double d2 = 0;
    for (std::size_t i = 0; i < descriptor.size(); ++i) {
      const double z = (double(descriptor[i]) - e.descriptor[i]) / m_scale[i];
      d2 += z * z;
    }
    byDistance.emplace_back(d2, &e);
  }
  if (byDistance.empty()) return std::nullopt;
  const std::size_t k = std::min<std::size_t>(std::size_t(m_neighbours), byDistance.size());
  std::partial_sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(k), byDistance.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::optional<ExpectedSize> best;
  for (const SizeMeasure measure : m_measures) {
    if (!usable(object[measure])) continue;
    std::vector<double> logs;
    for (std::size_t i = 0; i < k; ++i)
      if (const double m = byDistance[i].second->meters(measure); usable(m)) logs.push_back(std::log(m));
    if (logs.empty() || 2 * logs.size() < k) continue;
    const double centre = median(logs);
    std::vector<double> deviations;
    for (const double l : logs) deviations.push_back(std::abs(l - centre));
    const double spread = median(deviations);
    if (!best || spread < best->spread) best = ExpectedSize{measure, std::exp(centre), spread};
  }
  return best;
}

UnitGuess SizeMemory::refine(const UnitGuess& guess, const SizeMeasures& object,
                             const std::vector<float>& descriptor, const std::string& category,
                             const std::string& leaveOutSource, double farFactor) const {
  const auto expected = expectedSize(descriptor, category, object, leaveOutSource);
  if (!expected) return guess;
  return unlessFarFromExpectedSize(guess, object[expected->measure], expected->meters,
                                   farFactor < 0 ? m_farFactor : farFactor,
                                   sizeMeasureWords(expected->measure));
}

nlohmann::json SizeMemory::toJson() const {
  nlohmann::json measureNames = nlohmann::json::array();
  for (const SizeMeasure m : m_measures) measureNames.push_back(sizeMeasureName(m));
  nlohmann::json entries = nlohmann::json::array();
  for (const auto& e : m_entries)
    entries.push_back({{"id", e.id},
                       {"source", e.source},
                       {"category", e.category},
                       {"extent_units", e.units.largestExtent},
                       {kHeightKey, sizeOrNull(e.units.height)},
                       {kWorkSurfaceKey, sizeOrNull(e.units.workSurface)},
                       {"meters_per_unit", e.metersPerUnit},
                       {"descriptor", e.descriptor}});
  return {{"schema", kSchema},
          {"feature_config_hash", m_featureConfigHash},
          {"far_factor", m_farFactor},
          {"neighbours", m_neighbours},
          {"measures", measureNames},
          {"entries", entries}};
}

SizeMemory SizeMemory::fromJson(const nlohmann::json& j, const std::filesystem::path& file) {
  if (!j.is_object() || j.value("schema", "") != kSchema)
    throw FileError(file, "not a SAGrid units memory (schema)");
  try {
    const double farFactor = j.at("far_factor").get<double>();
    if (!std::isfinite(farFactor) || farFactor < 1)
      throw FileError(file, "far_factor must be a finite number of at least 1");
    std::vector<RememberedSize> entries;
    for (const auto& e : j.at("entries")) {
      RememberedSize r;
      r.id = e.at("id").get<std::string>();
      r.source = e.at("source").get<std::string>();
      r.category = e.at("category").get<std::string>();
      r.descriptor = e.at("descriptor").get<std::vector<float>>();
      r.units.largestExtent = e.at("extent_units").get<double>();
      r.units.height = optionalSize(e, kHeightKey);
      r.units.workSurface = optionalSize(e, kWorkSurfaceKey);
      r.metersPerUnit = e.at("meters_per_unit").get<double>();
      for (const double v : {r.units.largestExtent, r.metersPerUnit})
        if (!usable(v))
          throw FileError(file, "entry " + r.id + ": extent_units and meters_per_unit must be positive numbers");
      for (const double v : {r.units.height, r.units.workSurface})
        if (!std::isnan(v) && !usable(v))
          throw FileError(file, "entry " + r.id + ": " + kHeightKey + " and " + kWorkSurfaceKey +
                                    " must be positive numbers where given");
      if (!entries.empty() && r.descriptor.size() != entries.front().descriptor.size())
        throw FileError(file, "entry " + r.id + ": its descriptor has " +
                                  std::to_string(r.descriptor.size()) + " values, the first entry's " +
                                  std::to_string(entries.front().descriptor.size()));
      for (float v : r.descriptor)
        if (!std::isfinite(v)) throw FileError(file, "entry " + r.id + ": descriptor values must be finite");
      entries.push_back(std::move(r));
    }
    std::vector<SizeMeasure> measures;
    if (j.contains("measures"))
      for (const auto& name : j.at("measures")) measures.push_back(sizeMeasureNamed(name.get<std::string>()));
    return SizeMemory(std::move(entries), j.at("feature_config_hash").get<std::string>(), farFactor,
                      j.value("neighbours", 5), std::move(measures));
  } catch (const InvalidArgument& e) {
    throw FileError(file, e.what());
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, std::string("malformed units memory: ") + e.what());
  }
}

std::optional<SizeMemory> readSizeMemory(const std::filesystem::path& modelsDir) {
  const auto file = modelsDir / kSizeMemoryFile;
  if (!std::filesystem::exists(file)) return std::nullopt;
  return SizeMemory::fromJson(readJsonFile(file), file);
}

void writeSizeMemory(const SizeMemory& memory, const std::filesystem::path& modelsDir) {
  writeFileAtomic(modelsDir / kSizeMemoryFile, memory.toJson().dump() + "\n");
}

}  // namespace sagrid
