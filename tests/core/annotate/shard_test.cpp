#include "core/annotate/shard.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/common/error.h"

namespace sagrid {
namespace {
using ::testing::HasSubstr;

TEST(Shard, ParsesTaskOfCountFromZero) {
  const Shard s = parseShard("3/4");
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 4);
  EXPECT_EQ(s.toString(), "3/4");
  EXPECT_EQ(parseShard("0/1").count, 1);
}

TEST(Shard, RejectsSpecsOutsideTheArray) {
  for (const char* spec :
       {"5/4", "4/4", "0/0", "-1/3", "1/-2", "1", "a/b", "1/2/3", "", "/4", "1/"}) {
    try {
      parseShard(spec);
      ADD_FAILURE() << spec << " was accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_THAT(e.what(), HasSubstr(std::string("--shard ") + spec + ":"));
      EXPECT_THAT(e.what(), HasSubstr("0 <= I < N"));
    }
  }
}

TEST(Shard, EveryObjectFallsInExactlyOneShardWhateverTheOrder) {
  std::vector<MeshFile> files;
  for (int i = 0; i < 400; ++i)
    files.push_back({"m" + std::to_string(i) + ".obj", "obj" + std::to_string(i)});
  std::vector<MeshFile> reversed(files.rbegin(), files.rend());
  std::map<std::string, int> owner;
  for (int i = 0; i < 4; ++i) {
    const auto part = filesInShard(files, {i, 4});
    // Balanced within a loose bound (400 ids, expected 100 each).
    EXPECT_GT(part.size(), 70u);
    EXPECT_LT(part.size(), 130u);
    for (const auto& f : part) EXPECT_TRUE(owner.emplace(f.id, i).second) << f.id << " twice";
    // The same split from a listing in another order: by id, not by position.
    auto other = filesInShard(reversed, {i, 4});
    std::reverse(other.begin(), other.end());
    ASSERT_EQ(other.size(), part.size());
    for (std::size_t k = 0; k < part.size(); ++k) EXPECT_EQ(other[k].id, part[k].id);
  }
  EXPECT_EQ(owner.size(), files.size());
  // Known values pin the hash (first 8 bytes of sha256(id), big-endian, mod N): changing it would
  // reshuffle the objects of arrays already running.
  EXPECT_EQ(owner.at("obj0"), 3);
  EXPECT_EQ(owner.at("obj1"), 2);
  EXPECT_TRUE(parseShard("4/7").contains("obj0"));
  EXPECT_TRUE(Shard{}.contains("anything"));
}

}  // namespace
}  // namespace sagrid
