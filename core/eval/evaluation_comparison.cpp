#include "core/eval/evaluation_comparison.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/paired_change.h"
#include "core/common/report_cell.h"
#include "core/eval/count_breakdown.h"

namespace sagrid {
namespace {

constexpr const char* kPaperMethod = "SAGrid argmin (paper)";
constexpr const char* kAutoMethod = "SAGrid auto count";

const TypeMetrics* metricsOf(const EvaluationReport& r, const std::string& method,
                             const std::string& model) {
  for (const auto& m : r.methods)
    if (m.method == method) {
      const auto it = m.byModel.find(model);
      return it == m.byModel.end() ? nullptr : &it->second;
    }
  return nullptr;
}

std::vector<std::string> modelColumns(const std::vector<LabelledReport>& reports) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& lr : reports)
    for (const auto& n : lr.report->modelNames)
      if (seen.insert(n).second) names.push_back(n);
  return names;
}

double paperAverage(const EvaluationReport& r, const std::vector<std::string>& names) {
  double sum = 0;
  int count = 0;
  for (const auto& n : names)
    if (const auto* t = metricsOf(r, kPaperMethod, n); t && std::isfinite(t->paperError))
      sum += t->paperError, ++count;
  return count ? sum / count : NAN;
}

void checkSameData(const std::vector<LabelledReport>& reports) {
  if (reports.empty()) throw InvalidArgument("comparison: no reports");
  for (const auto& lr : reports)
    if (lr.report->objects != reports.front().report->objects ||
        evaluatedData(*lr.report) != evaluatedData(*reports.front().report))
      throw InvalidArgument("comparison: " + lr.label + " was evaluated on " +
                            std::to_string(lr.report->objects) + " objects of " +
                            evaluatedData(*lr.report) + ", " + reports.front().label + " on " +
                            std::to_string(reports.front().report->objects) + " of " +
                            evaluatedData(*reports.front().report));
}

// Another set against the first, object by object, on one per-object figure (lower is better).
PairedChange againstFirst(const EvaluationReport& first, const EvaluationReport& other,
                          double (*figure)(const nlohmann::json&)) {
  auto byId = [&](const EvaluationReport& r) {
    std::map<std::string, double> out;
    for (const auto& object : r.perObject)
      if (const double f = figure(object); std::isfinite(f))
        out[object.value("id", std::string())] = f;
    return out;
  };
  return pairedChange(pairById(byId(first), byId(other)));
}

double editsFigure(const nlohmann::json& object) { return objectEdits(object); }

std::string againstFirstCell(const PairedChange& c, double scale, const char* format) {
  return reportCell(scale * c.current, format) + " -> " + reportCell(scale * c.candidate, format) +
         " (noise " + reportCell(scale * c.noise, format) + "), lower on " +
         std::to_string(c.lower) + ", higher on " + std::to_string(c.higher) + ": " +
         c.comparison();
}

nlohmann::json againstFirstJson(const PairedChange& c) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"objects", c.objects},     {"first", number(c.current)}, {"this", number(c.candidate)},
          {"noise", number(c.noise)}, {"lower_on", c.lower},        {"higher_on", c.higher},
          {"verdict", c.comparison()}};
}

}  // namespace

