#include "core/annotate/size_memory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

RememberedSize remembered(const std::string& id, const std::string& source, const std::string& category,
                          std::vector<float> descriptor, double meters) {
  RememberedSize r;
  r.id = id;
  r.source = source;
  r.category = category;
  r.descriptor = std::move(descriptor);
  r.units.largestExtent = meters * 100;  // a file in centimetres
  r.metersPerUnit = 0.01;
  return r;
}

// An object known by its largest extent alone.
SizeMeasures extent(double units) {
  SizeMeasures sizes;
  sizes.largestExtent = units;
  return sizes;
}

// The expected largest extent in metres (0 when the memory expects nothing).
double expectedMeters(const SizeMemory& memory, const std::vector<float>& descriptor,
                      const std::string& category, const std::string& leaveOut = {}) {
  const auto e = memory.expectedSize(descriptor, category, extent(1.0), leaveOut);
  return e ? e->meters : 0.0;
}

// Two shapes: tall boxes (fridges, 1.8 m) and squat ones (microwaves, 0.5 m), from two sources.
SizeMemory appliances(double farFactor = 4.0) {
  return SizeMemory({remembered("fridge-a", "kit-a", "none", {1.0f, 0.3f}, 1.8),
                     remembered("fridge-b", "kit-b", "none", {0.95f, 0.35f}, 1.7),
                     remembered("microwave-a", "kit-a", "none", {0.4f, 0.9f}, 0.5),
                     remembered("microwave-b", "kit-b", "none", {0.45f, 0.85f}, 0.45),
                     remembered("range-a", "kit-a", "stove", {0.9f, 0.9f}, 0.9)},
                    "hash", farFactor, /*neighbours=*/1);
}

TEST(SizeMemory, ExpectsTheSizeOfTheNearestObjectsOfTheCategory) {
  const SizeMemory memory = appliances();
  EXPECT_NEAR(expectedMeters(memory, {0.98f, 0.32f}, "none"), 1.8, 1e-9);
  EXPECT_NEAR(expectedMeters(memory, {0.42f, 0.88f}, "none"), 0.5, 1e-9);
  // The stove entry is nearest in shape to a squat box, but it is not of the category asked.
  EXPECT_LT(expectedMeters(memory, {0.9f, 0.9f}, "none"), 0.6);  // a microwave's
  EXPECT_FALSE(memory.expectedSize({0.9f, 0.9f}, "sink", extent(1.0)));
  EXPECT_FALSE(memory.expectedSize({0.9f}, "none", extent(1.0)));  // a descriptor of another size
}

TEST(SizeMemory, LeavingASourceOutRecallsOnlyTheOthers) {
  const SizeMemory memory = appliances();
  EXPECT_NEAR(expectedMeters(memory, {1.0f, 0.3f}, "none", "kit-a"), 1.7, 1e-9);
  EXPECT_FALSE(memory.expectedSize({0.9f, 0.9f}, "stove", extent(1.0), "kit-a"));
}

TEST(SizeMemory, AMedianOfSeveralNeighboursInLog) {
  const SizeMemory memory({remembered("a", "s", "none", {0.0f}, 1.0),
                           remembered("b", "s", "none", {0.1f}, 4.0),
                           remembered("c", "s", "none", {5.0f}, 100.0)},
                          "hash", 4.0, /*neighbours=*/2);
  EXPECT_NEAR(expectedMeters(memory, {0.0f}, "none"), 2.0, 1e-9);  // geometric mean of 1 and 4
}

TEST(SizeMemory, RefinesTheNamedGuessOfAGameFileOnly) {
  const SizeMemory memory = appliances(5.0);
  // A fridge 448 units tall: millimetres make it 0.45 m, within 5x of 1.8 m, and stay.
  const UnitGuess mm = memory.refine(guessMetersPerUnit(448.0, "none"), extent(448.0), {1.0f, 0.3f}, "none");
  EXPECT_EQ(mm.unit, "mm");
  // With a tighter factor it is scaled to the fridges' size.
  const UnitGuess scaled =
      memory.refine(guessMetersPerUnit(448.0, "none"), extent(448.0), {1.0f, 0.3f}, "none", "", 2.0);
  EXPECT_NEAR(scaled.metersPerUnit * 448.0, 1.8, 1e-9);
  // A microwave 2.73 units wide (2.73 m in metres) is scaled to 0.5 m.
  const UnitGuess microwave = memory.refine(guessMetersPerUnit(2.73, "none"), extent(2.73), {0.4f, 0.9f}, "none");
  EXPECT_NEAR(microwave.metersPerUnit * 2.73, 0.5, 1e-9);
}

