#include "core/annotate/size_memory.h"

#include <algorithm>
#include <cmath>
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
}  // namespace

SizeMemory::SizeMemory(std::vector<RememberedSize> entries, std::string featureConfigHash,
                       double farFactor, int neighbours)
    : m_entries(std::move(entries)),
      m_featureConfigHash(std::move(featureConfigHash)),
      m_farFactor(farFactor),
      m_neighbours(std::max(1, neighbours)) {
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

std::optional<double> SizeMemory::expectedMeters(const std::vector<float>& descriptor,
                                                 const std::string& category,
                                                 const std::string& leaveOutSource) const {
  if (descriptor.size() != m_mean.size()) return std::nullopt;
  std::vector<std::pair<double, double>> byDistance;  // (squared distance, log size)
  for (const auto& e : m_entries) {
    if (e.category != category || (!leaveOutSource.empty() && e.source == leaveOutSource)) continue;
    double d2 = 0;
    for (std::size_t i = 0; i < descriptor.size(); ++i) {
      const double z = (double(descriptor[i]) - e.descriptor[i]) / m_scale[i];
      d2 += z * z;
    }
    byDistance.emplace_back(d2, std::log(e.largestExtentMeters()));
  }
  if (byDistance.empty()) return std::nullopt;
  const std::size_t k = std::min<std::size_t>(std::size_t(m_neighbours), byDistance.size());
  std::partial_sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(k), byDistance.end());
  std::vector<double> logs;
  for (std::size_t i = 0; i < k; ++i) logs.push_back(byDistance[i].second);
  return std::exp(median(logs));
}

UnitGuess SizeMemory::refine(const UnitGuess& guess, double largestExtent,
                             const std::vector<float>& descriptor, const std::string& category,
                             const std::string& leaveOutSource, double farFactor) const {
  const auto expected = expectedMeters(descriptor, category, leaveOutSource);
  if (!expected) return guess;
  return unlessFarFromExpectedSize(guess, largestExtent, *expected,
                                   farFactor < 0 ? m_farFactor : farFactor);
}

nlohmann::json SizeMemory::toJson() const {
  nlohmann::json entries = nlohmann::json::array();
  for (const auto& e : m_entries)
    entries.push_back({{"id", e.id},
                       {"source", e.source},
                       {"category", e.category},
                       {"extent_units", e.extentUnits},
                       {"meters_per_unit", e.metersPerUnit},
                       {"descriptor", e.descriptor}});
  return {{"schema", kSchema},
          {"feature_config_hash", m_featureConfigHash},
          {"far_factor", m_farFactor},
          {"neighbours", m_neighbours},
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
      r.extentUnits = e.at("extent_units").get<double>();
      r.metersPerUnit = e.at("meters_per_unit").get<double>();
      for (const double v : {r.extentUnits, r.metersPerUnit})
        if (!(v > 0) || !std::isfinite(v))
          throw FileError(file, "entry " + r.id + ": extent_units and meters_per_unit must be positive numbers");
      if (!entries.empty() && r.descriptor.size() != entries.front().descriptor.size())
        throw FileError(file, "entry " + r.id + ": its descriptor has " +
                                  std::to_string(r.descriptor.size()) + " values, the first entry's " +
                                  std::to_string(entries.front().descriptor.size()));
      for (float v : r.descriptor)
        if (!std::isfinite(v)) throw FileError(file, "entry " + r.id + ": descriptor values must be finite");
      entries.push_back(std::move(r));
    }
    return SizeMemory(std::move(entries), j.at("feature_config_hash").get<std::string>(), farFactor,
                      j.value("neighbours", 5));
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
