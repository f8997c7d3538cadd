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
  r.extentUnits = meters * 100;  // a file in centimetres
  r.metersPerUnit = 0.01;
  return r;
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
  EXPECT_NEAR(*memory.expectedMeters({0.98f, 0.32f}, "none"), 1.8, 1e-9);
  EXPECT_NEAR(*memory.expectedMeters({0.42f, 0.88f}, "none"), 0.5, 1e-9);
  // The stove entry is nearest in shape to a squat box, but it is not of the category asked.
  EXPECT_LT(*memory.expectedMeters({0.9f, 0.9f}, "none"), 0.6);  // a microwave's
  EXPECT_FALSE(memory.expectedMeters({0.9f, 0.9f}, "sink"));
  EXPECT_FALSE(memory.expectedMeters({0.9f}, "none"));  // a descriptor of another size
}

TEST(SizeMemory, LeavingASourceOutRecallsOnlyTheOthers) {
  const SizeMemory memory = appliances();
  EXPECT_NEAR(*memory.expectedMeters({1.0f, 0.3f}, "none", "kit-a"), 1.7, 1e-9);
  EXPECT_FALSE(memory.expectedMeters({0.9f, 0.9f}, "stove", "kit-a"));
}

TEST(SizeMemory, AMedianOfSeveralNeighboursInLog) {
  const SizeMemory memory({remembered("a", "s", "none", {0.0f}, 1.0),
                           remembered("b", "s", "none", {0.1f}, 4.0),
                           remembered("c", "s", "none", {5.0f}, 100.0)},
                          "hash", 4.0, /*neighbours=*/2);
  EXPECT_NEAR(*memory.expectedMeters({0.0f}, "none"), 2.0, 1e-9);  // geometric mean of 1 and 4
}

TEST(SizeMemory, RefinesTheNamedGuessOfAGameFileOnly) {
  const SizeMemory memory = appliances(5.0);
  // A fridge 448 units tall: millimetres make it 0.45 m, within 5x of 1.8 m, and stay.
  const UnitGuess mm = memory.refine(guessMetersPerUnit(448.0, "none"), 448.0, {1.0f, 0.3f}, "none");
  EXPECT_EQ(mm.unit, "mm");
  // With a tighter factor it is scaled to the fridges' size.
  const UnitGuess scaled =
      memory.refine(guessMetersPerUnit(448.0, "none"), 448.0, {1.0f, 0.3f}, "none", "", 2.0);
  EXPECT_NEAR(scaled.metersPerUnit * 448.0, 1.8, 1e-9);
  // A microwave 2.73 units wide (2.73 m in metres) is scaled to 0.5 m.
  const UnitGuess microwave = memory.refine(guessMetersPerUnit(2.73, "none"), 2.73, {0.4f, 0.9f}, "none");
  EXPECT_NEAR(microwave.metersPerUnit * 2.73, 0.5, 1e-9);
}

TEST(SizeMemory, WrittenAndReadBack) {
  const auto dir = test::freshTempDir();
  writeSizeMemory(appliances(3.0), dir);
  const auto read = readSizeMemory(dir);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->entries().size(), 5u);
  EXPECT_EQ(read->featureConfigHash(), "hash");
  EXPECT_DOUBLE_EQ(read->farFactor(), 3.0);
  EXPECT_NEAR(*read->expectedMeters({0.42f, 0.88f}, "none"), 0.5, 1e-9);
  EXPECT_FALSE(readSizeMemory(dir / "elsewhere"));
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
