#include "core/common/utf8.h"

#include <gtest/gtest.h>

namespace sagrid {
namespace {

TEST(Utf8, AcceptsWellFormed) {
  EXPECT_FALSE(firstInvalidUtf8("").has_value());
  EXPECT_FALSE(firstInvalidUtf8("plain ascii").has_value());
  EXPECT_FALSE(firstInvalidUtf8("\xc3\xbc \xe2\x82\xac \xf0\x9f\x98\x80 \xf4\x8f\xbf\xbf").has_value());
}

TEST(Utf8, ReportsOffsetOfFirstBadByte) {
  EXPECT_EQ(firstInvalidUtf8("ab\xff"), 2u);
  EXPECT_EQ(firstInvalidUtf8("a\xc0\xaf"), 1u);          // overlong '/'
  EXPECT_EQ(firstInvalidUtf8("\xe0\x80\xaf"), 0u);       // overlong 3-byte
  EXPECT_EQ(firstInvalidUtf8("xy\xed\xa0\x80"), 2u);     // UTF-16 surrogate
  EXPECT_EQ(firstInvalidUtf8("\xf4\x90\x80\x80"), 0u);   // above U+10FFFF
  EXPECT_EQ(firstInvalidUtf8("ok\xe2\x82"), 2u);         // truncated sequence
  EXPECT_EQ(firstInvalidUtf8("\xc3\x28"), 0u);           // bad continuation
}

}  // namespace
}  // namespace sagrid
