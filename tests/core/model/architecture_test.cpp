#include "core/model/architecture.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid::model {
namespace {
using ::testing::HasSubstr;

TEST(Architecture, ParsesPaperCnn1) {
  const auto arch = Architecture::parse(kPaperCnn1Architecture);
  ASSERT_EQ(arch.layers.size(), 4u);
  EXPECT_EQ(arch.layers[0], (ConvLayerSpec{3, 1, 1024, 1}));
  EXPECT_EQ(arch.layers[1], (ConvLayerSpec{3, 4, 512, 4}));
  EXPECT_EQ(arch.layers[3], (ConvLayerSpec{3, 1, 128, 1}));
  EXPECT_EQ(arch.toString(), kPaperCnn1Architecture);
  EXPECT_EQ(arch.receptiveRadius(), 1 + 4 + 1 + 1);
}

TEST(Architecture, AcceptsSpacesAndRoundTrips) {
  const auto arch = Architecture::parse(" [3, 2, 32, 2] , [1,0,8] ");
  EXPECT_EQ(arch.toString(), "[3,2,32,2],[1,0,8]");
  EXPECT_EQ(Architecture::parse(kDefaultArchitecture).toString(), kDefaultArchitecture);
}

TEST(Architecture, RejectsBadStringsWithClearMessages) {
  auto message = [](const std::string& text) {
    try {
      Architecture::parse(text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(""), HasSubstr("empty"));
  EXPECT_THAT(message("[3,1]"), HasSubstr("layer 1 has 2 numbers"));
  EXPECT_THAT(message("[3,1,16],[3,1,8,2]"), HasSubstr("layer 2: padding 1"));
  EXPECT_THAT(message("[3,1,16],[3,1,8,2]"), HasSubstr("must be 2"));
  EXPECT_THAT(message("[4,1,16]"), HasSubstr("kernel must be odd"));
  EXPECT_THAT(message("[3,1,0]"), HasSubstr("out_channels"));
  EXPECT_THAT(message("[3,1,x]"), HasSubstr("expected an integer"));
  EXPECT_THAT(message("[3,1,16]]"), HasSubstr("expected ','"));
  EXPECT_THAT(message("[3,1,16"), HasSubstr("expected ',' or ']'"));
  EXPECT_THAT(message("3,1,16"), HasSubstr("expected '['"));
}

TEST(Architecture, ParsesExecutionMode) {
  EXPECT_EQ(parseExecutionMode("sparse"), ExecutionMode::Sparse);
  EXPECT_EQ(parseExecutionMode("dense"), ExecutionMode::Dense);
  EXPECT_THROW(parseExecutionMode("Sparse"), InvalidArgument);
}

}  // namespace
}  // namespace sagrid::model
