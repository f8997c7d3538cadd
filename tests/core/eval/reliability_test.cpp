#include "core/eval/reliability.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"

namespace sagrid {
namespace {

TEST(Reliability, BinsObjectsAndMeasuresCalibrationError) {
  // Bin 0.8-1.0: 0.9 and 0.9, one right -> observed 0.5; bin 0.0-0.2: 0.1, wrong -> observed 0.
  const ReliabilityReport r =
      reliabilityReport({0.9, 0.9, 0.1}, {true, false, false}, 5, {0.5, 0.95});
  ASSERT_EQ(r.bins.size(), 5u);
  EXPECT_EQ(r.bins[4].objects, 2u);
  EXPECT_DOUBLE_EQ(r.bins[4].meanConfidence, 0.9);
  EXPECT_DOUBLE_EQ(r.bins[4].observed, 0.5);
  EXPECT_EQ(r.bins[0].objects, 1u);
  EXPECT_TRUE(std::isnan(r.bins[2].observed));
  EXPECT_NEAR(r.expectedCalibrationError, (2 * 0.4 + 1 * 0.1) / 3, 1e-12);
  ASSERT_EQ(r.autoAccept.size(), 2u);
  EXPECT_NEAR(r.autoAccept[0].coverage, 2.0 / 3, 1e-12);
  EXPECT_DOUBLE_EQ(r.autoAccept[0].precision, 0.5);
  EXPECT_DOUBLE_EQ(r.autoAccept[1].coverage, 0.0);
  EXPECT_TRUE(std::isnan(r.autoAccept[1].precision));
  EXPECT_THROW(reliabilityReport({}, {}), InvalidArgument);
}

TEST(Reliability, ConfidenceOfOneLandsInTheLastBin) {
  const ReliabilityReport r = reliabilityReport({1.0}, {true}, 4);
  EXPECT_EQ(r.bins[3].objects, 1u);
  EXPECT_DOUBLE_EQ(r.expectedCalibrationError, 0.0);
}

}  // namespace
}  // namespace sagrid
