#include "core/eval/reliability.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/common/error.h"
#include "core/common/report_cell.h"
#include "core/plot/plot.h"

namespace sagrid {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

void checkSizes(const std::vector<double>& confidence, const std::vector<bool>& right) {
  if (confidence.empty() || confidence.size() != right.size())
    throw InvalidArgument("reliability: " + std::to_string(confidence.size()) +
                          " confidences for " + std::to_string(right.size()) + " outcomes");
}

}  // namespace

ReliabilityReport reliabilityReport(const std::vector<double>& confidence,
                                    const std::vector<bool>& right, int binCount,
                                    const std::vector<double>& thresholds) {
  checkSizes(confidence, right);
  ReliabilityReport r;
  r.bins.resize(std::max(1, binCount));
  std::vector<double> confidenceSum(r.bins.size(), 0), rightSum(r.bins.size(), 0);
  for (std::size_t b = 0; b < r.bins.size(); ++b) {
    r.bins[b].low = static_cast<double>(b) / r.bins.size();
    r.bins[b].high = static_cast<double>(b + 1) / r.bins.size();
  }
  for (std::size_t i = 0; i < confidence.size(); ++i) {
    const double c = std::clamp(confidence[i], 0.0, 1.0);
    const auto b = std::min(r.bins.size() - 1, static_cast<std::size_t>(c * r.bins.size()));
    ++r.bins[b].objects;
    confidenceSum[b] += c;
    rightSum[b] += right[i];
  }
  for (std::size_t b = 0; b < r.bins.size(); ++b) {
    auto& bin = r.bins[b];
    bin.meanConfidence = bin.objects ? confidenceSum[b] / bin.objects : kNan;
    bin.observed = bin.objects ? rightSum[b] / bin.objects : kNan;
    if (bin.objects)
      r.expectedCalibrationError += static_cast<double>(bin.objects) / confidence.size() *
                                    std::abs(bin.meanConfidence - bin.observed);
  }
  for (double t : thresholds) r.autoAccept.push_back(autoAcceptAt(confidence, right, t));
  return r;
}

nlohmann::json toJson(const ReliabilityReport& r) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json j;
  for (const auto& b : r.bins)
    j["bins"].push_back({{"low", b.low},
                         {"high", b.high},
                         {"objects", b.objects},
                         {"mean_confidence", number(b.meanConfidence)},
                         {"observed_one_key", number(b.observed)}});
  j["expected_calibration_error"] = r.expectedCalibrationError;
  for (const auto& a : r.autoAccept)
    j["auto_accept"].push_back({{"threshold", a.threshold},
                                {"coverage", a.coverage},
                                {"precision", number(a.precision)}});
  return j;
}

std::string reliabilityMarkdown(const ReliabilityReport& r) {
  std::ostringstream md;
  md << "| Confidence | Objects | Mean confidence | Right with one key |\n|---|---|---|---|\n";
  for (const auto& b : r.bins)
    md << "| " << reportCell(b.low, "%.1f") << "–" << reportCell(b.high, "%.1f") << " | " << b.objects
       << " | " << reportCell(b.meanConfidence, "%.2f") << " | " << reportCell(100 * b.observed, "%.0f %%")
       << " |\n";
  md << "\nExpected calibration error: " << reportCell(r.expectedCalibrationError, "%.3f") << "\n\n"
     << "| Accept automatically above | Objects accepted | Precision (right among them) |\n"
     << "|---|---|---|\n";
  for (const auto& a : r.autoAccept)
    md << "| " << reportCell(a.threshold, "%.2f") << " | " << reportCell(100 * a.coverage, "%.0f %%") << " | "
       << reportCell(100 * a.precision, "%.0f %%") << " |\n";
  return md.str();
}

void writeReliabilityPng(const std::filesystem::path& file, const ReliabilityReport& r) {
  plot::LinePlot p;
  p.title = "Reliability: object confidence vs right with one key";
  p.xLabel = "mean confidence in bin";
  p.yLabel = "share right with one key";
  plot::Series ideal{"perfect calibration", {0, 1}, {0, 1}, {150, 150, 150}};
  plot::Series observed{"observed", {}, {}, {214, 39, 40}};
  for (const auto& b : r.bins)
    if (b.objects) observed.x.push_back(b.meanConfidence), observed.y.push_back(b.observed);
  p.series = {ideal};
  if (!observed.x.empty()) p.series.push_back(observed);
  plot::writeLinePlotPng(file, p, 600, 500);
}

}  // namespace sagrid