std::string comparisonMarkdown(const std::vector<LabelledReport>& reports) {
  checkSameData(reports);
  const auto names = modelColumns(reports);
  std::ostringstream md;
  md << "# Model sets side by side\n\nData: `" << evaluatedData(*reports.front().report) << "` — "
     << reports.front().report->objects << " objects.\n\n"
     << "## Single-point error (m, paper's metric)\n\n| Models |";
  for (const auto& n : names) md << ' ' << paperColumnName(n) << " |";
  md << " Avg |\n|---|";
  for (std::size_t i = 0; i <= names.size(); ++i) md << "---|";
  md << '\n';
  for (const auto& lr : reports) {
    md << "| " << lr.label << " |";
    for (const auto& n : names) {
      const auto* t = metricsOf(*lr.report, kPaperMethod, n);
      md << ' ' << reportCell(t ? t->paperError : NAN, "%.4f") << " |";
    }
    md << ' ' << reportCell(paperAverage(*lr.report, names), "%.4f") << " |\n";
  }
  md << "\n## Automatic count: recall within 5 cm / right count\n\n| Models |";
  for (const auto& n : names) md << ' ' << paperColumnName(n) << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < names.size(); ++i) md << "---|";
  md << '\n';
  for (const auto& lr : reports) {
    md << "| " << lr.label << " |";
    for (const auto& n : names) {
      const auto* t = metricsOf(*lr.report, kAutoMethod, n);
      md << ' ' << reportCell(t ? 100 * t->recall : NAN, "%.0f %%") << " / "
         << reportCell(t ? 100 * t->countRight : NAN, "%.0f %%") << " |";
    }
    md << '\n';
  }
  md << "\n## Curator effort\n\n| Models | Edits / object | By hand (points / object) | "
        "Edits ÷ by hand | Right with one key |\n|---|---|---|---|---|\n";
  for (const auto& lr : reports) {
    const CuratorEffort& e = lr.report->effort;
    md << "| " << lr.label << " | " << reportCell(e.editsPerObject, "%.2f") << " | "
       << reportCell(e.handPointsPerObject, "%.2f") << " | "
       << reportCell(e.editsPerObject / e.handPointsPerObject, "%.2f") << " | "
       << reportCell(100 * e.oneKeyShare, "%.1f %%") << " |\n";
  }
  if (reports.size() > 1) {
    md << "\n## Against " << reports.front().label
       << ", object by object\n\nEach object's figure under both sets, paired: the means, the "
          "standard error of the per-object changes (noise) and the objects whose figure went "
          "down or up; beyond its noise as every guarded update decides.\n\n| Models | Edits / "
          "object | Single-point error (cm, the object's models averaged) |\n|---|---|---|\n";
    for (std::size_t i = 1; i < reports.size(); ++i)
      md << "| " << reports[i].label << " | "
         << againstFirstCell(againstFirst(*reports.front().report, *reports[i].report, editsFigure),
                             1, "%.2f")
         << " | "
         << againstFirstCell(
                againstFirst(*reports.front().report, *reports[i].report, objectPaperError), 100,
                "%.1f")
         << " |\n";
  }
  std::vector<std::string> labels;
  std::vector<CountBreakdown> breakdowns;
  for (const auto& lr : reports) {
    labels.push_back(lr.label);
    breakdowns.push_back(countBreakdown(lr.report->perObject, kAutoMethod));
  }
  md << countBreakdownComparisonMarkdown(labels, breakdowns);
  return md.str();
}

nlohmann::json comparisonJson(const std::vector<LabelledReport>& reports) {
  checkSameData(reports);
  const auto names = modelColumns(reports);
  nlohmann::json j = nlohmann::json::array();
  for (const auto& lr : reports) {
    const double avg = paperAverage(*lr.report, names);
    const CuratorEffort& e = lr.report->effort;
    j.push_back({{"models", lr.label},
                 {"paper_error_avg_m", std::isfinite(avg) ? nlohmann::json(avg) : nullptr},
                 {"edits_per_object", e.editsPerObject},
                 {"hand_points_per_object", e.handPointsPerObject},
                 {"one_key_share", e.oneKeyShare},
                 {"report", evaluationJson(*lr.report)}});
    if (&lr != &reports.front())
      j.back()["against_first"] = {
          {"edits",
           againstFirstJson(againstFirst(*reports.front().report, *lr.report, editsFigure))},
          {"paper_error_m",
           againstFirstJson(againstFirst(*reports.front().report, *lr.report, objectPaperError))}};
  }
  return j;
}

}  // namespace sagrid