// Ranges of one kind: their largest extents differ (backguards of several heights), their cooktops
// are all near 0.9 m. With both measures the memory recalls the one they agree on.
TEST(SizeMemory, RecallsTheMeasureTheNearestObjectsAgreeOnMost) {
  std::vector<RememberedSize> ranges;
  const double extents[] = {0.9, 1.2, 1.5}, surfaces[] = {0.88, 0.9, 0.92};
  for (int i = 0; i < 3; ++i) {
    RememberedSize r = remembered("range-" + std::to_string(i), "kit", "stove", {float(i) * 0.01f}, 1.0);
    r.units.largestExtent = extents[i] / r.metersPerUnit;
    r.units.workSurface = surfaces[i] / r.metersPerUnit;
    ranges.push_back(r);
  }
  const SizeMemory both(ranges, "hash", 1.5, 3, {SizeMeasure::LargestExtent, SizeMeasure::WorkSurface});
  // A game range 2 units wide with its cooktop at 1.76 units: metres make the cooktop 2x too high.
  SizeMeasures game;
  game.largestExtent = 2.0;
  game.workSurface = 1.76;
  const auto expected = both.expectedSize({0.0f}, "stove", game);
  ASSERT_TRUE(expected);
  EXPECT_EQ(expected->measure, SizeMeasure::WorkSurface);
  EXPECT_NEAR(expected->meters, 0.9, 1e-9);
  const UnitGuess guess = both.refine(guessMetersPerUnit(2.0, "stove"), game, {0.0f}, "stove");
  EXPECT_NEAR(guess.metersPerUnit, 0.9 / 1.76, 1e-9);
  EXPECT_NE(guess.reason.find("work surface height"), std::string::npos) << guess.reason;
  // An object without a work surface is judged by its largest extent (1.2 m expected: 2 m stays
  // within 1.7x).
  const auto byExtent = both.expectedSize({0.0f}, "stove", extent(2.0));
  ASSERT_TRUE(byExtent);
  EXPECT_EQ(byExtent->measure, SizeMeasure::LargestExtent);
  EXPECT_NEAR(byExtent->meters, 1.2, 1e-9);
  // The largest extent alone (the memory's default) does not look at work surfaces.
  const SizeMemory extentOnly(ranges, "hash", 1.5, 3);
  EXPECT_EQ(extentOnly.expectedSize({0.0f}, "stove", game)->measure, SizeMeasure::LargestExtent);
}

TEST(SizeMemory, WrittenAndReadBack) {
  const auto dir = test::freshTempDir();
  writeSizeMemory(appliances(3.0), dir);
  const auto read = readSizeMemory(dir);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->entries().size(), 5u);
  EXPECT_EQ(read->featureConfigHash(), "hash");
  EXPECT_DOUBLE_EQ(read->farFactor(), 3.0);
  EXPECT_NEAR(expectedMeters(*read, {0.42f, 0.88f}, "none"), 0.5, 1e-9);
  EXPECT_EQ(read->measures(), std::vector<SizeMeasure>{SizeMeasure::LargestExtent});
  EXPECT_FALSE(readSizeMemory(dir / "elsewhere"));
  // The measures and the sizes beside the largest extent are kept; a file written before them
  // (no "measures", no heights) reads as the largest extent alone.
  std::vector<RememberedSize> entries = appliances().entries();
  entries[0].units.height = 170.0;
  writeSizeMemory(SizeMemory(entries, "hash", 3.0, 1, {SizeMeasure::Height, SizeMeasure::LargestExtent}), dir);
  const auto both = readSizeMemory(dir);
  ASSERT_TRUE(both);
  EXPECT_EQ(both->measures(), (std::vector<SizeMeasure>{SizeMeasure::Height, SizeMeasure::LargestExtent}));
  EXPECT_DOUBLE_EQ(both->entries()[0].units.height, 170.0);
  EXPECT_TRUE(std::isnan(both->entries()[1].units.height));
  nlohmann::json older = appliances().toJson();
  older.erase("measures");
  for (auto& e : older["entries"]) {
    e.erase("height_units");
    e.erase("work_surface_units");
  }
  const SizeMemory read1 = SizeMemory::fromJson(older, dir / kSizeMemoryFile);
  EXPECT_EQ(read1.measures(), std::vector<SizeMeasure>{SizeMeasure::LargestExtent});
  EXPECT_TRUE(std::isnan(read1.entries()[0].units.workSurface));
}

TEST(SizeMemory, MalformedFilesAreClearErrorsNamingTheFile) {
  const auto file = test::freshTempDir() / kSizeMemoryFile;
  auto expectError = [&](nlohmann::json j, const std::string& says) {
    try {
      SizeMemory::fromJson(j, file);
      ADD_FAILURE() << "no error for " << j.dump();
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  nlohmann::json good = appliances().toJson();
  expectError({{"schema", "something else"}}, "schema");
  auto j = good;
  j.erase("far_factor");
  expectError(j, "malformed");
  j = good;
  j["far_factor"] = 0.5;
  expectError(j, "far_factor");
  j = good;
  j["entries"][1]["extent_units"] = -1.0;
  expectError(j, "positive");
  j = good;
  j["entries"][3].erase("meters_per_unit");
  expectError(j, "malformed");
  j = good;
  j["entries"][2]["descriptor"] = {1.0};
  expectError(j, "descriptor has 1 values");
  j = good;
  j["entries"][0]["height_units"] = 0.0;
  expectError(j, "height_units");
  j = good;
  j["measures"] = {"largest_extent", "width"};
  expectError(j, "unknown size measure 'width'");
  // A file that is not JSON, read from a models folder.
  std::ofstream(file) << "{\"schema\": ";
  try {
    readSizeMemory(file.parent_path());
    ADD_FAILURE() << "no error for a truncated file";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sagrid
