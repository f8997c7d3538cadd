// Seeded random numbers for the procedural generator. Distributions are implemented here rather
// than taken from <random>: std::uniform_real_distribution and friends differ between standard
// library versions, and generated datasets must be byte-identical for the same seed.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <random>
#include <string_view>
#include <vector>

namespace sagrid::gen {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : m_engine(seed) {}

  std::uint64_t next() { return m_engine(); }
  double uniform();                            // [0, 1)
  double uniform(double lo, double hi);        // [lo, hi)
  float uniformf(double lo, double hi) { return static_cast<float>(uniform(lo, hi)); }
  int uniformInt(int lo, int hi);              // [lo, hi], inclusive
  bool chance(double probability) { return uniform() < probability; }
  double normal(double mean, double sd);       // Box-Muller
  // Index drawn with the given (unnormalised, non-negative) weights.
  int weighted(std::initializer_list<double> weights);
  int weighted(const std::vector<double>& weights);
  template <typename T>
  const T& pick(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(uniformInt(0, static_cast<int>(items.size()) - 1))];
  }

 private:
  std::mt19937_64 m_engine;  // the engine's output sequence is fixed by the standard
};

// Mixes a seed with a stream name and an index (splitmix64), so object i of a run gets its own
// stream and generating N objects is a prefix of generating N + 1.
std::uint64_t deriveSeed(std::uint64_t seed, std::string_view stream, std::uint64_t index);

}  // namespace sagrid::gen
