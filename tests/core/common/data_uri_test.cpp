#include "core/common/data_uri.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

TEST(DataUri, Base64DataUrisDecodeAndOtherUrisAreNotDataUris) {
  EXPECT_EQ(dataUriBytes("data:application/octet-stream;base64,AAECAw=="), std::string("\x00\x01\x02\x03", 4));
  EXPECT_EQ(dataUriBytes("data:;base64,aGVsbG8"), "hello");  // padding left out
  EXPECT_EQ(dataUriMediaType("data:image/webp;base64,AAAA"), "image/webp");
  EXPECT_FALSE(dataUriBytes("mesh.bin").has_value());
  EXPECT_THROW(dataUriBytes("data:text/plain,hello"), InvalidArgument);
  EXPECT_THROW(dataUriBytes("data:;base64,a$b="), InvalidArgument);
}

TEST(DataUri, PercentEscapesDecodeAndMalformedOnesStay) {
  EXPECT_EQ(percentDecoded("my%20tex%2Epng"), "my tex.png");
  EXPECT_EQ(percentDecoded("100%"), "100%");
  EXPECT_EQ(percentDecoded("a%zzb"), "a%zzb");
}

}  // namespace
}  // namespace sagrid
