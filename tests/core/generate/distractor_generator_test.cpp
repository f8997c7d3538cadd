// Distractors: category "none", no affordance points, every kind reached, deterministic, and the
// bench split's stoves and sinks do not depend on them.
#include <set>

#include <gtest/gtest.h>

#include "core/generate/dataset_generator.h"
#include "core/generate/distractor_generator.h"

namespace sagrid::gen {
namespace {

TEST(DistractorGenerator, NoneCategoryNoPointsEveryKind) {
  std::set<std::string> kinds;
  for (int i = 0; i < 40; ++i) {
    const FinishedObject o = makeObject(kDistractorCategory, 3001, i, MeshFormat::Mixed);
    EXPECT_EQ(o.labels.object.category, "none");
    EXPECT_TRUE(o.labels.affordances.empty()) << o.id;
    EXPECT_GT(o.mesh.triangleCount(), 12u) << o.id;
    kinds.insert(o.labels.object.extra.at("generator").at("kind").get<std::string>());
  }
  EXPECT_EQ(kinds.size(), distractorKinds().size());
}

TEST(DistractorGenerator, SameSeedSameObjectAndOwnPreset) {
  const FinishedObject a = makeObject(kDistractorCategory, 7, 3, MeshFormat::Obj);
  const FinishedObject b = makeObject(kDistractorCategory, 7, 3, MeshFormat::Obj);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  ASSERT_EQ(distractorPreset().size(), 2u);
  // The distractor preset uses seeds of its own, never the bench split's.
  std::set<std::uint64_t> benchSeeds;
  for (const auto& s : benchPreset())
    for (const auto& r : s.requests) benchSeeds.insert(r.seed);
  for (const auto& s : distractorPreset())
    for (const auto& r : s.requests) {
      EXPECT_EQ(r.category, "none");
      EXPECT_EQ(benchSeeds.count(r.seed), 0u);
    }
}

}  // namespace
}  // namespace sagrid::gen
