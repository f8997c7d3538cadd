#include "core/eval/scorer_learning_curve_plot.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/plot/plot.h"

namespace sagrid {
namespace {

// `figure` of each k's figures, then of all, over `base`'s; pairs that are not finite left out.
ScorerCurveSeries seriesOf(const std::string& name, const std::vector<std::size_t>& ks,
                           const std::vector<PointChoiceFigures>& curve,
                           const PointChoiceFigures& all, double allK,
                           const PointChoiceFigures& base,
                           double (*figure)(const PointChoiceFigures&)) {
  ScorerCurveSeries s;
  s.name = name;
  const double zero = figure(base);
  const auto add = [&](double k, const PointChoiceFigures& f) {
    const double share = figure(f) / zero;
    if (std::isfinite(share)) s.k.push_back(k), s.share.push_back(share);
  };
  for (std::size_t i = 0; i < ks.size() && i < curve.size(); ++i)
    add(static_cast<double>(ks[i]), curve[i]);
  add(allK, all);
  return s;
}

double edits(const PointChoiceFigures& f) { return f.editsPerHandPoint(); }
double error(const PointChoiceFigures& f) { return f.singleErrors ? f.singleError : NAN; }

}  // namespace

std::vector<ScorerCurveSeries> scorerCurveSeries(const ScorerCrossValidation& cv) {
  if (cv.ks.empty() || cv.folds.empty()) return {};
  double others = 0;  // curated objects of the other sources, mean over the folds
  for (const auto& f : cv.folds) others += static_cast<double>(cv.realObjects - f.objects);
  others /= static_cast<double>(cv.folds.size());
  std::vector<ScorerCurveSeries> out = {
      seriesOf("edits", cv.ks, cv.curve, cv.withCurated, others, cv.generatedOnly, edits),
      seriesOf("error", cv.ks, cv.curve, cv.withCurated, others, cv.generatedOnly, error)};
  if (!cv.tunedOn.empty() && cv.unseenCurve.size() == cv.ks.size()) {
    out.push_back(seriesOf("edits, unseen", cv.ks, cv.unseenCurve,
                           cv.unseenWithCurated, others, cv.unseenGeneratedOnly, edits));
    out.push_back(seriesOf("error, unseen", cv.ks, cv.unseenCurve,
                           cv.unseenWithCurated, others, cv.unseenGeneratedOnly, error));
  }
  return out;
}

void writeScorerLearningCurvePng(const ScorerCrossValidation& cv,
                                 const std::filesystem::path& file) {
  const auto series = scorerCurveSeries(cv);
  if (series.empty()) return;
  const plot::Color palette[] = {{31, 119, 180}, {214, 39, 40}, {158, 202, 225}, {255, 152, 150}};
  plot::LinePlot p;
  p.title = "Leave one source out, " + std::to_string(cv.folds.size()) + " sources";
  p.xLabel = "k curated objects of the other sources (last: all), " + std::to_string(cv.draws) +
             " draw(s) per k";
  p.yLabel = "share of generated-only";
  double lastK = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    plot::Series s;
    s.name = series[i].name;
    s.x = series[i].k, s.y = series[i].share;
    s.color = palette[i % std::size(palette)];
    if (!s.x.empty()) lastK = std::max(lastK, s.x.back());
    p.series.push_back(std::move(s));
  }
  plot::Series target;
  target.name = "target";
  target.x = {0.0, lastK};
  target.y = {kLearningCurveTarget, kLearningCurveTarget};
  target.color = {150, 150, 150};
  p.series.push_back(std::move(target));
  plot::writeLinePlotPng(file, p);
}

}  // namespace sagrid
