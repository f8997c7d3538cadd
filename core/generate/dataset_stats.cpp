#include "core/generate/dataset_stats.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

#include "core/dataset/dataset.h"
#include "core/labels/labels.h"

namespace sagrid::gen {

namespace {

struct CategoryStats {
  int objects = 0;
  std::map<std::string, std::map<std::string, int>> fields;  // field -> value -> count
  std::map<std::string, int> affordances;
  std::vector<long long> triangles;
};

std::string valueText(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  return v.dump();
}

}  // namespace

std::string datasetStatsTable(const std::filesystem::path& datasetDir) {
  static const std::vector<std::string> kFields = {
      "kind", "layout", "burners", "burner_look", "controls", "knobs", "knob_style", "finish",
      "basins", "basin_shape", "faucet", "handle", "handles", "rim", "cabinet", "spout"};
  std::map<std::string, CategoryStats> stats;
  for (const auto& entry : readDataset(datasetDir)) {
    const ObjectLabels labels = readLabels(entry.labels);
    CategoryStats& s = stats[labels.object.category];
    ++s.objects;
    const nlohmann::json& extra = labels.object.extra;
    if (auto units = extra.find("units"); units != extra.end()) ++s.fields["units"][valueText(*units)];
    ++s.fields["format"][entry.mesh.extension().string()];
    if (auto g = extra.find("generator"); g != extra.end() && g->is_object()) {
      for (const auto& f : kFields) {
        if (auto v = g->find(f); v != g->end()) ++s.fields[f][valueText(*v)];
      }
      for (const char* listField : {"extras", "distractors"}) {
        if (auto v = g->find(listField); v != g->end() && v->is_array()) {
          if (v->empty()) ++s.fields[listField]["(none)"];
          for (const auto& item : *v) ++s.fields[listField][valueText(item)];
        }
      }
      if (auto t = g->find("triangles"); t != g->end() && t->is_number()) s.triangles.push_back(t->get<long long>());
    }
    for (const auto& a : labels.affordances) ++s.affordances[a.type];
  }

  std::ostringstream out;
  for (auto& [category, s] : stats) {
    out << "## " << category << " (" << s.objects << " objects)\n\n";
    out << "| affordance | points | per object |\n|---|---:|---:|\n";
    for (const auto& [type, n] : s.affordances) {
      out << "| " << type << " | " << n << " | " << (s.objects ? double(n) / s.objects : 0.0) << " |\n";
    }
    if (!s.triangles.empty()) {
      std::sort(s.triangles.begin(), s.triangles.end());
      out << "\ntriangles: min " << s.triangles.front() << ", median " << s.triangles[s.triangles.size() / 2]
          << ", max " << s.triangles.back() << "\n";
    }
    for (const auto& [field, values] : s.fields) {
      out << "\n| " << field << " | count |\n|---|---:|\n";
      std::vector<std::pair<std::string, int>> sorted(values.begin(), values.end());
      std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
      for (const auto& [value, n] : sorted) out << "| " << value << " | " << n << " |\n";
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace sagrid::gen
