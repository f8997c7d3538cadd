#include "core/common/paired_change.h"

namespace sagrid {

std::string PairedChange::verdict() const {
  if (clearlyBetter()) return "adopted";
  return change() < 0 ? "refused (better by less than its noise)" : "refused";
}

std::string PairedChange::comparison() const {
  if (!std::isfinite(noise)) return "too few objects to tell";
  if (clearlyBetter()) return "better beyond its noise";
  if (change() > noise * (1 + 1e-9)) return "worse beyond its noise";
  return "within its noise";
}

PairedChange pairedChange(const std::vector<std::vector<ObjectFigures>>& groups) {
  PairedChange out;
  double current = 0, candidate = 0, variance = 0;
  std::size_t judged = 0;
  bool tooFew = false;
  for (const auto& group : groups) {
    if (group.empty()) continue;
    const auto n = static_cast<double>(group.size());
    double sumCurrent = 0, sumChange = 0;
    for (const ObjectFigures& f : group) {
      sumCurrent += f.current;
      sumChange += f.candidate - f.current;
      out.lower += f.candidate < f.current;
      out.higher += f.candidate > f.current;
    }
    const double meanChange = sumChange / n;
    double squares = 0;
    for (const ObjectFigures& f : group) {
      const double d = f.candidate - f.current - meanChange;
      squares += d * d;
    }
    current += sumCurrent / n;
    candidate += (sumCurrent + sumChange) / n;
    if (group.size() < 2)
      tooFew = true;
    else
      variance += squares / (n - 1) / n;
    out.objects += group.size();
    ++judged;
  }
  if (judged == 0) return out;
  const auto g = static_cast<double>(judged);
  out.current = current / g;
  out.candidate = candidate / g;
  out.noise = tooFew ? NAN : std::sqrt(variance) / g;
  return out;
}

std::vector<ObjectFigures> pairById(const std::map<std::string, double>& current,
                                    const std::map<std::string, double>& candidate) {
  std::vector<ObjectFigures> pairs;
  for (const auto& [id, figure] : candidate)
    if (const auto it = current.find(id); it != current.end())
      pairs.push_back({it->second, figure});
  return pairs;
}

}  // namespace sagrid
