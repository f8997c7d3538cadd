#include "core/eval/candidate_sets.h"

#include <fstream>
#include <optional>
#include <sstream>

#include "core/annotate/pass_options.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/eval/metrics.h"

namespace sagrid {

namespace {
constexpr const char* kSchema = "sagrid.point_candidates/1";

nlohmann::json pointsJson(const std::vector<Eigen::Vector3f>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) out.push_back({p.x(), p.y(), p.z()});
  return out;
}

std::vector<Eigen::Vector3f> pointsFrom(const nlohmann::json& j) {
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : j)
    out.emplace_back(p.at(0).get<float>(), p.at(1).get<float>(), p.at(2).get<float>());
  return out;
}
}  // namespace

std::vector<bool> candidateLabels(const CandidateSet& set, double radiusMeters) {
  // Each true point marks its nearest candidate within the radius: two candidates beside one
  // knob are one point and one deletion.
  std::vector<bool> out(set.candidateSurface.size(), false);
  for (const auto& t : set.truth) {
    double best = radiusMeters;
    std::optional<std::size_t> nearest;
    for (std::size_t c = 0; c < set.candidateSurface.size(); ++c) {
      const double d = (set.candidateSurface[c] - t).norm() * set.metersPerUnit;
      if (d <= best) {
        best = d;
        nearest = c;
      }
    }
    if (nearest) out[*nearest] = true;
  }
  return out;
}

void withoutFeatures(std::vector<CandidateSet>& sets, const std::vector<std::string>& names) {
  for (const auto& name : names) {
    const auto colon = name.rfind(':');
    const std::string model = colon == std::string::npos ? "" : name.substr(0, colon);
    const std::size_t column = candidateFeatureIndex(name.substr(colon + 1));
    for (auto& set : sets)
      if (model.empty() || set.model == model)
        for (auto& candidate : set.candidates) candidate.features.at(column) = 0;
  }
}

nlohmann::json toJson(const std::vector<CandidateSet>& sets) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& s : sets) {
    nlohmann::json features = nlohmann::json::array(), positions = nlohmann::json::array(),
                   distances = nlohmann::json::array(), kept = nlohmann::json::array(),
                   copies = nlohmann::json::array();
    for (const auto& c : s.candidates) {
      features.push_back(c.features);
      copies.push_back(c.copies);
      kept.push_back(c.kept);
      positions.push_back({c.position.x(), c.position.y(), c.position.z()});
      distances.push_back(c.distance);
    }
    all.push_back({{"object", s.object},
                   {"source", s.source},
                   {"model", s.model},
                   {"generated", s.generated},
                   {"meters_per_unit", s.metersPerUnit},
                   {"features", features},
                   {"positions", positions},
                   {"distances", distances},
                   {"kept_candidates", kept},
                   {"copies", copies},
                   {"surface", pointsJson(s.candidateSurface)},
                   {"kept", pointsJson(s.keptSurface)},
                   {"truth", pointsJson(s.truth)},
                   {"passes_off", s.passesOff},
                   {"network_weights", s.networkWeights}});
  }
  return {{"schema", kSchema}, {"features", candidateFeatureNames()}, {"sets", all}};
}

std::vector<CandidateSet> readCandidateSets(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw FileError(file, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  std::vector<CandidateSet> out;
  try {
    const auto j = nlohmann::json::parse(text.str());
    if (j.value("schema", "") != kSchema)
      throw FileError(file, "not a SAGrid point candidate file (schema)");
    if (j.at("features").get<std::vector<std::string>>() != candidateFeatureNames())
      throw FileError(file,
                      "holds other candidate features than this build computes: write it "
                      "again (sagrid scorer candidates)");
    for (const auto& s : j.at("sets")) {
      CandidateSet set;
      set.object = s.at("object").get<std::string>();
      set.source = s.at("source").get<std::string>();
      set.model = s.at("model").get<std::string>();
      set.generated = s.at("generated").get<bool>();
      set.metersPerUnit = s.at("meters_per_unit").get<double>();
      const auto positions = pointsFrom(s.at("positions"));
      const auto& features = s.at("features");
      const auto& distances = s.at("distances");
      const auto& kept = s.at("kept_candidates");
      if (!s.contains("copies"))
        throw FileError(file,
                        "object " + set.object +
                            ": its candidates carry no copies (an "
                            "older build wrote it): write it again (sagrid scorer candidates)");
      const auto& copies = s.at("copies");
      set.candidateSurface = pointsFrom(s.at("surface"));
      if (features.size() != positions.size() || distances.size() != positions.size() ||
          kept.size() != positions.size() || copies.size() != positions.size() ||
          set.candidateSurface.size() != positions.size())
        throw FileError(file, "object " + set.object + ": candidate lists of different lengths");
      for (std::size_t c = 0; c < positions.size(); ++c) {
        PointCandidate candidate{positions[c], distances.at(c).get<float>(), kept.at(c).get<bool>(),
                                 features.at(c).get<std::vector<float>>(),
                                 copies.at(c).get<std::vector<std::size_t>>()};
        if (candidate.features.size() != candidateFeatureNames().size())
          throw FileError(file, "object " + set.object + ": a candidate with " +
                                    std::to_string(candidate.features.size()) + " features");
        for (std::size_t q : candidate.copies)
          if (q >= positions.size() || q == c)
            throw FileError(file, "object " + set.object +
                                      ": a candidate's copy is no other candidate of the object");
        set.candidates.push_back(std::move(candidate));
      }
      set.keptSurface = pointsFrom(s.at("kept"));
      set.networkWeights = s.value("network_weights", "");
      set.truth = pointsFrom(s.at("truth"));
      try {
        set.passesOff = recordedPassesOff(s.value("passes_off", std::vector<std::string>{}));
      } catch (const InvalidArgument& e) {
        throw FileError(file, "object " + set.object + ": " + e.what());
      }
      out.push_back(std::move(set));
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, e.what());
  }
  return out;
}

void writeCandidateSets(const std::filesystem::path& file, const std::vector<CandidateSet>& sets) {
  writeFileAtomic(file, toJson(sets).dump() + "\n");
}

}  // namespace sagrid
