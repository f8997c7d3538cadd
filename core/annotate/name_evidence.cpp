#include "core/annotate/name_evidence.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/common/ascii_case.h"
#include "core/common/error.h"

namespace sagrid {

namespace {
bool isLetter(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c >= 0x80;
}
bool isUpper(unsigned char c) { return c >= 'A' && c <= 'Z'; }
bool isLower(unsigned char c) { return c >= 'a' && c <= 'z'; }
constexpr std::size_t kShortestWord = 3;
}  // namespace

std::vector<std::string> fileNameWords(const std::filesystem::path& file) {
  const std::string stem = file.stem().string();
  std::set<std::string> words;
  std::string word;
  const auto flush = [&] {
    if (word.size() >= kShortestWord) words.insert(asciiLower(word));
    word.clear();
  };
  for (std::size_t i = 0; i < stem.size(); ++i) {
    const auto c = static_cast<unsigned char>(stem[i]);
    if (!isLetter(c)) {
      flush();
      continue;
    }
    if (isUpper(c) && !word.empty() && isLower(static_cast<unsigned char>(word.back()))) flush();
    word += static_cast<char>(c);
  }
  flush();
  return {words.begin(), words.end()};
}

NameEvidence NameEvidence::count(
    const std::vector<std::pair<std::vector<std::string>, std::string>>& objects,
    const std::vector<std::string>& classes) {
  NameEvidence e;
  e.m_classes = classes;
  e.m_words.resize(classes.size());
  for (const auto& [words, cls] : objects) {
    const auto at = std::find(classes.begin(), classes.end(), cls);
    if (at == classes.end() || words.empty()) continue;
    auto& counts = e.m_words[static_cast<std::size_t>(at - classes.begin())];
    for (const auto& w : std::set<std::string>(words.begin(), words.end())) ++counts[w];
    ++e.m_objects;
  }
  e.finish();
  return e;
}

void NameEvidence::finish() {
  std::set<std::string> vocabulary;
  m_totals.assign(m_words.size(), 0.0);
  for (std::size_t c = 0; c < m_words.size(); ++c)
    for (const auto& [w, n] : m_words[c]) {
      vocabulary.insert(w);
      m_totals[c] += n;
    }
  m_vocabulary = vocabulary.size();
}

std::vector<std::string> NameEvidence::knownWords(const std::vector<std::string>& words) const {
  std::vector<std::string> known;
  for (const auto& w : std::set<std::string>(words.begin(), words.end()))
    if (std::any_of(m_words.begin(), m_words.end(),
                    [&](const auto& counts) { return counts.count(w) > 0; }))
      known.push_back(w);
  return known;
}

std::vector<double> NameEvidence::logLikelihoods(const std::vector<std::string>& words) const {
  std::vector<double> ll(m_classes.size(), 0.0);
  for (const auto& w : knownWords(words)) {
    for (std::size_t c = 0; c < m_classes.size(); ++c) {
      const auto it = m_words[c].find(w);
      const double n = it == m_words[c].end() ? 0.0 : it->second;
      ll[c] += std::log((n + 1.0) / (m_totals[c] + static_cast<double>(m_vocabulary)));
    }
  }
  return ll;
}

void NameEvidence::setWeight(double weight) {
  if (!std::isfinite(weight) || weight < 0)
    throw InvalidArgument(
        "the weight of the file-name evidence must be a finite number >= 0, got " +
        std::to_string(weight));
  m_weight = weight;
}

nlohmann::json NameEvidence::toJson() const {
  nlohmann::json words = nlohmann::json::object();
  for (std::size_t c = 0; c < m_classes.size(); ++c) words[m_classes[c]] = m_words[c];
  return {{"classes", m_classes}, {"objects", m_objects}, {"words", words}, {"weight", m_weight}};
}

NameEvidence NameEvidence::fromJson(const nlohmann::json& j) {
  NameEvidence e;
  try {
    e.m_classes = j.at("classes").get<std::vector<std::string>>();
    e.m_objects = j.at("objects").get<std::size_t>();
    if (j.contains("weight")) e.setWeight(j.at("weight").get<double>());
    for (const auto& cls : e.m_classes) {
      const auto& counts = j.at("words").at(cls);
      e.m_words.push_back(counts.get<std::map<std::string, int>>());
      for (const auto& [w, n] : e.m_words.back())
        if (n < 1)
          throw InvalidArgument("word \"" + w + "\" of " + cls + " counted " + std::to_string(n) +
                                " times");
    }
  } catch (const nlohmann::json::exception& err) {
    throw InvalidArgument(std::string("malformed name evidence: ") + err.what());
  }
  e.finish();
  return e;
}

std::vector<double> nameWeighted(std::vector<double> p, const std::vector<double>& logLikelihoods,
                                 double weight) {
  const double top = *std::max_element(logLikelihoods.begin(), logLikelihoods.end());
  double sum = 0;
  for (std::size_t a = 0; a < p.size(); ++a)
    sum += (p[a] *= std::exp(weight * (logLikelihoods[a] - top)));
  if (sum > 0)
    for (double& v : p) v /= sum;
  return p;
}

namespace {
void checkCase(const HeldOutNameCase& c) {
  if (c.shape.size() != c.logLikelihoods.size() || c.truth >= c.shape.size())
    throw InvalidArgument("a held-out name case with " + std::to_string(c.shape.size()) +
                          " shape probabilities, " + std::to_string(c.logLikelihoods.size()) +
                          " log-likelihoods and true class " + std::to_string(c.truth));
}
// d/dw of heldOutLogLikelihood: sum over cases of ll(truth) - the expected ll under p_w.
double slope(const std::vector<HeldOutNameCase>& cases, double w) {
  double g = 0;
  for (const auto& c : cases) {
    const auto p = nameWeighted(c.shape, c.logLikelihoods, w);
    g += c.logLikelihoods[c.truth];
    for (std::size_t a = 0; a < p.size(); ++a) g -= p[a] * c.logLikelihoods[a];
  }
  return g;
}
}  // namespace

double heldOutLogLikelihood(const std::vector<HeldOutNameCase>& cases, double weight) {
  double sum = 0;
  for (const auto& c : cases) {
    checkCase(c);
    sum += std::log(std::max(nameWeighted(c.shape, c.logLikelihoods, weight)[c.truth], 1e-300));
  }
  return sum;
}

double fitNameWeight(const std::vector<HeldOutNameCase>& cases) {
  std::vector<HeldOutNameCase> telling;
  for (const auto& c : cases) {
    checkCase(c);
    const auto [low, high] = std::minmax_element(c.logLikelihoods.begin(), c.logLikelihoods.end());
    if (c.shape[c.truth] > 0 && *high > *low) telling.push_back(c);
  }
  if (telling.empty()) return 1.0;
  if (slope(telling, 0) <= 0) return 0.0;
  if (slope(telling, kMaxNameWeight) >= 0) return kMaxNameWeight;
  double low = 0, high = kMaxNameWeight;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (low + high);
    (slope(telling, mid) > 0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace sagrid
