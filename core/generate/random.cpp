#include "core/generate/random.h"

#include <cmath>

namespace sagrid::gen {

double Rng::uniform() {
  return static_cast<double>(m_engine() >> 11) * (1.0 / 9007199254740992.0);  // 53 bits
}

double Rng::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

int Rng::uniformInt(int lo, int hi) {
  if (hi <= lo) return lo;
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(m_engine() % span);  // bias is negligible for small spans
}

double Rng::normal(double mean, double sd) {
  const double u1 = 1.0 - uniform();  // (0, 1]
  const double u2 = uniform();
  return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

int Rng::weighted(std::initializer_list<double> weights) {
  return weighted(std::vector<double>(weights));
}

int Rng::weighted(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) total += w;
  double x = uniform() * total;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (x < weights[i]) return static_cast<int>(i);
    x -= weights[i];
  }
  return static_cast<int>(weights.size()) - 1;
}

std::uint64_t deriveSeed(std::uint64_t seed, std::string_view stream, std::uint64_t index) {
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::uint64_t h = mix(seed);
  for (char c : stream) h = mix(h ^ static_cast<unsigned char>(c));
  return mix(h ^ mix(index));
}

}  // namespace sagrid::gen
