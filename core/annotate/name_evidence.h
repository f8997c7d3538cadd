// What the words of a mesh file's name say of its category, learned from curated objects: a
// publisher names a file "kitchenStove.glb", "coffee_machine.glb" or "lavello.obj" far more often
// than "model.dae", and a curated set of files from other publishers teaches which words go with
// which class. Multinomial naive Bayes over the words (each word counted once per object, Laplace
// smoothing): per class c, log P(words | c) = sum over the object's known words w of
// log((objects of c whose name holds w + 1) / (words of c's objects + vocabulary size)). Words no
// curated object's name held say nothing, so a file named "model.glb" is decided by its shape
// alone. The classifier (category_classifier.h) multiplies its shape probabilities by these
// likelihoods raised to a weight where its file says it reads the name: 1 is the Bayes rule as
// if the shape and the words were independent evidence; the weight the classifier learns
// (fitNameWeight) is the one under which curated objects, each decided without its source, were
// likeliest.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sagrid {

// The words of a file's name without its folder and extension: split at every character that is
// not a letter and where a lower-case letter meets an upper-case one ("kitchenStoveElectric_2" ->
// electric, kitchen, stove), lower case (ASCII; UTF-8 bytes stay within their word), words of
// fewer than three letters dropped; sorted, each once.
std::vector<std::string> fileNameWords(const std::filesystem::path& file);

class NameEvidence {
 public:
  // Counts the words of each named object under its class (`classes` order; an object of another
  // class is skipped). Objects are (words, class) pairs.
  static NameEvidence count(
      const std::vector<std::pair<std::vector<std::string>, std::string>>& objects,
      const std::vector<std::string>& classes);

  // Per class (the order given to count), the log-likelihood of `words` (duplicates counted once);
  // all zero when none of them is known, or when nothing was counted.
  std::vector<double> logLikelihoods(const std::vector<std::string>& words) const;

  // The words of `words` some counted name held (those that move the likelihoods), sorted, once.
  std::vector<std::string> knownWords(const std::vector<std::string>& words) const;

  // The power of the likelihoods beside the shape's probabilities (1: the Bayes rule).
  double weight() const { return m_weight; }
  // Throws InvalidArgument for a weight that is not finite or is negative.
  void setWeight(double weight);

  bool empty() const { return m_vocabulary == 0; }
  std::size_t namedObjects() const { return m_objects; }
  const std::vector<std::string>& classes() const { return m_classes; }

  // {"classes": [...], "objects": N, "words": {class: {word: objects}}, "weight": w}; fromJson
  // throws InvalidArgument for a record that does not have that shape (a record without a weight,
  // written before session 66, reads 1).
  nlohmann::json toJson() const;
  static NameEvidence fromJson(const nlohmann::json& j);

 private:
  std::vector<std::string> m_classes;
  // Per class: word -> objects whose name holds it; the sum of those counts; the distinct words.
  std::vector<std::map<std::string, int>> m_words;
  std::vector<double> m_totals;
  std::size_t m_vocabulary = 0, m_objects = 0;
  double m_weight = 1.0;
  void finish();  // totals and vocabulary from m_words
};

// `shape` (class probabilities) times exp(weight * logLikelihoods), normalised (classes in one
// order; left as it is where every product underflows).
std::vector<double> nameWeighted(std::vector<double> shape,
                                 const std::vector<double>& logLikelihoods, double weight);

// One curated object decided without its source: the class probabilities from its shape, the
// log-likelihoods of its file's words counted from the other sources' names (both in one class
// order) and the index of its true class.
struct HeldOutNameCase {
  std::vector<double> shape, logLikelihoods;
  std::size_t truth = 0;
};

// The most the fitted weight may be: where the held-out names never misled, the likelihood grows
// with the weight without end, and names would overrule every shape.
inline constexpr double kMaxNameWeight = 10.0;

// The weight w under which the cases' true classes are likeliest, each decided as
// p(c) = shape(c) * exp(w * ll(c)) / sum over classes (maximum likelihood; the log-likelihood is
// concave in w, so the root of its derivative sum(ll(truth) - E_p[ll]) is found by bisection),
// within [0, kMaxNameWeight]. 1 (the Bayes rule) when no case's words tell its classes apart.
// Throws InvalidArgument for a case whose vectors differ in size or whose truth is out of range.
double fitNameWeight(const std::vector<HeldOutNameCase>& cases);
// The cases' summed log-probability of their true classes under weight w.
double heldOutLogLikelihood(const std::vector<HeldOutNameCase>& cases, double weight);

}  // namespace sagrid
