#include "core/corpus/sweethome3d_catalog.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {
using ::testing::HasSubstr;

TEST(JavaProperties, DecodesIso88591AndUnicodeEscapes) {
  // \xe9 is é in ISO-8859-1; \u00e8 is è; \uD83D\uDE00 is one emoji as a surrogate pair.
  const std::string bytes =
      "# comment\n! also a comment\n"
      "caf\xe9=cr\xe8me\n"
      "escaped = \\u00e8\\u00E9 \\uD83D\\uDE00\n"
      "colon:value\n"
      "spaced   value with spaces  \n"
      "tabs=a\\tb\\\\c\\=d\n"
      "continued=first \\\n    second\r\n"
      "empty=\n";
  const auto p = parseJavaProperties(bytes, "test.properties");
  EXPECT_EQ(p.at("caf\xc3\xa9"), "cr\xc3\xa8me");
  EXPECT_EQ(p.at("escaped"), "\xc3\xa8\xc3\xa9 \xf0\x9f\x98\x80");
  EXPECT_EQ(p.at("colon"), "value");
  EXPECT_EQ(p.at("spaced"), "value with spaces  ");
  EXPECT_EQ(p.at("tabs"), "a\tb\\c=d");
  EXPECT_EQ(p.at("continued"), "first second");
  EXPECT_EQ(p.at("empty"), "");
  EXPECT_EQ(p.size(), 7u);
}

TEST(JavaProperties, MalformedUnicodeEscapeNamesFileAndLine) {
  try {
    parseJavaProperties("a=1\nb=\\u12G4\n", "lib.properties");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("lib.properties"));
    EXPECT_THAT(e.what(), HasSubstr("line 2"));
  }
  EXPECT_THROW(parseJavaProperties("b=\\u12", "x"), FileError);
}

TEST(FurnitureCatalog, ParsesEntriesInIndexOrder) {
  const std::string bytes =
      "id=Lib#All\nname=Lib\nlicense=CC-BY \\u00a9 Someone\n"
      "id#10=Lib#b\nname#10=B\ncategory#10=Kitchen\nmodel#10=/b/b.obj\nwidth#10=10.5\n"
      "modelRotation#10=0 0 1 0 1 0 -1 0 0\n"
      "id#2=Lib#a\nname#2=A\ncategory#2=Bathroom\nmodel#2=/a/"
      "a.obj\nwidth#2=1\ndepth#2=2\nheight#2=3\n"
      "id#3=Lib#nomodel\nname#3=No model\n";
  const FurnitureCatalog c = parseFurnitureCatalog(bytes, "x.properties");
  EXPECT_EQ(c.license, "CC-BY \xc2\xa9 Someone");
  ASSERT_EQ(c.entries.size(), 2u);
  EXPECT_EQ(c.entries[0].index, 2);
  EXPECT_EQ(c.entries[0].id, "Lib#a");
  EXPECT_DOUBLE_EQ(*c.entries[0].height, 3.0);
  EXPECT_FALSE(c.entries[0].modelRotation);
  EXPECT_EQ(c.entries[1].id, "Lib#b");
  EXPECT_DOUBLE_EQ(*c.entries[1].width, 10.5);
  EXPECT_FALSE(c.entries[1].depth);
  ASSERT_TRUE(c.entries[1].modelRotation);
  EXPECT_DOUBLE_EQ((*c.entries[1].modelRotation)[6], -1.0);
  EXPECT_THROW(parseFurnitureCatalog("id#1=a\nmodel#1=/a.obj\nwidth#1=wide\n", "x"), FileError);
  EXPECT_THROW(parseFurnitureCatalog("id#1=a\nmodel#1=/a.obj\nmodelRotation#1=1 0 0\n", "x"),
               FileError);
}

std::optional<CorpusRole> roleOf(const std::string& name, const std::string& category = "Kitchen") {
  FurnitureCatalogEntry e;
  e.name = name;
  e.category = category;
  return selectCorpusRole(e);
}

TEST(CorpusSelection, RolesFollowTheNameRules) {
  EXPECT_EQ(roleOf("Cooker"), CorpusRole::Stove);
  EXPECT_EQ(roleOf("Induction cooker 4 zones"), CorpusRole::Stove);
  EXPECT_EQ(roleOf("Cooktop"), CorpusRole::Stove);
  EXPECT_EQ(roleOf("Propane stove"), CorpusRole::Stove);
  EXPECT_EQ(roleOf("Washbasin", "Bathroom"), CorpusRole::Sink);
  EXPECT_EQ(roleOf("Double vanity", "Bathroom"), CorpusRole::Sink);
  EXPECT_EQ(roleOf("Small lavatory", "Bathroom"), CorpusRole::Sink);
  EXPECT_EQ(roleOf("Sink cabinet"), CorpusRole::Sink);
  EXPECT_EQ(roleOf("Faucet", "Bathroom"), CorpusRole::Sink);  // a tap alone
  EXPECT_EQ(roleOf("Mixer tap"), CorpusRole::Sink);
  EXPECT_EQ(roleOf("Tapestry", "Bathroom"), std::nullopt);
  EXPECT_EQ(roleOf("Shower head and faucet", "Bathroom"), std::nullopt);
  EXPECT_EQ(roleOf("Rice cooker"), CorpusRole::None);              // an appliance, not a hob
  EXPECT_EQ(roleOf("Bath with basin", "Bathroom"), std::nullopt);  // a bathtub, not a sink
  EXPECT_EQ(roleOf("Bathtub", "Bathroom"), std::nullopt);
  EXPECT_EQ(roleOf("Shower", "Bathroom"), std::nullopt);
  EXPECT_EQ(roleOf("Double oven"), CorpusRole::None);
  EXPECT_EQ(roleOf("Coffee brewer"), CorpusRole::None);
  EXPECT_EQ(roleOf("Clothes washing machine", "Bathroom"), CorpusRole::None);
  EXPECT_EQ(roleOf("Fridge & Freezer"), CorpusRole::None);
  EXPECT_EQ(roleOf("Range hood"), CorpusRole::None);
  EXPECT_EQ(roleOf("Coffee table"), std::nullopt);
  EXPECT_EQ(roleOf("Chair"), std::nullopt);
  EXPECT_EQ(roleOf("Cooker", "Living room"), std::nullopt);  // only Kitchen and Bathroom
  EXPECT_STREQ(toString(CorpusRole::None), "none");
}

TEST(CorpusSelection, ObjectIdsMatchTheLabellerListing) {
  EXPECT_EQ(corpusObjectId("Scopia#bathroom3"), "scopia_bathroom3");
  EXPECT_EQ(corpusObjectId("eTeks#cooker"), "eteks_cooker");
  EXPECT_EQ(corpusObjectId("Blend Swap CC-0#stove"), "blend_swap_cc_0_stove");
  EXPECT_EQ(corpusObjectId("Kator Legaz#propane-stove"), "kator_legaz_propane_stove");
  EXPECT_EQ(corpusObjectId("Scopia#induction-cooker-2-zones"), "scopia_induction_cooker_2_zones");
  EXPECT_EQ(corpusObjectId("__Odd  \xc3\xa9 Id!!"), "odd_id");
  EXPECT_EQ(corpusObjectId("###"), "object");
  const std::string longId(100, 'a');
  const std::string bounded = corpusObjectId(longId + "#x");
  EXPECT_EQ(bounded.size(), kMaxCorpusIdLength);
  EXPECT_EQ(bounded, corpusObjectId(longId + "#x"));
  EXPECT_NE(bounded, corpusObjectId(longId + "#y"));
}

}  // namespace
}  // namespace sagrid
