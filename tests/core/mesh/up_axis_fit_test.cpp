// The up-axis detector's fit (a linear term plus a hidden layer) and its weights file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/mesh/up_axis_benchmark.h"
#include "core/mesh/up_axis_detection.h"

namespace sagrid {
namespace {

// Six candidates whose descriptors are zero except entries 0 and 1; the true one is where the two
// entries agree (both 1 or both 0 among candidates where they differ otherwise): an exclusive-or
// that no linear score of the entries can rank first every time.
UpAxisExample xorExample(int up, bool bothOn) {
  UpAxisExample e;
  e.up = up;
  for (int i = 0; i < 6; ++i) {
    UpAxisDescriptor d{};
    const bool truth = i == up;
    const bool a = i % 2 == 0, b = i % 3 == 0;
    if (truth) {
      d[0] = d[1] = bothOn ? 1.0f : 0.0f;
    } else {
      d[0] = a == b ? (a ? 0.0f : 1.0f) : (a ? 1.0f : 0.0f);
      d[1] = 1.0f - d[0];
    }
    d[2] = 1.0f;  // a constant entry, as real descriptors have
    e.candidates.push_back(d);
  }
  return e;
}

TEST(UpAxisFit, HiddenLayerLearnsWhatNoLinearScoreCan) {
  std::vector<UpAxisExample> examples;
  for (int up = 0; up < 6; ++up) {
    examples.push_back(xorExample(up, true));
    examples.push_back(xorExample(up, false));
  }
  // No linear score ranks (1,1) and (0,0) above both (1,0) and (0,1): s11 + s00 = s10 + s01.
  float accuracy = 0;
  const UpAxisWeights w = fitUpAxisWeights(examples, 3000, 1e-4f, &accuracy);
  EXPECT_FLOAT_EQ(accuracy, 1.0f);
  for (const auto& e : examples) {
    for (int i = 0; i < 6; ++i) {
      if (i == e.up) continue;
      EXPECT_GT(upAxisScore(w, e.candidates[e.up]), upAxisScore(w, e.candidates[i]));
    }
  }
}

TEST(UpAxisFit, DeterministicAndDefaultWithoutExamples) {
  std::vector<UpAxisExample> examples{xorExample(2, true), xorExample(4, false)};
  EXPECT_EQ(fitUpAxisWeights(examples, 200), fitUpAxisWeights(examples, 200));
  EXPECT_EQ(fitUpAxisWeights({}, 200), defaultUpAxisWeights());
  UpAxisExample broken;  // not six candidates: ignored
  broken.up = 0;
  EXPECT_EQ(fitUpAxisWeights({broken}, 200), defaultUpAxisWeights());
}

TEST(UpAxisWeightsText, RoundTripsAndNamesWhatIsWrong) {
  UpAxisWeights w{};
  for (int k = 0; k < kUpAxisParameterCount; ++k) w[k] = 0.25f * static_cast<float>(k % 7) - 0.5f;
  EXPECT_EQ(parseUpAxisWeights(formatUpAxisWeights(w)), w);
  EXPECT_EQ(parseUpAxisWeights(formatUpAxisWeights(defaultUpAxisWeights()) + "\n"),
            defaultUpAxisWeights());

  const auto message = [](const std::string& text) {
    try {
      parseUpAxisWeights(text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("1, 2, 3").find("3 numbers, this detector has"), std::string::npos);
  EXPECT_NE(message("").find("0 numbers"), std::string::npos);
  EXPECT_NE(message("1, nan, 3").find("'nan' (number 2) is not a finite number"),
            std::string::npos);
  EXPECT_NE(message("1, x2f").find("'x2' (number 2)"), std::string::npos);
  EXPECT_NE(message(formatUpAxisWeights(w) + ", 1").find("more than the"), std::string::npos);
}

}  // namespace
}  // namespace sagrid
