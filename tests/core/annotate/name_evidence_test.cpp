// The words of a mesh file's name and what curated names teach of a category: the split at
// separators and case changes, naive Bayes worked by hand, unknown words saying nothing, the
// record's round trip and a malformed record refused; the weight of the names beside the shape
// fitted by maximum likelihood, worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/annotate/name_evidence.h"
#include "core/common/error.h"

namespace sagrid {
namespace {

using Words = std::vector<std::string>;

TEST(FileNameWords, SplitAtSeparatorsAndCaseChangesInLowerCase) {
  EXPECT_EQ(fileNameWords("assets/kitchenStoveElectric_2.glb"),
            (Words{"electric", "kitchen", "stove"}));
  EXPECT_EQ(fileNameWords("/a/coffee-machine.v2.obj"), (Words{"coffee", "machine"}));
  EXPECT_EQ(fileNameWords("Sink Sink SINK.OBJ"), (Words{"sink"}));  // each word once
  EXPECT_EQ(fileNameWords("model.dae"), (Words{"model"}));
  EXPECT_EQ(fileNameWords("x1_yz.glb"), Words{});  // words of fewer than three letters go
  EXPECT_EQ(fileNameWords("cuisini\xc3\xa8re.obj"), (Words{"cuisini\xc3\xa8re"}));  // UTF-8 stays
  EXPECT_EQ(fileNameWords(""), Words{});
}

NameEvidence fourNamedObjects() {
  return NameEvidence::count({{{"stove", "kitchen"}, "stove"},
                              {{"stove"}, "stove"},
                              {{"sink", "kitchen"}, "sink"},
                              {{"coffee", "machine"}, "none"},
                              {{"anything"}, "microwave"}},  // not a class given: skipped
                             {"sink", "stove", "none"});
}

TEST(NameEvidence, NaiveBayesOverTheWordsWorkedByHand) {
  const NameEvidence e = fourNamedObjects();
  EXPECT_EQ(e.namedObjects(), 4u);
  // Vocabulary: coffee, kitchen, machine, sink, stove (5). Words per class: sink 2, stove 3,
  // none 2.
  const auto ll = e.logLikelihoods({"stove", "stove", "unheard"});
  ASSERT_EQ(ll.size(), 3u);
  EXPECT_NEAR(ll[0], std::log(1.0 / 7), 1e-12);  // sink: 0 + 1 over 2 + 5
  EXPECT_NEAR(ll[1], std::log(3.0 / 8), 1e-12);  // stove: 2 + 1 over 3 + 5
  EXPECT_NEAR(ll[2], std::log(1.0 / 7), 1e-12);  // none
  const auto kitchen = e.logLikelihoods({"kitchen", "machine"});
  EXPECT_NEAR(kitchen[0], std::log(2.0 / 7) + std::log(1.0 / 7), 1e-12);
  EXPECT_NEAR(kitchen[1], std::log(2.0 / 8) + std::log(1.0 / 8), 1e-12);
  EXPECT_NEAR(kitchen[2], std::log(1.0 / 7) + std::log(2.0 / 7), 1e-12);
  EXPECT_EQ(e.knownWords({"stove", "unheard", "kitchen", "stove"}), (Words{"kitchen", "stove"}));
  // Words no curated name held say nothing.
  EXPECT_EQ(e.logLikelihoods({"model", "scene"}), (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(NameEvidence::count({}, {"sink", "none"}).logLikelihoods({"sink"}),
            (std::vector<double>{0, 0}));
}

TEST(NameEvidence, TheRecordRoundTripsAndAMalformedOneIsRefused) {
  const NameEvidence e = fourNamedObjects();
  const NameEvidence back = NameEvidence::fromJson(e.toJson());
  EXPECT_EQ(back.classes(), e.classes());
  EXPECT_EQ(back.namedObjects(), 4u);
  EXPECT_EQ(back.logLikelihoods({"kitchen", "coffee"}), e.logLikelihoods({"kitchen", "coffee"}));
  nlohmann::json missing = e.toJson();
  missing["words"].erase("none");
  EXPECT_THROW(NameEvidence::fromJson(missing), InvalidArgument);
  nlohmann::json negative = e.toJson();
  negative["words"]["sink"]["sink"] = 0;
  EXPECT_THROW(NameEvidence::fromJson(negative), InvalidArgument);
  // The weight travels with the counts; a record written before it reads the Bayes rule's 1.
  NameEvidence weighted = fourNamedObjects();
  weighted.setWeight(1.75);
  EXPECT_EQ(NameEvidence::fromJson(weighted.toJson()).weight(), 1.75);
  nlohmann::json unweighted = e.toJson();
  unweighted.erase("weight");
  EXPECT_EQ(NameEvidence::fromJson(unweighted).weight(), 1.0);
  nlohmann::json below = e.toJson();
  below["weight"] = -0.5;
  EXPECT_THROW(NameEvidence::fromJson(below), InvalidArgument);
  EXPECT_THROW(weighted.setWeight(std::nan("")), InvalidArgument);
}

// Two classes, shapes that cannot tell them apart, and words whose likelihoods favour class 0 by
// a factor of 2: under weight w class 0 has probability 2^w / (2^w + 1). Three of four held-out
// objects are of class 0, so the likeliest weight makes that probability 3/4: w = log2(3).
std::vector<HeldOutNameCase> threeOfFourAsTheWordsSay() {
  const HeldOutNameCase zero{{0.5, 0.5}, {std::log(2.0), 0.0}, 0};
  HeldOutNameCase one = zero;
  one.truth = 1;
  return {zero, zero, zero, one};
}

TEST(FitNameWeight, MaximumLikelihoodWorkedByHand) {
  const auto cases = threeOfFourAsTheWordsSay();
  EXPECT_NEAR(fitNameWeight(cases), std::log2(3.0), 1e-9);
  EXPECT_NEAR(heldOutLogLikelihood(cases, std::log2(3.0)), 3 * std::log(0.75) + std::log(0.25),
              1e-12);
  EXPECT_NEAR(heldOutLogLikelihood(cases, 1.0), 3 * std::log(2.0 / 3) + std::log(1.0 / 3), 1e-12);
}

TEST(FitNameWeight, NamesThatAlwaysMisleadWeighNothingAndNamesNeverWrongTheMost) {
  auto cases = threeOfFourAsTheWordsSay();
  for (auto& c : cases) c.truth = 1;  // the words favour the wrong class every time
  EXPECT_EQ(fitNameWeight(cases), 0.0);
  for (auto& c : cases) c.truth = 0;  // ... or the right one every time
  EXPECT_EQ(fitNameWeight(cases), kMaxNameWeight);
  for (auto& c : cases) c.logLikelihoods = {-3.0, -3.0};  // words known to both classes alike
  EXPECT_EQ(fitNameWeight(cases), 1.0);
  EXPECT_EQ(fitNameWeight({}), 1.0);
  cases.front().truth = 2;
  EXPECT_THROW(fitNameWeight(cases), InvalidArgument);
  cases.front() = {{0.5, 0.5}, {0.0}, 0};
  EXPECT_THROW(fitNameWeight(cases), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
