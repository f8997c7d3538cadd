#include "core/eval/count_breakdown.h"

#include <cmath>
#include <sstream>

#include "core/common/report_cell.h"

namespace sagrid {

namespace {

int editsOf(const nlohmann::json& object, const std::string& model) {
  int total = 0;
  const auto edits = object.find("edits");
  if (edits == object.end() || !edits->contains(model)) return 0;
  for (const auto& [kind, n] : edits->at(model).items())
    if (n.is_number_integer()) total += n.get<int>();
  return total;
}

// The settings of `generator` that can group objects: string values.
std::map<std::string, std::string> stringSettings(const nlohmann::json& generator) {
  std::map<std::string, std::string> out;
  for (const auto& [key, value] : generator.items())
    if (value.is_string()) out[key] = value.get<std::string>();
  return out;
}

}  // namespace

const CountGroup* CountBreakdown::find(const std::string& model, const std::string& setting,
                                       const std::string& value) const {
  const auto m = groups.find(model);
  if (m == groups.end()) return nullptr;
  const auto k = m->second.find(setting);
  if (k == m->second.end()) return nullptr;
  const auto v = k->second.find(value);
  return v == k->second.end() ? nullptr : &v->second;
}

CountBreakdown countBreakdown(const nlohmann::json& perObject, const std::string& method) {
  CountBreakdown all;
  for (const auto& object : perObject) {
    const auto generator = object.find("generator");
    const auto truth = object.find("truth");
    const auto predictions = object.find("predictions");
    if (generator == object.end() || !generator->is_object() || truth == object.end() ||
        predictions == object.end())
      continue;
    const auto settings = stringSettings(*generator);
    for (const auto& [model, points] : truth->items()) {
      if (!predictions->contains(model) || !predictions->at(model).contains(method)) continue;
      const std::size_t expected = points.size();
      const std::size_t found = predictions->at(model).at(method).size();
      const int edits = editsOf(object, model);
      for (const auto& [key, value] : settings) {
        CountGroup& g = all.groups[model][key][value];
        ++g.objects;
        g.right += found == expected;
        g.fewer += found < expected;
        g.more += found > expected;
        g.edits += static_cast<std::size_t>(edits);
      }
    }
  }
  // A setting with one value says nothing about which objects fail.
  for (auto& [model, settings] : all.groups)
    for (auto it = settings.begin(); it != settings.end();)
      it = it->second.size() < 2 ? settings.erase(it) : std::next(it);
  for (auto it = all.groups.begin(); it != all.groups.end();)
    it = it->second.empty() ? all.groups.erase(it) : std::next(it);
  return all;
}

std::string countBreakdownMarkdown(const CountBreakdown& breakdown) {
  if (breakdown.empty()) return {};
  std::ostringstream md;
  md << "\n## Automatic count by generator setting (generated objects)\n";
  for (const auto& [model, settings] : breakdown.groups) {
    md << "\n### " << model << "\n\n"
       << "| Setting | Value | Objects | Right count | Too few | Too many | Edits / object |\n"
       << "|---|---|---|---|---|---|---|\n";
    for (const auto& [key, values] : settings)
      for (const auto& [value, g] : values) {
        md << "| " << key << " | " << value << " | " << g.objects << " | "
           << reportCell(g.rightPercent(), "%.0f %%") << " | " << g.fewer << " | " << g.more
           << " | "
           << reportCell(static_cast<double>(g.edits) / static_cast<double>(g.objects), "%.2f")
           << " |\n";
      }
  }
  return md.str();
}

std::string countBreakdownComparisonMarkdown(const std::vector<std::string>& labels,
                                             const std::vector<CountBreakdown>& breakdowns) {
  // Every (model, setting, value) any set has; the objects are the same for every set.
  std::map<std::string, std::map<std::string, std::map<std::string, std::size_t>>> rows;
  for (const auto& b : breakdowns)
    for (const auto& [model, settings] : b.groups)
      for (const auto& [key, values] : settings)
        for (const auto& [value, g] : values) rows[model][key][value] = g.objects;
  if (rows.empty()) return {};
  std::ostringstream md;
  md << "\n## Automatic count by generator setting: right count\n\n| Model | Setting | Value | "
        "Objects |";
  for (const auto& label : labels) md << ' ' << label << " |";
  md << "\n|---|---|---|---|";
  for (std::size_t i = 0; i < labels.size(); ++i) md << "---|";
  md << '\n';
  for (const auto& [model, settings] : rows)
    for (const auto& [key, values] : settings)
      for (const auto& [value, objects] : values) {
        md << "| " << model << " | " << key << " | " << value << " | " << objects << " |";
        for (const auto& b : breakdowns) {
          const CountGroup* g = b.find(model, key, value);
          md << ' ' << reportCell(g ? g->rightPercent() : NAN, "%.0f %%") << " |";
        }
        md << '\n';
      }
  return md.str();
}

nlohmann::json countBreakdownJson(const CountBreakdown& breakdown) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [model, settings] : breakdown.groups)
    for (const auto& [key, values] : settings)
      for (const auto& [value, g] : values)
        j[model][key][value] = {{"objects", g.objects},
                                {"right", g.right},
                                {"fewer", g.fewer},
                                {"more", g.more},
                                {"edits", g.edits}};
  return j;
}

}  // namespace sagrid
