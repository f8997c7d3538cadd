// The words of a mesh file's name and what curated names teach of a category: the split at
// separators and case changes, naive Bayes worked by hand, unknown words saying nothing, the
// record's round trip and a malformed record refused.
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
}

}  // namespace
}  // namespace sagrid
